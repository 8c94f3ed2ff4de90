// The orbit sweep: the camera goes once around the scene; how much each method pops.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "sweeps.h"

namespace zb::lab {

Camera orbit_camera(const Scene& scene, float deg) {
  Camera c = scene.camera;
  const glm::vec3 offset = c.eye - c.at;
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(deg), glm::normalize(c.up));
  c.eye = c.at + glm::vec3(turn * glm::vec4(offset, 0.0f));

  // The scene's own near and far fit its own view; another angle may see it deeper.
  float radius = 0.0f;
  for (const Object& o : scene.objects)
    for (const glm::vec3& p : o.mesh.positions)
      radius = std::max(radius, glm::length(glm::vec3(o.transform * glm::vec4(p, 1.0f)) - c.at));
  const float dist = glm::length(offset);
  const float margin = 0.02f * radius + 0.01f;
  c.near = std::min(c.near, std::max(0.01f, dist - radius - margin));
  c.far = std::max(c.far, dist + radius + margin);
  return c;
}

double popping_share(const Framebuffer& m0, const Framebuffer& m1, const Framebuffer& r0,
                     const Framebuffer& r1, int threshold) {
  const size_t n = m0.color.size();
  if (n == 0 || m1.color.size() != n || r0.color.size() != n || r1.color.size() != n)
    throw std::invalid_argument("popping_share: frames of different sizes");
  size_t popped = 0;
  for (size_t i = 0; i < n; ++i) {
    const Rgba8 a0 = m0.color[i], a1 = m1.color[i], b0 = r0.color[i], b1 = r1.color[i];
    auto pops = [&](int ma, int mb, int ra, int rb) {
      return std::abs(mb - ma) > std::abs(rb - ra) + threshold;
    };
    popped += pops(a0.r, a1.r, b0.r, b1.r) || pops(a0.g, a1.g, b0.g, b1.g) ||
              pops(a0.b, a1.b, b0.b, b1.b);
  }
  return double(popped) / double(n);
}

namespace {

// Every method's frame at one angle; the reference last.
std::vector<Framebuffer> frames_at(const Scene& scene, float deg, const Viewport& vp,
                                   const std::vector<std::string>& methods) {
  Scene s = scene;
  s.camera = orbit_camera(scene, deg);
  const RasterizedScene rs = rasterize_scene(s, vp);
  std::vector<Framebuffer> out;
  Framebuffer ref = render_reference(rs);
  for (const std::string& m : methods)
    out.push_back(m == kReferenceMethod ? ref : render_method(rs, m));
  out.push_back(std::move(ref));
  return out;
}

}  // namespace

std::vector<OrbitRow> orbit_sweep(const Scene& scene, const OrbitOptions& o,
                                  const SweepProgress& progress) {
  if (o.steps < 2) throw std::invalid_argument("orbit_sweep: at least 2 steps");
  const std::vector<std::string> methods = methods_or_all(o.methods);
  auto angle = [&](int step) { return 360.0 * step / o.steps; };

  // The orbit is closed: step 0 pops against the last step.
  const std::vector<Framebuffer> last =
      frames_at(scene, float(angle(o.steps - 1)), o.viewport, methods);
  std::vector<Framebuffer> prev = last;
  std::vector<OrbitRow> rows;
  for (int step = 0; step < o.steps; ++step) {
    std::vector<Framebuffer> cur =
        step == o.steps - 1 ? last : frames_at(scene, float(angle(step)), o.viewport, methods);
    const Framebuffer& ref0 = prev.back();
    const Framebuffer& ref1 = cur.back();
    double worst = 0;
    std::string worst_method;
    for (size_t m = 0; m < methods.size(); ++m) {
      OrbitRow r;
      r.step = step;
      r.angle_deg = angle(step);
      r.method = methods[m];
      r.popping = popping_share(prev[m], cur[m], ref0, ref1, o.threshold);
      r.error = compare_images(cur[m], ref1);
      if (r.popping > worst) worst = r.popping, worst_method = r.method;
      rows.push_back(std::move(r));
    }
    if (progress)
      progress(fmt::format("orbit: step {}/{} at {:.1f} deg{}", step + 1, o.steps, angle(step),
                           worst > 0 ? fmt::format(", most popping {} {:.2f}%", worst_method,
                                                   100 * worst)
                                     : std::string()));
    prev = std::move(cur);
  }
  return rows;
}

}  // namespace zb::lab
