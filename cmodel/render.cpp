#include "render.h"

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

}  // namespace

std::vector<Fragment> pass_fragments(const RasterizedScene& rs, const PassState& pass) {
  std::vector<Fragment> out;
  for (size_t i = 0; i < rs.triangles.size(); ++i) {
    if (!pass_draws(pass, rs.triangles[i])) continue;
    out.insert(out.end(), rs.fragments.begin() + static_cast<ptrdiff_t>(rs.first_fragment[i]),
               rs.fragments.begin() + static_cast<ptrdiff_t>(rs.first_fragment[i + 1]));
  }
  return out;
}

RenderResult render(const RasterizedScene& rs, const PassPlan& plan, Backend& backend) {
  const Viewport& vp = rs.viewport;
  backend.begin_frame(vp.width, vp.height, vp.depth_bits, rs.background);
  RenderResult result;
  for (const PassState& pass : plan.passes) {
    backend.begin_pass(pass.rop);
    backend.draw(pass_fragments(rs, pass));
    result.passes.push_back(backend.end_pass());
  }
  result.framebuffer = backend.framebuffer();
  return result;
}

}  // namespace zb
