// An edge's offset from its own faces (docs/raster.md, "Depth offset").
#include "edge_lift.h"

#include <algorithm>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;

}  // namespace

FaceLift::FaceLift(const ScreenLine& line) : line_(line) {
  for (int k = 0; k < 2; ++k) {
    const EdgeFace& f = line.faces[k];
    if (f.prim == kNoFace || f.side == 0) continue;
    ScreenTriangle tri;
    for (int i = 0; i < 3; ++i) tri.v[i] = f.v[i];
    edge::OrientedTriangle t;
    if (!edge::orient(tri, t)) continue;  // zero area: no plane
    for (int i = 0; i < 3; ++i) faces_[k].v[i] = t.v[i];
    faces_[k].area = t.area;
    faces_[k].side = f.side;
  }
}

// Each face's plane at p (1/256 pixel): raster.md step 5's formula with signed weights, so a
// covered centre gets exactly its fragment's depth, then clamped to the vertex depths (the
// coverage rasterizer's rule for a centre outside).
uint64_t FaceLift::own_face_depth(int64_t x, int64_t y, uint64_t none) const {
  const int64_t px = x * kSubpixelOne + kSubpixelOne / 2, py = y * kSubpixelOne + kSubpixelOne / 2;
  const int64_t e = line_side(line_, px, py);
  const int side = e > 0 ? 1 : e < 0 ? -1 : 0;
  uint64_t nearest = none;
  for (const Face& f : faces_) {
    if (f.area == 0 || (side != 0 && side != f.side)) continue;
    const ScreenVertex(&v)[3] = f.v;
    // w_k: the edge function of the edge opposite vertex k at p.
    auto weight = [&](const ScreenVertex& a, const ScreenVertex& b) {
      return (int64_t{b.x} - a.x) * (py - a.y) - (int64_t{b.y} - a.y) * (px - a.x);
    };
    const int64_t w[3] = {weight(v[1], v[2]), weight(v[2], v[0]), weight(v[0], v[1])};
    const i128 num = i128(w[0]) * v[0].z + i128(w[1]) * v[1].z + i128(w[2]) * v[2].z + f.area / 2;
    const i128 lo = std::min({v[0].z, v[1].z, v[2].z}), hi = std::max({v[0].z, v[1].z, v[2].z});
    nearest = std::min(nearest, uint64_t(std::clamp<i128>(edge::floor_div(num, f.area), lo, hi)));
  }
  return nearest;
}

uint64_t FaceLift::lift(int64_t x, int64_t y, uint32_t z) const {
  const uint64_t own = own_face_depth(x, y, z);
  return own < z ? z - own : 0;
}

uint64_t own_face_depth(const ScreenLine& line, int64_t x, int64_t y, uint64_t none) {
  return FaceLift(line).own_face_depth(x, y, none);
}

uint64_t face_lift(const ScreenLine& line, int64_t x, int64_t y, uint32_t z) {
  return FaceLift(line).lift(x, y, z);
}

}  // namespace zb
