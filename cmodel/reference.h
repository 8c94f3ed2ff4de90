// The exact reference: every fragment of the scene sorted per pixel by unrounded depth and
// composited back to front in floating point. Ground truth, not a hardware method.
#pragma once

#include "framebuffer.h"
#include "render.h"

namespace zb {

Framebuffer render_reference(const RasterizedScene& rs);

}  // namespace zb
