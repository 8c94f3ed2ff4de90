#include "feeder.h"

#include <algorithm>


namespace zb {

namespace {

// Fragments handed to the datapath at a time: a buffer that stays in the cache.
constexpr size_t kChunk = 4096;

}  // namespace

bool pass_draws(const PassState& pass, const ScreenTriangle& t) {
  switch (pass.filter) {
    case PrimFilter::kOpaque: if (t.transparent) return false; break;
    case PrimFilter::kTransparent: if (!t.transparent) return false; break;
    case PrimFilter::kAll: break;
    case PrimFilter::kEdges: return false;  // lines, not triangles
  }
  switch (pass.cull) {
    case Cull::kFront: return !t.front;
    case Cull::kBack: return t.front;
    case Cull::kNone: return true;
  }
  return true;
}

bool feeder_rewrites(const PassState& p) {
  return p.facing != FacingFilter::kAll || p.zero_alpha_toward || p.offset.any() ||
         p.constant_color;
}

namespace {

uint64_t clamped(const DepthOffset& o, uint64_t off) {
  return o.clamp != 0 ? std::min<uint64_t>(off, o.clamp) : off;
}

}  // namespace

uint64_t depth_offset_of(const DepthOffset& o, uint32_t slope) {
  if (o.faces) return clamped(o, o.units);
  return clamped(o, uint64_t{o.units} + (uint64_t{o.slope_q8} * slope + 255) / 256);
}

uint64_t edge_offset_of(const DepthOffset& o, const FaceLift& lift, const Fragment& f, int row0) {
  return clamped(o, uint64_t{o.units} + lift.lift(f.x, int64_t{f.y} + row0, f.z));
}

bool feed_fragment(const PassState& p, uint64_t offset, Fragment& f) {
  if (p.facing == FacingFilter::kToward && !f.facing) return false;
  if (p.facing == FacingFilter::kAway && f.facing) return false;
  if (p.constant_color) f.color = p.color;
  if (p.zero_alpha_toward && f.facing) f.color.a = 0;
  f.z = f.z > offset ? static_cast<uint32_t>(f.z - offset) : 0;
  return true;
}

std::vector<uint32_t> primitive_slopes(const std::vector<ScreenTriangle>& triangles) {
  std::vector<uint32_t> slope;
  for (const ScreenTriangle& t : triangles) {
    if (t.prim >= slope.size()) slope.resize(size_t(t.prim) + 1, 0);
    slope[t.prim] = std::max(slope[t.prim], depth_slope(t));
  }
  return slope;
}

FrameOp resolve_op(FrameOp op, Rgba8 background) {
  if (op.background) {
    op.value = background;
    op.background = false;
  }
  return op;
}

void feed_pass(FragmentSource& source, size_t index, const PassState& pass, const DrawFn& draw,
               std::vector<Fragment>& buf) {
  const bool edges = pass.filter == PrimFilter::kEdges;
  const bool rewrite = edges || feeder_rewrites(pass);
  buf.clear();
  buf.reserve(2 * kChunk);
  // One primitive's fragments, buf[from..]: rewritten (or dropped) in place, each with the
  // offset `offset_of` gives it; the buffer drawn once it holds a chunk.
  auto finish = [&](size_t from, const auto& offset_of) {
    if (rewrite) {
      size_t keep = from;
      for (size_t k = from; k < buf.size(); ++k) {
        Fragment f = buf[k];
        if (feed_fragment(pass, offset_of(f), f)) buf[keep++] = f;
      }
      buf.resize(keep);
    }
    if (buf.size() >= kChunk) {
      draw(buf.data(), buf.size());
      buf.clear();
    }
  };
  if (edges) {
    const DepthOffset& o = pass.offset;
    const int row0 = source.row_origin();
    source.lines(buf, [&](const ScreenLine& l, size_t from) {
      if (!o.any()) {
        finish(from, [](const Fragment&) { return uint64_t{0}; });
      } else if (o.faces) {  // per fragment: how far it lies behind its own faces
        const FaceLift lift(l);
        finish(from, [&](const Fragment& f) { return edge_offset_of(o, lift, f, row0); });
      } else {
        const uint64_t off = depth_offset_of(o, l.depth_slope);
        finish(from, [off](const Fragment&) { return off; });
      }
    });
  } else {
    const bool offset = rewrite && pass.offset.any();
    const FragmentKind kind = is_coverage_pass(pass.rop) ? FragmentKind::kCoverage
                                                         : FragmentKind::kPixel;
    source.triangles(index, pass, kind, buf, [&](const ScreenTriangle& t, size_t from) {
      const uint64_t off = offset ? depth_offset_of(pass.offset, source.slope(t)) : 0;
      finish(from, [off](const Fragment&) { return off; });
    });
  }
  if (!buf.empty()) draw(buf.data(), buf.size());
}

}  // namespace zb
