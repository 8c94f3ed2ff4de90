// A file written whole or not at all: to a temporary file beside the target, then renamed.
// Apart from the PNG writer so that what writes text does not link zlib (the kit's static
// libraries).
#pragma once

#include <string>

namespace zb {

// Writes `text` to `path`. Returns an empty string, or what went wrong.
std::string write_file_atomic(const std::string& path, const std::string& text);

}  // namespace zb
