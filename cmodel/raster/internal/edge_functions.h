// Integer helpers shared by the rasterizers (triangles, coverage, lines): floor division,
// the coordinate range they accept, the top-left rule and triangle orientation (raster.md).
#pragma once

#include <cstdint>
#include <utility>

#include "geometry/geometry.h"

namespace zb::edge {

// Window coordinates beyond this (in 1/256 pixel) are rejected: the geometry stage keeps
// |x|, |y| < 2^23, and with |x|, |y| <= 2^24 every edge value stays below 2^51.
constexpr int64_t kCoordLimit = int64_t{1} << 24;

template <class T>
T floor_div(T a, int64_t b) {  // b > 0
  T q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}

inline int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }  // b > 0

inline bool in_range(const ScreenVertex& v) {
  return v.x >= -kCoordLimit && v.x <= kCoordLimit && v.y >= -kCoordLimit && v.y <= kCoordLimit;
}

// With the triangle oriented to positive area (clockwise on the y-down screen) the inside is
// where the edge function of a->b is positive. A top edge is horizontal with the inside below
// it (ey == 0, ex > 0); a left edge has the inside to its right: it runs upward (ey < 0).
// A pixel centre or sample on the edge is covered only on a top or left edge.
inline bool top_left(int64_t ex, int64_t ey) { return ey < 0 || (ey == 0 && ex > 0); }

// A triangle's vertices (and their facing flags) in the rasterizers' orientation.
struct OrientedTriangle {
  ScreenVertex v[3];
  bool facing[3];
  int64_t area = 0;  // twice the area in 1/256-pixel units, > 0
};

// Orients `tri` to positive area, swapping v1 and v2 with their flags. False when a vertex is
// out of range or the area is zero: such a triangle has no fragments.
inline bool orient(const ScreenTriangle& tri, OrientedTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    t.v[i] = tri.v[i];
    t.facing[i] = tri.facing[i];
    if (!in_range(t.v[i])) return false;
  }
  t.area = (int64_t{t.v[1].x} - t.v[0].x) * (int64_t{t.v[2].y} - t.v[0].y) -
           (int64_t{t.v[2].x} - t.v[0].x) * (int64_t{t.v[1].y} - t.v[0].y);
  if (t.area == 0) return false;
  if (t.area < 0) {
    std::swap(t.v[1], t.v[2]);
    std::swap(t.facing[1], t.facing[2]);
    t.area = -t.area;
  }
  return true;
}

}  // namespace zb::edge
