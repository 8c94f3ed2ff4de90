// Pixel-by-pixel agreement of two frames of one size, and a picture of where they differ.
#pragma once

#include <cstdint>
#include <string>

#include "rop/framebuffer.h"

namespace zb::oracle {

struct FrameDiff {
  uint64_t pixels = 0;
  uint64_t identical = 0;        // RGBA equal in every bit
  int max_diff = 0;              // largest channel difference, RGBA
  int first_x = -1, first_y = -1;  // first differing pixel in row order, or -1
  uint64_t depth_identical = 0;  // depth equal in every bit
  uint32_t max_depth_diff = 0;   // largest depth difference, depth units
  double identical_share() const { return pixels ? double(identical) / double(pixels) : 1.0; }
  double depth_identical_share() const {
    return pixels ? double(depth_identical) / double(pixels) : 1.0;
  }
};

// Throws std::invalid_argument when the sizes differ.
FrameDiff diff_frames(const Framebuffer& a, const Framebuffer& b);

// Where `a` and `b` differ: identical pixels as a faint grey copy of `a`, differing ones in
// red, brighter for a larger difference (a difference of 1 is still plainly red).
Framebuffer diff_image(const Framebuffer& a, const Framebuffer& b);

}  // namespace zb::oracle
