// The exact reference: every fragment of the scene sorted per pixel by unrounded depth and
// composited back to front in floating point. Ground truth, not a hardware method.
#pragma once

#include <utility>
#include <vector>

#include "rop/framebuffer.h"
#include "pipeline/render.h"
#include "scene/scene.h"

namespace zb {

Framebuffer render_reference(const RasterizedScene& rs);

// The exact reference at each pixel of `at` (x, y): the scene's fragments there, nearest first,
// up to and including the nearest opaque one (what it composites over the background, or over
// that fragment), how many lie behind that one, and the pixel's colour as render_reference
// gives it.
struct ReferenceLayer {
  uint32_t prim = 0;  // the scene's triangle
  double z_exact = 0;
  Rgba8 color;
};
struct ReferencePixel {
  std::vector<ReferenceLayer> layers;
  size_t behind = 0;
  Rgba8 color;
};
std::vector<ReferencePixel> reference_pixels(const RasterizedScene& rs,
                                             const std::vector<std::pair<int, int>>& at);

// The reference for anti-aliased methods: the exact reference at `factor` times the width and
// height, box-filtered down to `vp`. Each pixel averages the factor x factor sub-pixel colours
// (a regular grid of sample points), composited in double and rounded once; its depth is the
// nearest of its sub-pixels'. Coverage stays 0. factor 1 equals render_reference. Throws
// std::invalid_argument when factor < 1 or the enlarged frame exceeds kMaxFrameSize. Drawn in
// bands of rows on `threads` workers (0: every core); the same frame for any number.
Framebuffer render_reference_supersampled(const Scene& scene, const Viewport& vp, int factor,
                                          int threads = 1);

}  // namespace zb
