// Line rasterizer for tessellation edges (docs/raster.md, "Lines"): one fragment per pixel
// cell the line crosses along its major axis, the minor coordinate and the depth evaluated at
// the cell's centre clamped to the segment, exactly in integers.
#pragma once

#include <vector>

#include "rop/fragment.h"
#include "geometry/geometry.h"
#include "raster.h"

namespace zb {

// Appends the fragments of the segment (a, b) inside the viewport to `out`, in ascending major
// coordinate; the result does not depend on the order of a and b. Every fragment carries
// `color`, front = facing = true and `prim`. `rows` scissors rows as for rasterize (raster.h):
// the rows kept give the same fragments.
void rasterize_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp,
                    Rgba8 color, uint32_t prim, std::vector<Fragment>& out, RowRange rows = {});

}  // namespace zb
