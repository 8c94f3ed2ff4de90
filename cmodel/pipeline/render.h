// A pass plan over a whole frame's stored fragments: geometry and raster once, then the plan
// executor (executor.h) on any backend, golden model or RTL, with the fragments replayed from
// storage pass after pass.
#pragma once

#include <string>
#include <vector>

#include "feeder.h"
#include "geometry/frame_geometry.h"
#include "passes.h"
#include "rop/backend.h"
#include "scene/scene.h"

namespace zb {

// A frame's geometry (frame_geometry.h) with every primitive's fragments stored: ready for any
// pass, and for the exact reference (reference.h) and the traces (trace.h).
struct RasterizedScene : FrameGeometry {
  std::vector<Fragment> fragments;      // all triangles' fragments, in primitive order
  std::vector<double> z_exact;          // per fragment, unrounded window depth
  std::vector<size_t> first_fragment;   // triangle i owns [first_fragment[i], first_fragment[i+1])
  // The edges' line fragments (lines.h), for passes with PrimFilter::kEdges; not part of the
  // reference.
  std::vector<Fragment> line_fragments;      // all lines' fragments, in edge order
  std::vector<size_t> first_line_fragment;   // line i owns [first_line_fragment[i], [i+1])
};

// `exact_depth` false leaves z_exact empty: for runs that never build the exact reference.
RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp, bool exact_depth = true);

// The same from triangles already in window coordinates (tests, traces).
RasterizedScene rasterize_triangles(std::vector<ScreenTriangle> triangles, const Viewport& vp,
                                    Rgba8 background, bool exact_depth = true);

// Replaces the scene's edges with `lines` and rasterizes them (rasterize_scene does this with
// setup_lines; tests may give their own).
void add_lines(RasterizedScene& rs, std::vector<ScreenLine> lines);

// The fragments a pass draws, in primitive order, as the feeder sends them to the datapath
// (filtered, culled and rewritten by the pass's feeder rules).
std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass);
// The same handed to `draw` as the feeder goes, a few thousand at a time, nothing kept.
void feed_stored_pass(const RasterizedScene& rs, const PassState& pass, const DrawFn& draw);

struct RenderResult {
  Framebuffer framebuffer;
  std::vector<PassStats> passes;  // one per pass of the plan
  size_t triangles = 0;           // set-up triangles the frame was drawn from (after clipping)
};

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend);

// Memory traffic in bytes (docs/datapath.md "Counters"): per colour access 4 bytes, or in an
// accumulate pass the accumulation word's ceil((4A + R) / 8); per depth access the depth
// width in whole bytes.
struct Traffic {
  uint64_t read = 0;
  uint64_t written = 0;
};
Traffic pass_traffic(const PassStats& s, const RopState& state, const Viewport& vp);
// Over the passes of `plan`, `passes` their counters in order.
Traffic plan_traffic(const std::vector<PassStats>& passes, const PassPlan& plan,
                     const Viewport& vp);

}  // namespace zb
