// Line rasterizer (docs/raster.md, "Lines").
#include "lines.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

constexpr int64_t kHalf = kSubpixelOne / 2;
using edge::floor_div;

// Step 1: the major axis (x when |dx| >= |dy|) and the ends ordered by major coordinate, then
// minor, so that the pixels do not depend on the direction.
LineAxes axes_of(const ScreenVertex& a, const ScreenVertex& b) {
  LineAxes l;
  l.x_major = std::llabs(int64_t{b.x} - a.x) >= std::llabs(int64_t{b.y} - a.y);
  auto major = [&](const ScreenVertex& v) { return int64_t{l.x_major ? v.x : v.y}; };
  auto minor = [&](const ScreenVertex& v) { return int64_t{l.x_major ? v.y : v.x}; };
  const bool swap = major(b) < major(a) || (major(b) == major(a) && minor(b) < minor(a));
  l.start = swap ? b : a;
  l.end = swap ? a : b;
  l.M0 = major(l.start);
  l.m0 = minor(l.start);
  l.M1 = major(l.end);
  l.m1 = minor(l.end);
  return l;
}

}  // namespace

void walk_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp, RowRange rows,
               const std::function<void(const LineAxes&, const LinePoint&)>& visit) {
  if (!edge::in_range(a) || !edge::in_range(b)) return;
  const LineAxes l = axes_of(a, b);
  const int64_t dM = l.dM(), dm = l.dm();
  const uint64_t z0 = l.start.z, z1 = l.end.z;
  const int64_t major_size = l.x_major ? vp.width : vp.height;
  // Rows are the minor axis of an x-major line and the major one otherwise.
  const int64_t row_lo = std::max(0, rows.begin);
  const int64_t row_hi = std::min<int64_t>(vp.height, rows.end);  // exclusive
  const int64_t major_lo = l.x_major ? 0 : row_lo;
  const int64_t major_hi = l.x_major ? major_size : row_hi;
  const int64_t minor_lo = l.x_major ? row_lo : 0;
  const int64_t minor_hi = l.x_major ? row_hi : vp.width;

  // Cells along the major axis from the one holding the start to the one holding the end.
  const int64_t i_lo = std::max<int64_t>(major_lo, floor_div(l.M0, kSubpixelOne));
  const int64_t i_hi = std::min<int64_t>(major_hi - 1, floor_div(l.M1, kSubpixelOne));
  LinePoint p;
  for (int64_t i = i_lo; i <= i_hi; ++i) {
    // The evaluation point: the cell's centre, clamped to the segment.
    const int64_t c = std::clamp<int64_t>(i * kSubpixelOne + kHalf, l.M0, l.M1);
    p.s = c - l.M0;  // 0 .. dM
    int64_t j;
    if (dM == 0) {  // a point
      j = floor_div(l.m0, kSubpixelOne);
      p.z = static_cast<uint32_t>(std::min(z0, z1));
    } else {
      j = floor_div(l.m0 * dM + dm * p.s, kSubpixelOne * dM);
      p.z = static_cast<uint32_t>((z0 * uint64_t(dM - p.s) + z1 * uint64_t(p.s) + uint64_t(dM / 2)) /
                                  uint64_t(dM));
    }
    if (j < minor_lo || j >= minor_hi) continue;
    p.x = l.x_major ? i : j;
    p.y = l.x_major ? j : i;
    visit(l, p);
  }
}

void rasterize_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp,
                    Rgba8 color, uint32_t prim, std::vector<Fragment>& out, RowRange rows) {
  Fragment f;
  f.color = color;
  f.front = true;
  f.facing = true;
  f.prim = prim;
  walk_line(a, b, vp, rows, [&](const LineAxes&, const LinePoint& p) {
    f.x = static_cast<uint16_t>(p.x);
    f.y = static_cast<uint16_t>(p.y);
    f.z = p.z;
    out.push_back(f);
  });
}

}  // namespace zb
