// The exact reference: every fragment of the scene sorted per pixel by unrounded depth and
// composited back to front in floating point. Ground truth, not a hardware method.
#pragma once

#include "rop/framebuffer.h"
#include "pipeline/render.h"
#include "scene/scene.h"

namespace zb {

Framebuffer render_reference(const RasterizedScene& rs);

// The reference for anti-aliased methods: the exact reference at `factor` times the width and
// height, box-filtered down to `vp`. Each pixel averages the factor x factor sub-pixel colours
// (a regular grid of sample points), composited in double and rounded once; its depth is the
// nearest of its sub-pixels'. Coverage stays 0. factor 1 equals render_reference. Throws
// std::invalid_argument when factor < 1 or the enlarged frame exceeds kMaxFrameSize.
Framebuffer render_reference_supersampled(const Scene& scene, const Viewport& vp, int factor);

}  // namespace zb
