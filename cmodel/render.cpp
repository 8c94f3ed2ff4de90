#include "render.h"

#include <algorithm>
#include <cmath>

#include "coverage.h"
#include "edges.h"
#include "lines.h"
#include "raster.h"

namespace zb {

RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp) {
  std::vector<ScreenTriangle> triangles = setup_triangles(scene, vp);
  std::vector<ScreenLine> lines = setup_lines(scene, vp, triangles);
  RasterizedScene rs = rasterize_triangles(std::move(triangles), vp, scene.background);
  add_lines(rs, std::move(lines));
  return rs;
}

void add_lines(RasterizedScene& rs, std::vector<ScreenLine> lines) {
  rs.lines = std::move(lines);
  rs.line_fragments.clear();
  rs.first_line_fragment.clear();
  for (const ScreenLine& l : rs.lines) {
    rs.first_line_fragment.push_back(rs.line_fragments.size());
    rasterize_line(l.v[0], l.v[1], rs.viewport, Rgba8{0, 0, 0, 255}, l.prim, rs.line_fragments);
  }
  rs.first_line_fragment.push_back(rs.line_fragments.size());
}

RasterizedScene rasterize_triangles(std::vector<ScreenTriangle> triangles, const Viewport& vp,
                                    Rgba8 background) {
  RasterizedScene rs;
  rs.viewport = vp;
  rs.background = background;
  rs.triangles = std::move(triangles);
  rs.first_fragment.reserve(rs.triangles.size() + 1);
  // Reserve about the fragments to come (the area covered), so the buffers grow once.
  const double frame = double(vp.width) * vp.height;
  double estimate = 0;
  for (const ScreenTriangle& t : rs.triangles) {
    const double ax = t.v[1].x - t.v[0].x, ay = t.v[1].y - t.v[0].y;
    const double bx = t.v[2].x - t.v[0].x, by = t.v[2].y - t.v[0].y;
    const double pixels = std::abs(ax * by - bx * ay) / (2.0 * kSubpixelOne * kSubpixelOne);
    estimate += std::min(pixels, frame) + 1;
  }
  rs.fragments.reserve(size_t(estimate * 1.02));
  rs.z_exact.reserve(size_t(estimate * 1.02));
  for (const ScreenTriangle& t : rs.triangles) {
    rs.first_fragment.push_back(rs.fragments.size());
    rasterize(t, vp, rs.fragments, &rs.z_exact);
  }
  rs.first_fragment.push_back(rs.fragments.size());
  return rs;
}

// --- the feeder's per-fragment stage (docs/datapath.md, "The feeder") ---

bool feeder_rewrites(const PassState& p) {
  return p.facing != FacingFilter::kAll || p.zero_alpha_toward || p.offset.any() ||
         p.constant_color;
}

