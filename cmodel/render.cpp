#include "render.h"

#include <algorithm>
#include <cmath>

#include "raster.h"

namespace zb {

RasterizedScene rasterize_scene(const Scene& scene, const Viewport& vp) {
  return rasterize_triangles(setup_triangles(scene, vp), vp, scene.background);
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

namespace {

bool pass_draws(const PassState& pass, const ScreenTriangle& t) {
  switch (pass.filter) {
    case PrimFilter::kOpaque: if (t.transparent) return false; break;
    case PrimFilter::kTransparent: if (!t.transparent) return false; break;
    case PrimFilter::kAll: break;
  }
  switch (pass.cull) {
    case Cull::kFront: return !t.front;
    case Cull::kBack: return t.front;
    case Cull::kNone: return true;
  }
  return true;
}

// Calls draw(first, count) for each run of consecutive fragments the pass draws.
template <class Draw>
void for_each_pass_range(const RasterizedScene& rs, const PassState& pass, Draw&& draw) {
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

}  // namespace

std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass) {
  std::vector<Fragment> out;
  for_each_pass_range(rs, pass, [&](const Fragment* f, size_t n) { out.insert(out.end(), f, f + n); });
  return out;
}

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend) {
  const Viewport& vp = rs.viewport;
  backend.begin_frame(vp.width, vp.height, vp.depth_bits, rs.background);
  RenderResult result;
  for (const PassState& pass : plan.passes) {
    backend.label_pass(pass.name);
    backend.begin_pass(pass.rop);
    for_each_pass_range(rs, pass,
                        [&](const Fragment* f, size_t n) { backend.draw(f, n); });
    result.passes.push_back(backend.end_pass());
  }
  result.framebuffer = backend.framebuffer();
  return result;
}

}  // namespace zb
