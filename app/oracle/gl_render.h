// A pass plan drawn through OpenGL: the scene's clip-space triangles (geometry.h,
// transform_triangles) with each pass's primitive filter, cull, depth and blend state as GL
// state. GL does its own clipping, viewport, rasterization, depth interpolation and blending.
#pragma once

#include <string>
#include <vector>

#include "rop/framebuffer.h"
#include "geometry/geometry.h"
#include "gl_context.h"
#include "pipeline/passes.h"

namespace zb::oracle {

// Empty when OpenGL can draw every pass of `plan`; otherwise what it cannot draw.
std::string unsupported_reason(const PassPlan& plan);

// Which way GL's window y runs relative to the picture. kDown: GL draws the picture upside
// down (clip y negated, front faces clockwise), so GL's window y is zblend's y-down window y
// and GL's fill rule for pixel centres on an edge meets the golden model's top-left rule in
// the same frame. kUp: GL's usual y up, rows flipped on read-back; pixels on a horizontal edge
// then go to the other triangle (docs/oracle.md, "Edges through pixel centres").
enum class WindowY { kDown, kUp };

// The GL objects a plan is drawn with (program, vertex array, buffer), made once so that
// repeated frames time the drawing, not the shader compiler.
class GlRenderer {
 public:
  explicit GlRenderer(GlContext& gl);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // As render_gl below.
  Framebuffer draw(const std::vector<ClipTriangle>& triangles, const PassPlan& plan,
                   Rgba8 background, WindowY window_y = WindowY::kDown);

 private:
  GlContext& gl_;
  unsigned program_ = 0, vao_ = 0, vbo_ = 0;
};

// Draws `plan` into `gl`'s framebuffer cleared to `background` and far depth, and reads it
// back as a zblend frame: row 0 at the top, 24-bit depth. Throws std::invalid_argument when
// the plan is unsupported, GlUnavailable when GL fails.
Framebuffer render_gl(GlContext& gl, const std::vector<ClipTriangle>& triangles,
                      const PassPlan& plan, Rgba8 background, WindowY window_y = WindowY::kDown);

}  // namespace zb::oracle
