// Rasterizer: integer edge functions at pixel centres, top-left fill rule, depth interpolated
// exactly in integers and rounded half up.
#pragma once

#include <climits>
#include <vector>

#include "rop/fragment.h"
#include "geometry/geometry.h"

namespace zb {

// A scissor on rows: only rows begin <= y < end are rasterized. The fragments of the rows
// kept are exactly those of the whole primitive, in the same order (the banded renderer,
// frame_render.h, relies on it).
struct RowRange {
  int begin = 0;
  int end = INT_MAX;
};

// Appends the fragments of `tri` inside the viewport (and `rows`) to `out`, rows top to bottom,
// each row left to right. When `z_exact` is given, appends each fragment's unrounded window
// depth too.
void rasterize(const ScreenTriangle& tri, const Viewport& vp, std::vector<Fragment>& out,
               std::vector<double>* z_exact = nullptr, RowRange rows = {});

}  // namespace zb
