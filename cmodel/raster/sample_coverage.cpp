// Coverage rasterizer (docs/raster.md "Coverage"): the N-rooks sample pattern, each sample
// tested with the rasterizer's edge functions and top-left rule, depth at the pixel centre.
#include "sample_coverage.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;


// Column of sample i (its row is i) per pattern: raster.md "Coverage", table "Sample pattern".
const int kCol1[] = {0};
const int kCol2[] = {1, 0};
const int kCol4[] = {1, 3, 0, 2};
const int kCol8[] = {1, 4, 7, 2, 5, 0, 3, 6};                                  // (3i + 1) mod 8
const int kCol16[] = {2, 7, 12, 1, 6, 11, 0, 5, 10, 15, 4, 9, 14, 3, 8, 13};  // (5i + 2) mod 16

std::vector<SamplePos> make_pattern(const int* col, int n) {
  std::vector<SamplePos> p(static_cast<size_t>(n));
  const int pitch = kSubpixelOne / n;  // 256 / n sub-pixel units per row and column
  for (int i = 0; i < n; ++i) p[size_t(i)] = {col[i] * pitch + pitch / 2, i * pitch + pitch / 2};
  return p;
}

using edge::floor_div;

// The rasterizer's edge a->b (raster.md step 2 and 3): E(p) = (b.x - a.x)(p.y - a.y) -
// (b.y - a.y)(p.x - a.x); covered iff E >= bias, bias 0 on a top or left edge, else 1.
struct Edge {
  int64_t ex = 0, ey = 0;
  int64_t ax = 0, ay = 0;
  int64_t bias = 0;
  int64_t at(int64_t px, int64_t py) const { return ex * (py - ay) - ey * (px - ax); }
};

Edge make_edge(const ScreenVertex& a, const ScreenVertex& b) {
  Edge e;
  e.ex = int64_t{b.x} - a.x;
  e.ey = int64_t{b.y} - a.y;
  e.ax = a.x;
  e.ay = a.y;
  e.bias = edge::top_left(e.ex, e.ey) ? 0 : 1;
  return e;
}

}  // namespace

const std::vector<SamplePos>& sample_pattern(int n) {
  static const std::vector<SamplePos> p1 = make_pattern(kCol1, 1), p2 = make_pattern(kCol2, 2),
                                      p4 = make_pattern(kCol4, 4), p8 = make_pattern(kCol8, 8),
                                      p16 = make_pattern(kCol16, 16);
  switch (n) {
    case 1: return p1;
    case 2: return p2;
    case 4: return p4;
    case 8: return p8;
    case 16: return p16;
    default: break;
  }
  throw std::invalid_argument("coverage: " + std::to_string(n) +
                              " samples; the patterns have 1, 2, 4, 8 or 16");
}

// Pixels with a sample position (256 px + 0..255) inside the vertices' box, scissored to the
// viewport and the row range.
PixelBox coverage_box(const ScreenTriangle& tri, const Viewport& vp, RowRange rows) {
  const ScreenVertex(&v)[3] = tri.v;
  PixelBox b;
  b.x_lo = std::max<int64_t>(0, floor_div(std::min({v[0].x, v[1].x, v[2].x}), kSubpixelOne));
  b.x_hi = std::min<int64_t>(vp.width - 1, floor_div(std::max({v[0].x, v[1].x, v[2].x}), kSubpixelOne));
  b.y_lo = std::max<int64_t>({0, rows.begin, floor_div(std::min({v[0].y, v[1].y, v[2].y}), kSubpixelOne)});
  b.y_hi = std::min<int64_t>({vp.height - 1, int64_t{rows.end} - 1,
                              floor_div(std::max({v[0].y, v[1].y, v[2].y}), kSubpixelOne)});
  return b;
}