uint64_t depth_offset_of(const DepthOffset& o, uint32_t slope) {
  uint64_t off = uint64_t{o.units} + (uint64_t{o.slope_q8} * slope + 255) / 256;
  if (o.clamp != 0) off = std::min<uint64_t>(off, o.clamp);
  return off;
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

namespace {

// Calls draw(first, count) for each run of consecutive fragments the pass draws.
template <class Draw>
void for_each_pass_range(const RasterizedScene& rs, const PassState& pass, Draw&& draw) {
  if (is_coverage_pass(pass.rop)) {  // coverage fragments, rasterized for the pass (coverage.h)
    std::vector<Fragment> cov;
    for (const ScreenTriangle& t : rs.triangles)
      if (pass_draws(pass, t)) rasterize_coverage(t, rs.viewport, cov);
    if (!cov.empty()) draw(cov.data(), cov.size());
    return;
  }
  size_t run_begin = 0, run_end = 0;
  for (size_t i = 0; i < rs.triangles.size(); ++i) {
    if (!pass_draws(pass, rs.triangles[i])) continue;
    if (rs.first_fragment[i] != run_end) {
      if (run_end > run_begin) draw(rs.fragments.data() + run_begin, run_end - run_begin);
      run_begin = rs.first_fragment[i];
    }
    run_end = rs.first_fragment[i + 1];
  }
  if (run_end > run_begin) draw(rs.fragments.data() + run_begin, run_end - run_begin);
}

// Calls draw(first, count) with the fragments the pass sends to the datapath, in primitive
// order: the triangles' (for_each_pass_range) or the edges' (PrimFilter::kEdges), rewritten by
// feed_fragment when the pass asks for it.
template <class Draw>
void feed_pass(const RasterizedScene& rs, const PassState& pass, Draw&& draw) {
  if (pass.filter != PrimFilter::kEdges && !feeder_rewrites(pass)) {
    for_each_pass_range(rs, pass, draw);
    return;
  }
  constexpr size_t kChunk = 4096;
  std::vector<Fragment> buf;
  buf.reserve(kChunk);
  auto emit = [&](const Fragment* f, size_t n, uint64_t offset) {
    for (size_t i = 0; i < n; ++i) {
      Fragment g = f[i];
      if (!feed_fragment(pass, offset, g)) continue;
      buf.push_back(g);
      if (buf.size() == kChunk) {
        draw(buf.data(), buf.size());
        buf.clear();
      }
    }
  };
  if (pass.filter == PrimFilter::kEdges) {
    for (size_t i = 0; i < rs.lines.size(); ++i) {
      const size_t first = rs.first_line_fragment[i];
      emit(rs.line_fragments.data() + first, rs.first_line_fragment[i + 1] - first,
           pass.offset.any() ? depth_offset_of(pass.offset, rs.lines[i].depth_slope) : 0);
    }
  } else if (!pass.offset.any()) {
    for_each_pass_range(rs, pass, [&](const Fragment* f, size_t n) { emit(f, n, 0); });
  } else {
    const std::vector<uint32_t> slope = primitive_slopes(rs.triangles);
    for_each_pass_range(rs, pass, [&](const Fragment* f, size_t n) {
      for (size_t i = 0; i < n; ++i) emit(f + i, 1, depth_offset_of(pass.offset, slope[f[i].prim]));
    });
  }
  if (!buf.empty()) draw(buf.data(), buf.size());
}

}  // namespace

bool pass_draws(const PassState& pass, const ScreenTriangle& t) {
  switch (pass.filter) {
    case PrimFilter::kOpaque: if (t.transparent) return false; break;
    case PrimFilter::kTransparent: if (!t.transparent) return false; break;
    case PrimFilter::kAll: break;
    case PrimFilter::kEdges: return false;  // lines, not triangles (feed_pass)
  }
  switch (pass.cull) {
    case Cull::kFront: return !t.front;
    case Cull::kBack: return t.front;
    case Cull::kNone: return true;
  }
  return true;
}

FrameOp resolve_op(FrameOp op, Rgba8 background) {
  if (op.background) {
    op.value = background;
    op.background = false;
  }
  return op;
}

std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass) {
  std::vector<Fragment> out;
  feed_pass(rs, pass, [&](const Fragment* f, size_t n) { out.insert(out.end(), f, f + n); });
  return out;
}

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend) {
  const Viewport& vp = rs.viewport;
  backend.begin_frame(vp.width, vp.height, vp.depth_bits, rs.background, vp.coverage_samples);
  RenderResult result;
  for (const PassState& pass : plan.passes) {
    for (const FrameOp& op : pass.frame_ops) backend.frame_op(resolve_op(op, rs.background));
    backend.label_pass(pass.name);
    backend.begin_pass(pass.rop);
    feed_pass(rs, pass, [&](const Fragment* f, size_t n) { backend.draw(f, n); });
    result.passes.push_back(backend.end_pass());
  }
  for (const FrameOp& op : plan.final_ops) backend.frame_op(resolve_op(op, rs.background));
  result.framebuffer = backend.framebuffer();
  return result;
}

}  // namespace zb
