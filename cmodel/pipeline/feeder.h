// The feeder between raster and datapath (docs/datapath.md, "The feeder"): which primitives a
// pass draws and how their fragments are rewritten on the way. It draws from a FragmentSource:
// the whole frame's stored fragments (render.h) or a band's, rasterized as they are drawn
// (frame_render.h). The sources only produce fragments; every decision is made here, once.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/edges.h"
#include "geometry/geometry.h"
#include "raster/edge_lift.h"
#include "rop/fragment.h"

namespace zb {

// The primitive filter and cull: true when `pass` draws triangle `t`.
bool pass_draws(const PassState& pass, const ScreenTriangle& t);
// True when the pass changes or drops fragments on their way to the datapath.
bool feeder_rewrites(const PassState& pass);
// The depth offset of a primitive with depth slope `slope`:
// units + ceil(slope_q8 * slope / 256), at most `clamp` when clamp > 0. With o.faces (an edge
// offset taken from its faces, edge_offset_of) a triangle's is units, at most `clamp`.
uint64_t depth_offset_of(const DepthOffset& o, uint32_t slope);
// The depth offset, with o.faces, of an edge fragment f whose rows start at frame row `row0`:
// units + the lift to its line's own faces (raster/edge_lift.h) at f's pixel, at most `clamp`
// when clamp > 0. (Without o.faces an edge's offset is depth_offset_of its depth slope.)
uint64_t edge_offset_of(const DepthOffset& o, const FaceLift& lift, const Fragment& f, int row0);
// Applies the pass's feeder rules to one fragment, in this order: facing filter (false:
// dropped), constant colour, zero alpha for fragments facing the viewer, depth offset
// (saturating at 0, the near plane).
bool feed_fragment(const PassState& pass, uint64_t offset, Fragment& f);
// A triangle's depth slope for the offset is its source primitive's, the largest of its
// clipped pieces: indexed by ScreenTriangle::prim.
std::vector<uint32_t> primitive_slopes(const std::vector<ScreenTriangle>& triangles);
// `op` as the backend receives it: a plan's background placeholder replaced by `background`.
FrameOp resolve_op(FrameOp op, Rgba8 background);

// The fragments a triangle is drawn with: pixel centres, or coverage samples (coverage passes).
enum class FragmentKind : uint8_t { kPixel, kCoverage };

// Where a pass's fragments come from. A source appends each primitive's fragments to the
// feeder's buffer, then names the primitive; the feeder filters and rewrites them there.
class FragmentSource {
 public:
  using TriangleDone = std::function<void(const ScreenTriangle& t, size_t first)>;
  using LineDone = std::function<void(const ScreenLine& l, size_t first)>;
  virtual ~FragmentSource() = default;
  // The triangles pass `index` draws (pass_draws), in primitive order: each one's fragments of
  // `kind` appended to `out`, then done(t, first) with out[first..] its fragments.
  virtual void triangles(size_t index, const PassState& pass, FragmentKind kind,
                         std::vector<Fragment>& out, const TriangleDone& done) = 0;
  // The scene's edges (edges.h), in order, likewise.
  virtual void lines(std::vector<Fragment>& out, const LineDone& done) = 0;
  // The depth slope of triangle `t` for the offset: its source primitive's (primitive_slopes).
  virtual uint32_t slope(const ScreenTriangle& t) = 0;
  // The frame row of the fragments' row 0 (a band's fragments come with rows relative to the
  // band): where an edge's offset from its faces is measured.
  virtual int row_origin() const { return 0; }
};

using DrawFn = std::function<void(const Fragment* fragments, size_t count)>;

// Pass `index` of a plan: its fragments from `source`, filtered and rewritten by the pass's
// rules, handed to `draw` in primitive order, a few thousand at a time. `buffer` is the
// scratch they gather in (cleared first; the caller keeps it from pass to pass).
void feed_pass(FragmentSource& source, size_t index, const PassState& pass, const DrawFn& draw,
               std::vector<Fragment>& buffer);

}  // namespace zb
