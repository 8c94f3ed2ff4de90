// Line rasterizer for tessellation edges (docs/raster.md, "Lines"): one fragment per pixel
// cell the line crosses along its major axis, the minor coordinate and the depth evaluated at
// the cell's centre clamped to the segment, exactly in integers.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "rop/fragment.h"
#include "geometry/geometry.h"
#include "raster.h"

namespace zb {

// A segment as the line rule sees it (step 1): its major axis and its ends ordered by major
// coordinate, then minor; M and m are the ends' major and minor coordinates (1/256 pixel).
struct LineAxes {
  bool x_major = true;
  ScreenVertex start, end;  // the ends in that order
  int64_t M0 = 0, m0 = 0, M1 = 0, m1 = 0;
  int64_t dM() const { return M1 - M0; }  // >= 0; 0 for a point
  int64_t dm() const { return m1 - m0; }  // |dm| <= dM
};

// One fragment of the rule: its pixel and depth, and the point of the segment it was
// evaluated at (step 3): `s` (0..dM) along the major axis from the start, so the point is
// (M0 + s, m0 + dm s / dM) in (major, minor); a point segment (dM = 0) has s = 0.
struct LinePoint {
  int64_t x = 0, y = 0;
  uint32_t z = 0;
  int64_t s = 0;
};

// Calls `visit` for each fragment of the segment (a, b) inside the viewport and `rows`, in
// ascending major coordinate: the fragments rasterize_line makes, with their points.
void walk_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp, RowRange rows,
               const std::function<void(const LineAxes&, const LinePoint&)>& visit);

// Appends the fragments of the segment (a, b) inside the viewport to `out`, in ascending major
// coordinate; the result does not depend on the order of a and b. Every fragment carries
// `color`, front = facing = true and `prim`. `rows` scissors rows as for rasterize (raster.h):
// the rows kept give the same fragments.
void rasterize_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp,
                    Rgba8 color, uint32_t prim, std::vector<Fragment>& out, RowRange rows = {});

}  // namespace zb
