// Rasterizer: integer edge functions at pixel centres, top-left fill rule, depth interpolated
// exactly in integers and rounded half up.
#pragma once

#include <vector>

#include "fragment.h"
#include "geometry.h"

namespace zb {

// Appends the fragments of `tri` inside the viewport to `out`, rows top to bottom, each row
// left to right. When `z_exact` is given, appends each fragment's unrounded window depth too.
void rasterize(const ScreenTriangle& tri, const Viewport& vp, std::vector<Fragment>& out,
               std::vector<double>* z_exact = nullptr);

}  // namespace zb
