// What the banded renderer draws from (frame_render.h): the set-up triangles, on several
// threads when asked, and the edges when a plan draws them.
#pragma once

#include <vector>

#include "edges.h"
#include "geometry.h"
#include "pipeline/passes.h"
#include "scene/scene.h"

namespace zb {

// What a frame is drawn from: the set-up triangles in scene order and, when a pass draws
// edges, the scene's unique edges (edges.h).
struct FrameGeometry {
  Viewport viewport;
  Rgba8 background;
  std::vector<ScreenTriangle> triangles;
  std::vector<ScreenLine> lines;
};

// True when a pass of `plan` draws the scene's edges (PrimFilter::kEdges).
bool plan_draws_edges(const PassPlan& plan);

// The triangles of setup_triangles(scene, vp), bit for bit and in the same order, computed on
// `threads` threads (0 = all cores).
std::vector<ScreenTriangle> setup_triangles_parallel(const Scene& scene, const Viewport& vp,
                                                     int threads);

// setup_triangles on `threads` threads (setup_triangles_parallel; 1: serial, 0: all cores),
// and setup_lines when `with_lines`.
FrameGeometry make_frame_geometry(const Scene& scene, const Viewport& vp, bool with_lines,
                          int threads = 1);

}  // namespace zb
