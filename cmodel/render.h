// Runs a pass plan over a scene on a backend: geometry, raster, then per pass the feeder
// (primitive filter and cull) and the datapath.
#pragma once

#include <string>
#include <vector>

#include "backend.h"
#include "geometry.h"
#include "passes.h"
#include "scene.h"

namespace zb {

// A scene after geometry and raster: every triangle's fragments, ready for any pass.
struct RasterizedScene {
  Viewport viewport;
  Rgba8 background;
  std::vector<ScreenTriangle> triangles;
  std::vector<Fragment> fragments;      // all triangles' fragments, in primitive order
  std::vector<double> z_exact;          // per fragment, unrounded window depth
  std::vector<size_t> first_fragment;   // triangle i owns [first_fragment[i], first_fragment[i+1])
};

RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp);

// The same from triangles already in window coordinates (tests, traces).
RasterizedScene rasterize_triangles(std::vector<ScreenTriangle> triangles, const Viewport& vp,
                                    Rgba8 background);

// The fragments a pass draws, in primitive order.
std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass);

struct RenderResult {
  Framebuffer framebuffer;
  std::vector<PassStats> passes;  // one per pass of the plan
};

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend);

}  // namespace zb
