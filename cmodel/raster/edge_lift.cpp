// An edge's offset from its own faces (docs/raster.md, "Depth offset").
#include "edge_lift.h"

#include <algorithm>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;

// The face's plane at p (1/256 pixel): raster.md step 5's formula with signed weights, so a
// covered centre gets exactly its fragment's depth, then clamped to the vertex depths (the
// coverage rasterizer's rule for a centre outside). False for a zero-area face.
bool plane_depth(const EdgeFace& face, int64_t px, int64_t py, uint64_t& z) {
  ScreenTriangle tri;
  for (int k = 0; k < 3; ++k) tri.v[k] = face.v[k];
  edge::OrientedTriangle t;
  if (!edge::orient(tri, t)) return false;
  const ScreenVertex(&v)[3] = t.v;
  // w_k: the edge function of the edge opposite vertex k at p.
  auto weight = [&](const ScreenVertex& a, const ScreenVertex& b) {
    return (int64_t{b.x} - a.x) * (py - a.y) - (int64_t{b.y} - a.y) * (px - a.x);
  };
  const int64_t w[3] = {weight(v[1], v[2]), weight(v[2], v[0]), weight(v[0], v[1])};
  const i128 num = i128(w[0]) * v[0].z + i128(w[1]) * v[1].z + i128(w[2]) * v[2].z + t.area / 2;
  const i128 lo = std::min({v[0].z, v[1].z, v[2].z}), hi = std::max({v[0].z, v[1].z, v[2].z});
  z = static_cast<uint64_t>(std::clamp<i128>(edge::floor_div(num, t.area), lo, hi));
  return true;
}

}  // namespace

uint64_t own_face_depth(const ScreenLine& line, int64_t x, int64_t y, uint64_t none) {
  const int64_t px = x * kSubpixelOne + kSubpixelOne / 2, py = y * kSubpixelOne + kSubpixelOne / 2;
  const int64_t e = line_side(line, px, py);
  const int side = e > 0 ? 1 : e < 0 ? -1 : 0;
  uint64_t nearest = none;
  for (const EdgeFace& f : line.faces) {
    if (f.prim == kNoFace || f.side == 0 || (side != 0 && side != f.side)) continue;
    uint64_t z;
    if (plane_depth(f, px, py, z)) nearest = std::min(nearest, z);
  }
  return nearest;
}

uint64_t face_lift(const ScreenLine& line, int64_t x, int64_t y, uint32_t z) {
  const uint64_t own = own_face_depth(line, x, y, z);
  return own < z ? z - own : 0;
}

}  // namespace zb
