// PNG output. Writes to a temporary file beside the target and renames it, so a failed write
// leaves no partial file.
#pragma once

#include <string>

#include "rop/framebuffer.h"

namespace zb {

// Writes the colour buffer as an RGB PNG. Returns an empty string, or what went wrong.
std::string write_png(const std::string& path, const Framebuffer& fb);

// Writes `text` to `path` the same way. Returns an empty string, or what went wrong.
std::string write_file_atomic(const std::string& path, const std::string& text);

}  // namespace zb
