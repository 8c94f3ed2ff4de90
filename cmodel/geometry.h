// Geometry stage: transforms, flat Lambert shading, near- and far-plane clipping, guard band,
// viewport to fixed-point window coordinates, facing from winding.
#pragma once

#include <cstdint>
#include <vector>

#include "fixed.h"
#include "scene.h"

namespace zb {

// Largest width or height of a frame, in pixels.
constexpr int kMaxFrameSize = 8192;

struct Viewport {
  int width = 0;
  int height = 0;
  int depth_bits = kDefaultDepthBits;
};

// A vertex in window coordinates: x right, y down, 8 fractional bits; pixel centres at +0.5.
struct ScreenVertex {
  int32_t x = 0;
  int32_t y = 0;
  uint32_t z = 0;     // unorm window depth of Viewport::depth_bits
  double z_exact = 0; // window depth in [0, 1] before rounding: input to the reference
};

struct ScreenTriangle {
  ScreenVertex v[3];
  Rgba8 color;            // flat, shaded once per triangle
  bool front = true;      // counter-clockwise as the viewer sees it
  bool transparent = false;
  uint32_t prim = 0;      // index of the source triangle in scene order
};

// Ambient share of the flat Lambert term: shade = kAmbient + (1 - kAmbient) * |n . l|.
constexpr float kAmbient = 0.25f;

// Runs the geometry stage over every object of the scene, in scene order. A triangle that
// crosses the near or far plane (or the guard band) is clipped into a fan; one that lies wholly
// outside is dropped; zero-area triangles are dropped.
std::vector<ScreenTriangle> setup_triangles(const Scene& scene, const Viewport& vp);

}  // namespace zb
