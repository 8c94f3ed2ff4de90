// Runs a pass plan over a scene on a backend: geometry, raster, then per pass the feeder
// (primitive filter and cull) and the datapath.
#pragma once

#include <string>
#include <vector>

#include "backend.h"
#include "edges.h"
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
  // The unique tessellation edges (edges.h) and their line fragments (lines.h), for passes
  // with PrimFilter::kEdges; not part of the reference.
  std::vector<ScreenLine> lines;
  std::vector<Fragment> line_fragments;      // all lines' fragments, in edge order
  std::vector<size_t> first_line_fragment;   // line i owns [first_line_fragment[i], [i+1])
};

RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp);

// The same from triangles already in window coordinates (tests, traces).
RasterizedScene rasterize_triangles(std::vector<ScreenTriangle> triangles, const Viewport& vp,
                                    Rgba8 background);

// Replaces the scene's edges with `lines` and rasterizes them (rasterize_scene does this with
// setup_lines; tests may give their own).
void add_lines(RasterizedScene& rs, std::vector<ScreenLine> lines);

// The feeder's primitive filter and cull: true when `pass` draws triangle `t`.
bool pass_draws(const PassState& pass, const ScreenTriangle& t);

// The feeder's per-fragment stage (docs/datapath.md, "The feeder"), shared by render() and the
// banded renderer (frame_render.h).
// True when the pass changes or drops fragments on their way to the datapath.
bool feeder_rewrites(const PassState& pass);
// The depth offset of a primitive with depth slope `slope`:
// units + ceil(slope_q8 * slope / 256), at most `clamp` when clamp > 0.
uint64_t depth_offset_of(const DepthOffset& o, uint32_t slope);
// Applies the pass's feeder rules to one fragment, in this order: facing filter (false:
// dropped), constant colour, zero alpha for fragments facing the viewer, depth offset
// (saturating at 0, the near plane).
bool feed_fragment(const PassState& pass, uint64_t offset, Fragment& f);
// A triangle's depth slope for the offset is its source primitive's, the largest of its
// clipped pieces: indexed by ScreenTriangle::prim.
std::vector<uint32_t> primitive_slopes(const std::vector<ScreenTriangle>& triangles);

// The fragments a pass draws, in primitive order, as the feeder sends them to the datapath
// (filtered, culled and rewritten by the pass's feeder rules).
std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass);

// `op` as the backend receives it: a plan's background placeholder replaced by `background`.
FrameOp resolve_op(FrameOp op, Rgba8 background);

struct RenderResult {
  Framebuffer framebuffer;
  std::vector<PassStats> passes;  // one per pass of the plan
};

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend);

}  // namespace zb
