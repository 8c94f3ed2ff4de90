// The depth offset an edge takes from its own faces (docs/raster.md "Depth offset"): how far a
// line fragment lies behind the nearest of the edge's faces on the pixel centre's side of the
// edge, at the pixel centre, where the depth test will compare it with whatever the faces pass
// left there.
#pragma once

#include <cstdint>

#include "geometry/edges.h"

namespace zb {

// The depth of the edge's own faces at the centre of pixel (x, y): the least, over the faces
// of `line` that lie on the centre's side of it (both when the centre is on the line), of the
// face's plane at the centre, rounded as the rasterizer rounds a covered centre and clamped to
// the face's vertex depths. `none` when no face is on that side.
uint64_t own_face_depth(const ScreenLine& line, int64_t x, int64_t y, uint64_t none);

// max(0, z - own_face_depth): what lifts a line fragment at (x, y, z) to its own surface.
uint64_t face_lift(const ScreenLine& line, int64_t x, int64_t y, uint32_t z);

}  // namespace zb
