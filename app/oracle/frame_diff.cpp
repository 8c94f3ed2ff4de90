#include "frame_diff.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace zb::oracle {
namespace {

int channel_diff(Rgba8 a, Rgba8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b),
                   std::abs(a.a - b.a)});
}

void check_sizes(const Framebuffer& a, const Framebuffer& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("frames of different sizes");
}

}  // namespace

FrameDiff diff_frames(const Framebuffer& a, const Framebuffer& b) {
  check_sizes(a, b);
  FrameDiff d;
  d.pixels = a.color.size();
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const size_t i = a.index(x, y);
      const int c = channel_diff(a.color[i], b.color[i]);
      if (c == 0) {
        ++d.identical;
      } else if (d.first_x < 0) {
        d.first_x = x;
        d.first_y = y;
      }
      d.max_diff = std::max(d.max_diff, c);
      const uint32_t za = a.depth[i], zb = b.depth[i];
      if (za == zb) ++d.depth_identical;
      d.max_depth_diff = std::max(d.max_depth_diff, za > zb ? za - zb : zb - za);
    }
  return d;
}

Framebuffer diff_image(const Framebuffer& a, const Framebuffer& b) {
  check_sizes(a, b);
  Framebuffer out(a.width, a.height, a.depth_bits, Rgba8{255, 255, 255, 255});
  for (size_t i = 0; i < a.color.size(); ++i) {
    const Rgba8 p = a.color[i];
    const int c = channel_diff(p, b.color[i]);
    if (c == 0) {
      const int luma = (54 * p.r + 183 * p.g + 19 * p.b) >> 8;
      const auto grey = static_cast<uint8_t>(192 + luma / 4);
      out.color[i] = Rgba8{grey, grey, grey, 255};
    } else {
      out.color[i] = Rgba8{static_cast<uint8_t>(std::min(255, 160 + 8 * c)), 0, 0, 255};
    }
  }
  return out;
}

}  // namespace zb::oracle
