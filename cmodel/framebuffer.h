// The pixel buffers a frame renders into: colour RGBA8 and depth, row-major, row 0 at the top.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fixed.h"

namespace zb {

struct Framebuffer {
  int width = 0;
  int height = 0;
  int depth_bits = kDefaultDepthBits;
  std::vector<Rgba8> color;
  std::vector<uint32_t> depth;

  Framebuffer() = default;
  Framebuffer(int w, int h, int bits, Rgba8 clear_color)
      : width(w), height(h), depth_bits(bits),
        color(static_cast<size_t>(w) * h, clear_color),
        depth(static_cast<size_t>(w) * h, depth_max(bits)) {}

  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
  Rgba8 color_at(int x, int y) const { return color[index(x, y)]; }
  uint32_t depth_at(int x, int y) const { return depth[index(x, y)]; }
};

}  // namespace zb
