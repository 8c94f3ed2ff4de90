// The coverage-samples sweep: coverage-aa at 1 to 16 samples per pixel against the
// supersampled reference, on a scene with shared edges and on one without.
#include <cmath>
#include <stdexcept>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "scene/scene_build.h"
#include "sweeps.h"

namespace zb::lab {

Scene separate_triangles_scene() {
  using namespace build;
  Scene s;
  s.name = "separate-triangles";
  s.description = "eight opaque triangles apart from each other: edges without seams";
  s.camera.eye = {0.0f, 0.0f, 10.0f};
  s.camera.fov_y_deg = 45.0f;
  // Each triangle turned by its own angle, so that its edges take many slopes.
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 centre{-3.0f + 2.0f * float(k % 4), k < 4 ? 1.4f : -1.4f, 0.0f};
    const float turn = 17.0f + 41.0f * float(k);
    Mesh m;
    const glm::vec3 n{0.0f, 0.0f, 1.0f};
    add_vertex(m, {-0.8f, -0.6f, 0.0f}, n);
    add_vertex(m, {0.8f, -0.3f, 0.0f}, n);
    add_vertex(m, {-0.1f, 0.8f, 0.0f}, n);
    m.triangles.emplace_back(0u, 1u, 2u);
    const uint8_t c = static_cast<uint8_t>(40 + 25 * k);
    const uint32_t mat =
        add_material(s, fmt::format("tri{}", k), Rgba8{c, uint8_t(220 - c), 90, 255});
    add_object(s, fmt::format("tri{}", k), std::move(m), mat,
               translate(centre) * rotate(turn, {0.0f, 0.0f, 1.0f}));
  }
  fit_depth_range(s);
  return s;
}

namespace {

void sweep_scene(const Scene& scene, const SamplesOptions& o, const SweepProgress& progress,
                 std::vector<MethodRow>& rows) {
  const Scene s = o.opaque_only ? opaque_only(scene) : scene;
  // The ground truth does not depend on the sample count.
  const Framebuffer truth = render_reference_supersampled(s, o.viewport, o.supersample);
  for (size_t i = 0; i < o.samples.size(); ++i) {
    Viewport vp = o.viewport;
    vp.coverage_samples = o.samples[i];
    const RasterizedScene rs = rasterize_scene(s, vp);
    std::string note;
    for (const std::string& m : o.methods) {
      MethodRow r{double(o.samples[i]), scene.name, m, compare_images(render_method(rs, m), truth)};
      note += fmt::format(", {} RMSE {:.2f}", m, r.error.rmse);
      rows.push_back(std::move(r));
    }
    if (progress)
      progress(fmt::format("samples: {} {}/{}, {} samples{}", scene.name, i + 1,
                           o.samples.size(), o.samples[i], note));
  }
}

}  // namespace

std::vector<MethodRow> samples_sweep(const Scene& scene, const SamplesOptions& o,
                                     const SweepProgress& progress) {
  for (const int n : o.samples)
    if (!valid_coverage_samples(n))
      throw std::invalid_argument(fmt::format("samples_sweep: {} samples (1, 2, 4, 8 or 16)", n));
  std::vector<MethodRow> rows;
  sweep_scene(scene, o, progress, rows);
  sweep_scene(separate_triangles_scene(), o, progress, rows);
  return rows;
}

}  // namespace zb::lab
