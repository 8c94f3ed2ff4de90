// Geometry stage: transforms, flat Lambert shading, near- and far-plane clipping, guard band,
// viewport to fixed-point window coordinates, facing from winding.
#pragma once

#include <cstdint>
#include <vector>

#include "rop/fixed.h"
#include "scene/scene.h"

namespace zb {

// Largest width or height of a frame, in pixels.
constexpr int kMaxFrameSize = 8192;

struct Viewport {
  constexpr Viewport(int w = 0, int h = 0, int bits = kDefaultDepthBits,
           int samples = kDefaultCoverageSamples, WboitFormat wb = {})
      : width(w), height(h), depth_bits(bits), coverage_samples(samples), wboit(wb) {}
  int width = 0;
  int height = 0;
  int depth_bits = kDefaultDepthBits;
  int coverage_samples = kDefaultCoverageSamples;  // N of the sample pattern (raster.md "Coverage")
  WboitFormat wboit;  // accumulation, revealage and weight widths (datapath.md "Accumulate blend")
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
  bool facing[3] = {true, true, true};  // per vertex: normal toward the eye (raster.md, "Facing")
  bool transparent = false;
  uint32_t prim = 0;      // index of the source triangle in scene order
};

// Ambient share of the flat Lambert term: shade = kAmbient + (1 - kAmbient) * |n . l|.
constexpr float kAmbient = 0.25f;

// A scene triangle after the vertex stage, before clipping: clip-space corners (GLM float),
// flat colour, per-vertex facing. The OpenGL oracle draws exactly these.
struct ClipTriangle {
  glm::vec4 clip[3];
  Rgba8 color;
  bool facing[3] = {true, true, true};
  bool transparent = false;
  uint32_t prim = 0;
};

// The vertex stage over every object, in scene order: object -> world -> clip, shading and
// per-vertex facing. Triangles with a non-finite corner are dropped. Throws
// std::invalid_argument for a bad material or vertex index.
std::vector<ClipTriangle> transform_triangles(const Scene& scene, const Viewport& vp);

// Runs the geometry stage (transform_triangles, then the primitive stage) over every object of
// the scene, in scene order. A triangle that
// crosses the near or far plane (or the guard band) is clipped into a fan; one that lies wholly
// outside is dropped; zero-area triangles are dropped.
std::vector<ScreenTriangle> setup_triangles(const Scene& scene, const Viewport& vp);

// The per-vertex facing decision of the vertex stage (CN 103021015; raster.md, "Facing"):
// true when dot(normal_world, eye - vertex_world) > 0, in float.
bool vertex_faces_eye(const glm::vec3& normal_world, const glm::vec3& vertex_world,
                      const glm::vec3& eye);

// The stage's pieces, shared with the edge setup (edges.h): signed distance of a clip-space
// point to clip plane `plane` (0 near, 1 far, 2..5 the guard band; inside when >= 0), the
// crossing point interpolated from the inside end and set exactly on the plane, and the
// perspective divide and viewport (false when the point is unusable).
constexpr int kClipPlaneCount = 6;
float clip_plane_distance(int plane, const glm::vec4& c);
glm::vec4 clip_crossing(int plane, const glm::vec4& in, float d_in, const glm::vec4& out,
                        float d_out);
bool clip_to_window(const glm::vec4& c, const Viewport& vp, ScreenVertex& out);

}  // namespace zb
