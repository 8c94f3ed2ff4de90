// PNG output. Written as write_file_atomic writes (atomic_file.h), so a failed write leaves no
// partial file.
#pragma once

#include <string>

#include "io/atomic_file.h"
#include "rop/framebuffer.h"

namespace zb {

// Writes the colour buffer as an RGB PNG. Returns an empty string, or what went wrong.
std::string write_png(const std::string& path, const Framebuffer& fb);
// The same from `width` x `height` colours, row by row.
std::string write_png(const std::string& path, int width, int height, const Rgba8* color);

}  // namespace zb
