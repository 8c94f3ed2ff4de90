#include "exact_depth.h"

#include <unordered_map>

#include "rop/rop.h"

namespace zb::oracle {

std::vector<Rgba8> replay_exact_depth(const RasterizedScene& rs, const PassPlan& plan,
                                      const std::vector<size_t>& pixels) {
  struct Pixel {
    Rgba8 color;
    double depth = 1.0;
  };
  std::unordered_map<size_t, size_t> slot;  // pixel index -> position in `pixels`
  for (size_t i = 0; i < pixels.size(); ++i) slot.emplace(pixels[i], i);
  std::vector<Pixel> out(pixels.size(), Pixel{rs.background, 1.0});
  const size_t width = static_cast<size_t>(rs.viewport.width);

  for (const PassState& pass : plan.passes) {
    const RopState& r = pass.rop;
    for (size_t t = 0; t < rs.triangles.size(); ++t) {
      if (!pass_draws(pass, rs.triangles[t])) continue;
      for (size_t k = rs.first_fragment[t]; k < rs.first_fragment[t + 1]; ++k) {
        const Fragment& f = rs.fragments[k];
        const auto it = slot.find(size_t{f.y} * width + f.x);
        if (it == slot.end()) continue;
        Pixel& p = out[it->second];
        const double z = rs.z_exact[k];
        if (r.depth_test && !depth_compare(r.depth_func, z, p.depth)) continue;
        p.color = apply_color_mask(r.color_mask, blend(r.blend, f.color, p.color), p.color);
        if (r.depth_test && r.depth_write) p.depth = z;
      }
    }
  }
  std::vector<Rgba8> colors;
  colors.reserve(out.size());
  for (const Pixel& p : out) colors.push_back(p.color);
  return colors;
}

}  // namespace zb::oracle
