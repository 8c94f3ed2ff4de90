// The wboit sweep: weighted blended OIT's accumulation width against its weight range, beside
// the patents' methods, on scenes where the order of high-alpha layers matters.
#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"
#include "scene/failure_scenes.h"
#include "scene/scene_suite.h"
#include "sweeps.h"

namespace zb::lab {

std::vector<Scene> wboit_scenes() {
  std::vector<Scene> out{layers_scene(4, 0.5f), layers_scene(4, 0.9f), *builtin_scene("cad"),
                         glass_torus_scene(), particles_scene()};
  out[2].name = "cad";
  out[3].name = "glass-torus";
  out[4].name = "particles";
  return out;
}

std::vector<WboitRow> wboit_scene_rows(const Scene& scene, const WboitOptions& o) {
  std::vector<WboitRow> rows;
  RasterizedScene rs = rasterize_scene(scene, o.viewport);
  const Framebuffer ref = render_reference(rs);
  auto run = [&](const std::string& method, const WboitFormat& f) {
    rs.viewport.wboit = f;
    const PassPlan* plan = find_plan(method);
    if (!plan) throw std::invalid_argument("wboit sweep: unknown method '" + method + "'");
    GoldenRop rop;
    const RenderResult r = render(rs, *plan, rop);
    const Traffic t = plan_traffic(r.passes, *plan, rs.viewport);
    rows.push_back({scene.name, method, f, t.read + t.written,
                    compare_images(r.framebuffer, ref)});
  };
  for (const std::string& b : o.baselines) run(b, WboitFormat{});
  for (const int a : o.acc_bits)
    for (const int w : o.weight_bits) run("wboit", WboitFormat{a, 8, w});
  return rows;
}

std::vector<WboitRow> wboit_sweep(const WboitOptions& o, const SweepProgress& progress) {
  std::vector<WboitRow> rows;
  const std::vector<Scene> scenes = wboit_scenes();
  for (size_t i = 0; i < scenes.size(); ++i) {
    const Scene& scene = scenes[i];
    for (WboitRow& r : wboit_scene_rows(scene, o)) rows.push_back(std::move(r));
    if (progress)
      progress(fmt::format("wboit: {}/{} {}, {} formats", i + 1, scenes.size(), scene.name,
                           o.acc_bits.size() * o.weight_bits.size()));
  }
  return rows;
}

double wboit_mean_error(const std::vector<WboitRow>& rows, int acc_bits, int weight_bits) {
  double sum = 0;
  int n = 0;
  for (const WboitRow& r : rows)
    if (r.method == "wboit" && r.format.acc_bits == acc_bits &&
        r.format.weight_bits == weight_bits)
      sum += r.error.delta_e_mean, ++n;
  return n ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

int wboit_best_weight(const std::vector<WboitRow>& rows, int acc_bits) {
  int best = -1;
  double least = std::numeric_limits<double>::infinity();
  for (const WboitRow& r : rows) {
    if (r.method != "wboit" || r.format.acc_bits != acc_bits) continue;
    const double e = wboit_mean_error(rows, acc_bits, r.format.weight_bits);
    if (e < least || (e == least && r.format.weight_bits < best))
      least = e, best = r.format.weight_bits;
  }
  return best;
}

}  // namespace zb::lab
