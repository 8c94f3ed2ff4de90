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

}  // namespace

void rasterize_line(const ScreenVertex& a, const ScreenVertex& b, const Viewport& vp,
                    Rgba8 color, uint32_t prim, std::vector<Fragment>& out, RowRange rows) {
  if (!edge::in_range(a) || !edge::in_range(b)) return;
  const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;
  // Major axis: x when |dx| >= |dy|. (M, m) are the major and minor coordinates.
  const bool x_major = std::llabs(dx) >= std::llabs(dy);
  struct End {
    int64_t M, m;
    uint64_t z;
  };
  End e0{x_major ? a.x : a.y, x_major ? a.y : a.x, a.z};
  End e1{x_major ? b.x : b.y, x_major ? b.y : b.x, b.z};
  // Start at the smaller major coordinate (then the smaller minor one): direction-free.
  if (e1.M < e0.M || (e1.M == e0.M && e1.m < e0.m)) std::swap(e0, e1);
  const int64_t dM = e1.M - e0.M;  // >= 0
  const int64_t dm = e1.m - e0.m;  // |dm| <= dM
  const int64_t major_size = x_major ? vp.width : vp.height;
  // Rows are the minor axis of an x-major line and the major one otherwise.
  const int64_t row_lo = std::max(0, rows.begin);
  const int64_t row_hi = std::min<int64_t>(vp.height, rows.end);  // exclusive
  const int64_t major_lo = x_major ? 0 : row_lo;
  const int64_t major_hi = x_major ? major_size : row_hi;
  const int64_t minor_lo = x_major ? row_lo : 0;
  const int64_t minor_hi = x_major ? row_hi : vp.width;

  Fragment f;
  f.color = color;
  f.front = true;
  f.facing = true;
  f.prim = prim;
  // Cells along the major axis from the one holding the start to the one holding the end.
  const int64_t i_lo = std::max<int64_t>(major_lo, floor_div(e0.M, kSubpixelOne));
  const int64_t i_hi = std::min<int64_t>(major_hi - 1, floor_div(e1.M, kSubpixelOne));
  for (int64_t i = i_lo; i <= i_hi; ++i) {
    // The evaluation point: the cell's centre, clamped to the segment.
    const int64_t c = std::clamp<int64_t>(i * kSubpixelOne + kHalf, e0.M, e1.M);
    const int64_t s = c - e0.M;  // 0 .. dM
    int64_t j;
    uint64_t z;
    if (dM == 0) {  // a point
      j = floor_div(e0.m, kSubpixelOne);
      z = std::min(e0.z, e1.z);
    } else {
      j = floor_div(e0.m * dM + dm * s, kSubpixelOne * dM);
      z = (e0.z * uint64_t(dM - s) + e1.z * uint64_t(s) + uint64_t(dM / 2)) / uint64_t(dM);
    }
    if (j < minor_lo || j >= minor_hi) continue;
    f.x = static_cast<uint16_t>(x_major ? i : j);
    f.y = static_cast<uint16_t>(x_major ? j : i);
    f.z = static_cast<uint32_t>(z);
    out.push_back(f);
  }
}

}  // namespace zb
