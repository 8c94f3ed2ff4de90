// The depth offset an edge takes from its own faces (docs/raster.md "Depth offset"): how far a
// line fragment lies behind the nearest of the edge's faces on the pixel centre's side of the
// edge, at the pixel centre, where the depth test will compare it with whatever the faces pass
// left there.
#pragma once

#include <cstdint>

#include "geometry/edges.h"

namespace zb {

// An edge's own faces, oriented once for all of the line's fragments.
class FaceLift {
 public:
  explicit FaceLift(const ScreenLine& line);
  // The depth of the edge's own faces at the centre of pixel (x, y): the least, over the faces
  // of the line that lie on the centre's side of it (both when the centre is on the line), of
  // the face's plane at the centre, rounded as the rasterizer rounds a covered centre and
  // clamped to the face's vertex depths. `none` when no face is on that side.
  uint64_t own_face_depth(int64_t x, int64_t y, uint64_t none) const;
  // max(0, z - own_face_depth): what lifts a line fragment at (x, y, z) to its own surface.
  uint64_t lift(int64_t x, int64_t y, uint32_t z) const;

 private:
  struct Face {
    ScreenVertex v[3];  // positive area, as the rasterizers orient a triangle
    int64_t area = 0;   // twice the area in 1/256-pixel units; 0: the face takes no part
    int side = 0;       // EdgeFace::side
  };
  const ScreenLine& line_;
  Face faces_[2];
};

// FaceLift(line).own_face_depth and .lift, for one pixel.
uint64_t own_face_depth(const ScreenLine& line, int64_t x, int64_t y, uint64_t none);
uint64_t face_lift(const ScreenLine& line, int64_t x, int64_t y, uint32_t z);

}  // namespace zb
