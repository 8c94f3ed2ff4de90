// A pass plan replayed at single pixels with the unrounded window depths of the fragments
// (RasterizedScene::z_exact, double) in every depth test: what the plan draws there when no
// depth is rounded. Where the golden model and llvmpipe differ, it tells which one the exact
// depth order sides with.
#pragma once

#include <cstddef>
#include <vector>

#include "pipeline/passes.h"
#include "pipeline/render.h"

namespace zb::oracle {

// The colour of each pixel (index y * width + x) in `pixels`, in the same order. Only plans
// without coverage, peel or depth-offset passes (gl_render.h, unsupported_reason).
std::vector<Rgba8> replay_exact_depth(const RasterizedScene& rs, const PassPlan& plan,
                                      const std::vector<size_t>& pixels);

}  // namespace zb::oracle
