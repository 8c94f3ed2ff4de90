// Rasterizer (docs/raster.md): integer edge functions at pixel centres, top-left fill rule for
// the y-down window, bounding box scissored to the viewport, depth interpolated exactly.
#include "raster.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

__extension__ typedef unsigned __int128 u128;

using edge::ceil_div;
using edge::floor_div;

// Coordinates within edge::kCoordLimit keep w * z below 2^83.
constexpr int64_t kHalf = kSubpixelOne / 2;

// E(p) = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), stepped over pixel centres.
struct Edge {
  int64_t at_origin = 0;  // E at the centre of the bounding box's top-left pixel
  int64_t step_x = 0;     // change per pixel to the right
  int64_t step_y = 0;     // change per pixel down
  int64_t bias = 0;       // 0 for a top or left edge, 1 otherwise: covered iff E >= bias
};

Edge make_edge(const ScreenVertex& a, const ScreenVertex& b, int64_t x0, int64_t y0) {
  const int64_t ex = int64_t{b.x} - a.x;
  const int64_t ey = int64_t{b.y} - a.y;
  Edge e;
  e.at_origin = ex * (y0 - a.y) - ey * (x0 - a.x);
  e.step_x = -ey * kSubpixelOne;
  e.step_y = ex * kSubpixelOne;
  e.bias = edge::top_left(ex, ey) ? 0 : 1;
  return e;
}

}  // namespace

void rasterize(const ScreenTriangle& tri, const Viewport& vp, std::vector<Fragment>& out,
               std::vector<double>* z_exact, RowRange rows) {
  if (vp.width < 1 || vp.width > kMaxFrameSize || vp.height < 1 || vp.height > kMaxFrameSize)
    return;
  edge::OrientedTriangle t;  // depth weights and facing flags follow their vertices
  if (!edge::orient(tri, t)) return;
  const ScreenVertex(&v)[3] = t.v;
  const bool(&facing)[3] = t.facing;
  const int64_t area = t.area;

  // Bounding box of the pixel centres (px * 256 + 128) inside the vertices' box, scissored to
  // the viewport and the row range.
  const int64_t min_x = std::min({v[0].x, v[1].x, v[2].x});
  const int64_t max_x = std::max({v[0].x, v[1].x, v[2].x});
  const int64_t min_y = std::min({v[0].y, v[1].y, v[2].y});
  const int64_t max_y = std::max({v[0].y, v[1].y, v[2].y});
  const int64_t px_lo = std::max<int64_t>(0, ceil_div(min_x - kHalf, kSubpixelOne));
  const int64_t px_hi = std::min<int64_t>(vp.width - 1, floor_div(max_x - kHalf, kSubpixelOne));
  const int64_t py_lo = std::max<int64_t>({0, rows.begin, ceil_div(min_y - kHalf, kSubpixelOne)});
  const int64_t py_hi = std::min<int64_t>({vp.height - 1, int64_t{rows.end} - 1,
                                           floor_div(max_y - kHalf, kSubpixelOne)});
  if (px_lo > px_hi || py_lo > py_hi) return;

  const int64_t cx = px_lo * kSubpixelOne + kHalf;
  const int64_t cy = py_lo * kSubpixelOne + kHalf;
  // Edge k is opposite vertex k; its value is vertex k's barycentric weight (times area).
  Edge edge[3] = {make_edge(v[1], v[2], cx, cy), make_edge(v[2], v[0], cx, cy),
                  make_edge(v[0], v[1], cx, cy)};

  const uint64_t z[3] = {v[0].z, v[1].z, v[2].z};
  const uint64_t z_top = std::max({z[0], z[1], z[2]});
  const uint64_t half_area = static_cast<uint64_t>(area) / 2;
  // Sum of w_k * z_k <= area * max z: fits 64 bits for all usual triangles and depth widths.
  const bool narrow = u128(static_cast<uint64_t>(area)) * z_top + half_area <= UINT64_MAX;
  const double area_d = double(area);

  Fragment frag;
  frag.color = tri.color;
  frag.front = tri.front;
  frag.prim = tri.prim;
  // Every sample of a pixel whose centre is covered counts as covered: the full count (a
  // coverage pass uses rasterize_coverage instead, coverage.h).
  frag.coverage = static_cast<uint8_t>(vp.coverage_samples);
  // Facing (raster.md, "Facing"): constant when the vertices agree; otherwise a fragment faces
  // the viewer iff the barycentric weights of the flagged vertices sum to at least half.
  const bool facing_mixed = !(facing[0] == facing[1] && facing[1] == facing[2]);
  frag.facing = facing[0];

  int64_t row[3] = {edge[0].at_origin, edge[1].at_origin, edge[2].at_origin};
  const int64_t span_max = px_hi - px_lo;
  for (int64_t py = py_lo; py <= py_hi; ++py) {
    // The covered pixels of a row form one span [lo, hi] (offsets from px_lo): solve
    // row + k * step_x >= bias for every edge.
    int64_t lo = 0, hi = span_max;
    for (int k = 0; k < 3; ++k) {
      const Edge& e = edge[k];
      if (e.step_x > 0)
        lo = std::max(lo, ceil_div(e.bias - row[k], e.step_x));
      else if (e.step_x < 0)
        hi = std::min(hi, floor_div(row[k] - e.bias, -e.step_x));
      else if (row[k] < e.bias)
        hi = -1;
    }
    if (lo <= hi) {
      int64_t w[3];
      for (int k = 0; k < 3; ++k) w[k] = row[k] + lo * edge[k].step_x;
      frag.y = static_cast<uint16_t>(py);
      for (int64_t k = lo; k <= hi; ++k) {
        const uint64_t w0 = static_cast<uint64_t>(w[0]), w1 = static_cast<uint64_t>(w[1]),
                       w2 = static_cast<uint64_t>(w[2]);
        if (narrow) {
          frag.z = static_cast<uint32_t>((w0 * z[0] + w1 * z[1] + w2 * z[2] + half_area) /
                                         static_cast<uint64_t>(area));
        } else {
          const u128 num = u128(w0) * z[0] + u128(w1) * z[1] + u128(w2) * z[2] + half_area;
          frag.z = static_cast<uint32_t>(num / static_cast<uint64_t>(area));
        }
        frag.x = static_cast<uint16_t>(px_lo + k);
        if (facing_mixed) {
          const int64_t toward = (facing[0] ? w[0] : 0) + (facing[1] ? w[1] : 0) +
                                 (facing[2] ? w[2] : 0);
          frag.facing = 2 * toward >= area;
        }
        out.push_back(frag);
        if (z_exact) {
          z_exact->push_back((double(w[0]) * v[0].z_exact + double(w[1]) * v[1].z_exact +
                              double(w[2]) * v[2].z_exact) /
                             area_d);
        }
        w[0] += edge[0].step_x;
        w[1] += edge[1].step_x;
        w[2] += edge[2].step_x;
      }
    }
    for (int k = 0; k < 3; ++k) row[k] += edge[k].step_y;
  }
}

}  // namespace zb