void rasterize_coverage(const ScreenTriangle& tri, const Viewport& vp, std::vector<Fragment>& out,
                        std::vector<double>* z_exact, RowRange rows) {
  if (vp.width < 1 || vp.width > kMaxFrameSize || vp.height < 1 || vp.height > kMaxFrameSize)
    return;
  const std::vector<SamplePos>& pattern = sample_pattern(vp.coverage_samples);
  const int n = int(pattern.size());
  edge::OrientedTriangle t;  // the rasterizer's orientation: inside where E > 0
  if (!edge::orient(tri, t)) return;
  const ScreenVertex(&v)[3] = t.v;
  const int64_t area = t.area;

  const PixelBox box = coverage_box(tri, vp, rows);
  if (box.empty()) return;
  const int64_t px_lo = box.x_lo, px_hi = box.x_hi, py_lo = box.y_lo, py_hi = box.y_hi;

  // Edge k is opposite vertex k: its value at the centre is vertex k's weight times A.
  const Edge edge[3] = {make_edge(v[1], v[2]), make_edge(v[2], v[0]), make_edge(v[0], v[1])};
  // E at a sample = E at the pixel's corner + the sample's offset term, per edge and sample.
  std::vector<int64_t> offset(size_t(3 * n));
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < n; ++i)
      offset[size_t(k * n + i)] =
          edge[k].ex * pattern[size_t(i)].y - edge[k].ey * pattern[size_t(i)].x;

  const int64_t zv[3] = {int64_t{v[0].z}, int64_t{v[1].z}, int64_t{v[2].z}};
  const int64_t z_lo = std::min({zv[0], zv[1], zv[2]}), z_hi = std::max({zv[0], zv[1], zv[2]});
  const double ze_lo = std::min({v[0].z_exact, v[1].z_exact, v[2].z_exact});
  const double ze_hi = std::max({v[0].z_exact, v[1].z_exact, v[2].z_exact});
  const int64_t half_area = area / 2;
  const double area_d = double(area);

  Fragment frag;
  frag.color = tri.color;
  frag.front = tri.front;
  frag.prim = tri.prim;

  for (int64_t py = py_lo; py <= py_hi; ++py) {
    frag.y = static_cast<uint16_t>(py);
    for (int64_t px = px_lo; px <= px_hi; ++px) {
      const int64_t cx = px * kSubpixelOne, cy = py * kSubpixelOne;  // the pixel's corner
      const int64_t e0 = edge[0].at(cx, cy), e1 = edge[1].at(cx, cy), e2 = edge[2].at(cx, cy);
      int count = 0;
      for (int i = 0; i < n; ++i)
        count += (e0 + offset[size_t(i)] >= edge[0].bias) &&
                 (e1 + offset[size_t(n + i)] >= edge[1].bias) &&
                 (e2 + offset[size_t(2 * n + i)] >= edge[2].bias);
      if (count == 0) continue;
      // Depth at the centre: raster.md step 5's formula with signed weights (the centre may
      // lie outside), floor division, then clamped to the vertex depth range.
      const int64_t w[3] = {edge[0].at(cx + kSubpixelOne / 2, cy + kSubpixelOne / 2),
                            edge[1].at(cx + kSubpixelOne / 2, cy + kSubpixelOne / 2),
                            edge[2].at(cx + kSubpixelOne / 2, cy + kSubpixelOne / 2)};
      const i128 num = i128(w[0]) * zv[0] + i128(w[1]) * zv[1] + i128(w[2]) * zv[2] + half_area;
      const i128 z = std::clamp<i128>(floor_div(num, area), z_lo, z_hi);
      frag.x = static_cast<uint16_t>(px);
      frag.z = static_cast<uint32_t>(z);
      frag.coverage = static_cast<uint8_t>(count);
      out.push_back(frag);
      if (z_exact) {
        const double ze = (double(w[0]) * v[0].z_exact + double(w[1]) * v[1].z_exact +
                           double(w[2]) * v[2].z_exact) /
                          area_d;
        z_exact->push_back(std::clamp(ze, ze_lo, ze_hi));
      }
    }
  }
}

}  // namespace zb
