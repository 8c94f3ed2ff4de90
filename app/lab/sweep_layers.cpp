// The layer-count and alpha sweeps: layers_scene as one of its two parameters moves.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "scene/scene_suite.h"
#include "sweeps.h"

namespace zb::lab {

namespace {

// Every method on `scene` against the reference, as rows at `x`. Returns the worst RMSE's
// method and value through `note`, for progress.
std::vector<MethodRow> every_method(const Scene& scene, const Viewport& vp,
                                    const std::vector<std::string>& methods, double x,
                                    std::string& note) {
  const RasterizedScene rs = rasterize_scene(scene, vp);
  const Framebuffer ref = render_reference(rs);
  std::vector<MethodRow> rows;
  double worst = -1;
  for (const std::string& m : methods) {
    const Framebuffer image = m == kReferenceMethod ? ref : render_method(rs, m);
    MethodRow r{x, scene.name, m, compare_images(image, ref)};
    if (r.error.rmse > worst) {
      worst = r.error.rmse;
      note = fmt::format("largest RMSE {} {:.2f}", m, worst);
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace

std::vector<MethodRow> layers_sweep(const LayersOptions& o, const SweepProgress& progress) {
  if (o.max_layers < 1 || o.max_layers > 16)
    throw std::invalid_argument("layers_sweep: 1 to 16 layers");
  const std::vector<std::string> methods = methods_or_all(o.methods);
  std::vector<MethodRow> rows;
  for (int n = 1; n <= o.max_layers; ++n) {
    std::string note;
    for (MethodRow& r : every_method(layers_scene(n, o.alpha), o.viewport, methods, n, note))
      rows.push_back(std::move(r));
    if (progress) progress(fmt::format("layers: {}/{} layers, {}", n, o.max_layers, note));
  }
  return rows;
}

std::vector<MethodRow> order_sweep(const OrderOptions& o, const SweepProgress& progress) {
  if (o.max_layers < 1 || o.max_layers > 16)
    throw std::invalid_argument("order_sweep: 1 to 16 layers");
  std::vector<MethodRow> rows;
  for (int n = 1; n <= o.max_layers; ++n) {
    const Scene near_first = layers_scene(n, o.alpha);  // two backdrop objects, then the layers
    for (const char* order : {"near first", "far first", "shuffled"}) {
      Scene s = near_first;
      const auto layers = s.objects.begin() + 2;
      if (order[0] == 'f') std::reverse(layers, s.objects.end());
      if (order[0] == 's') {
        std::mt19937_64 rng(o.seed * 1000 + uint64_t(n));
        std::shuffle(layers, s.objects.end(), rng);
      }
      std::string note;
      for (MethodRow& r : every_method(s, o.viewport, o.methods, n, note)) {
        r.method += fmt::format(" ({})", order);
        rows.push_back(std::move(r));
      }
    }
    if (progress) progress(fmt::format("order: {}/{} layers", n, o.max_layers));
  }
  return rows;
}

std::vector<MethodRow> alpha_sweep(const AlphaOptions& o, const SweepProgress& progress) {
  std::vector<float> alphas = o.alphas;
  if (alphas.empty())
    for (int k = 1; k <= 19; ++k) alphas.push_back(0.05f * float(k));
  const std::vector<std::string> methods = methods_or_all(o.methods);
  std::vector<MethodRow> rows;
  for (size_t i = 0; i < alphas.size(); ++i) {
    std::string note;
    for (MethodRow& r :
         every_method(layers_scene(o.layers, alphas[i]), o.viewport, methods, alphas[i], note))
      rows.push_back(std::move(r));
    if (progress)
      progress(fmt::format("alpha: {}/{} alpha {:.2f}, {}", i + 1, alphas.size(), alphas[i], note));
  }
  return rows;
}

}  // namespace zb::lab
