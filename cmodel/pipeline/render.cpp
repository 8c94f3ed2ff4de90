#include "render.h"

#include <algorithm>
#include <cmath>

#include "executor.h"
#include "raster/lines.h"
#include "raster/raster.h"
#include "raster/sample_coverage.h"

namespace zb {

namespace {

// The stored fragments as a FragmentSource: triangles' and lines' copied from storage, coverage
// samples rasterized when a pass asks for them (they are not stored).
class StoredSource final : public FragmentSource {
 public:
  explicit StoredSource(const RasterizedScene& rs) : rs_(rs) {}

  void triangles(size_t /*index*/, const PassState& pass, FragmentKind kind,
                 std::vector<Fragment>& out, const TriangleDone& done) override {
    for (size_t i = 0; i < rs_.triangles.size(); ++i) {
      const ScreenTriangle& t = rs_.triangles[i];
      if (!pass_draws(pass, t)) continue;
      const size_t from = out.size();
      if (kind == FragmentKind::kCoverage)
        rasterize_coverage(t, rs_.viewport, out);
      else
        out.insert(out.end(), rs_.fragments.begin() + std::ptrdiff_t(rs_.first_fragment[i]),
                   rs_.fragments.begin() + std::ptrdiff_t(rs_.first_fragment[i + 1]));
      done(t, from);
    }
  }

  void lines(std::vector<Fragment>& out, const LineDone& done) override {
    for (size_t i = 0; i < rs_.lines.size(); ++i) {
      const size_t from = out.size();
      out.insert(out.end(), rs_.line_fragments.begin() + std::ptrdiff_t(rs_.first_line_fragment[i]),
                 rs_.line_fragments.begin() + std::ptrdiff_t(rs_.first_line_fragment[i + 1]));
      done(rs_.lines[i], from);
    }
  }

  uint32_t slope(const ScreenTriangle& t) override {
    if (slopes_.empty()) slopes_ = primitive_slopes(rs_.triangles);
    return slopes_[t.prim];
  }

 private:
  const RasterizedScene& rs_;
  std::vector<uint32_t> slopes_;  // when a pass has a depth offset
};

}  // namespace

RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp, bool exact_depth) {
  std::vector<ScreenTriangle> triangles = setup_triangles(scene, vp);
  std::vector<ScreenLine> lines = setup_lines(scene, vp, triangles);
  RasterizedScene rs = rasterize_triangles(std::move(triangles), vp, scene.background, exact_depth);
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
                                    Rgba8 background, bool exact_depth) {
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
  if (exact_depth) rs.z_exact.reserve(size_t(estimate * 1.02));
  for (const ScreenTriangle& t : rs.triangles) {
    rs.first_fragment.push_back(rs.fragments.size());
    rasterize(t, vp, rs.fragments, exact_depth ? &rs.z_exact : nullptr);
  }
  rs.first_fragment.push_back(rs.fragments.size());
  return rs;
}

std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass) {
  std::vector<Fragment> out;
  // A pixel pass draws at most the stored fragments: one allocation, not a doubling series.
  out.reserve(std::max(rs.fragments.size(), rs.line_fragments.size()));
  feed_stored_pass(rs, pass, [&](const Fragment* f, size_t n) { out.insert(out.end(), f, f + n); });
  return out;
}

void feed_stored_pass(const RasterizedScene& rs, const PassState& pass, const DrawFn& draw) {
  std::vector<Fragment> buffer;
  StoredSource source(rs);
  feed_pass(source, 0, pass, draw, buffer);
}

Traffic pass_traffic(const PassStats& s, const RopState& state, const Viewport& vp) {
  const uint64_t color =
      state.blend == BlendMode::kAccumulate
          ? uint64_t(4 * vp.wboit.acc_bits + vp.wboit.rev_bits + 7) / 8
      : state.blend == BlendMode::kLayers
          ? (uint64_t(state.layers) * uint64_t(vp.depth_bits + 32) + 7) / 8  // the layers word
          : 4;
  const uint64_t depth = uint64_t(vp.depth_bits + 7) / 8;
  return {s.color_reads * color + s.depth_reads * depth,
          s.color_writes * color + s.depth_writes * depth};
}

Traffic plan_traffic(const std::vector<PassStats>& passes, const PassPlan& plan,
                     const Viewport& vp) {
  Traffic t;
  for (size_t i = 0; i < passes.size() && i < plan.passes.size(); ++i) {
    const Traffic p = pass_traffic(passes[i], plan.passes[i].rop, vp);
    t.read += p.read;
    t.written += p.written;
  }
  return t;
}

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend) {
  StoredSource source(rs);
  RenderResult result;
  result.passes = run_plan(plan, rs.viewport, rs.background, source, backend);
  result.triangles = rs.triangles.size();
  result.framebuffer = backend.framebuffer();
  return result;
}

}  // namespace zb
