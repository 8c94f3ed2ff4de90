// Error of an image against the reference, over the RGB channels of RGBA8.
#pragma once

#include <vector>

#include "rop/framebuffer.h"

namespace zb {

struct ImageError {
  double rmse = 0;            // root mean square error over RGB, in 8-bit units
  double psnr = 0;            // dB; infinity when identical
  int max_abs = 0;            // largest channel difference
  double share_over_2 = 0;    // share of pixels with a channel off by more than 2
  double share_over_16 = 0;   // share of pixels with a channel off by more than 16
  double delta_e_mean = 0;    // CIEDE2000 (color_difference.h) per pixel, mean over the frame
  double delta_e_max = 0;     // and its largest value
  int worst_x = -1, worst_y = -1;  // the pixel of that value (the first, row-major); -1: exact
};

// Frames of different sizes compare as an all-zero ImageError. With `delta_e`, each pixel's
// CIEDE2000 too (row-major; error_map.h draws it).
ImageError compare_images(const Framebuffer& image, const Framebuffer& reference,
                          std::vector<float>* delta_e = nullptr);


}  // namespace zb
