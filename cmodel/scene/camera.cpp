// The camera (docs/scenes.md): fitted to the scene's bounds, or aimed where the user says.
#include "camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

#include "io/internal/text.h"

namespace zb {

namespace {

// Calls f(world position) for every vertex whose world position is finite, in double: sums and
// differences of far-apart float coordinates would overflow in float.
template <typename F>
void for_each_world_vertex(const Scene& scene, F&& f) {
  for (const Object& o : scene.objects)
    for (const glm::vec3& p : o.mesh.positions) {
      const glm::vec3 w = glm::vec3(o.transform * glm::vec4(p, 1.0f));
      if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) f(glm::dvec3(w));
    }
}

// Centre and radius of the bounding sphere (the axis-aligned box's centre and half diagonal)
// of every world-space vertex; radius 1 for a single point.
void bounding_sphere(const Scene& scene, glm::dvec3& centre, double& radius) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for_each_world_vertex(scene, [&](const glm::dvec3& w) {
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  });
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
  centre = (lo + hi) * 0.5;
  radius = glm::length(hi - lo) * 0.5;
  if (!(radius > 0.0)) radius = 1.0;
}

constexpr double kFitFovDeg = 45.0;
constexpr double kDepthMargin = 1.01;  // fitted near and far: the sphere widened by 1% of its radius
constexpr double kMaxFar = 1e37;       // far plane at most here, so that far + near stays a float
constexpr double kMinUpSine = 1e-3;    // a user's up at least this far from the view direction

// Sets near and far so that the float projection (glm::perspectiveRH_NO: (far + near) and
// 2 * far * near) stays finite: far at most kMaxFar, near lowered when far * near is too big.
void set_depth_range(Camera& cam, double near, double far) {
  far = std::min(far, kMaxFar);
  if (near >= far) near = 0.5 * far;  // everything beyond kMaxFar
  near = std::min(near, static_cast<double>(std::numeric_limits<float>::max()) / (4.0 * far));
  cam.near = static_cast<float>(near);
  cam.far = static_cast<float>(far);
}

// Throws unless `up` is usable with the unit view direction `fwd`.
void check_up(const glm::vec3& up, const glm::dvec3& fwd) {
  const glm::dvec3 u(up);
  const double len = glm::length(u);
  if (!(len > 0.0)) throw std::invalid_argument("field 'up' is the zero vector");
  if (!(glm::length(glm::cross(fwd, u / len)) >= kMinUpSine))
    throw std::invalid_argument("'up' is parallel to the view direction (eye to at)");
}

}  // namespace

void fit_camera(Scene& scene) {
  glm::dvec3 c;
  double r = 0;
  bounding_sphere(scene, c, r);
  const double d = r / std::sin(glm::radians(kFitFovDeg * 0.5));
  Camera& cam = scene.camera;
  cam.eye = glm::vec3(c + glm::dvec3(0.0, 0.0, d));
  cam.at = glm::vec3(c);
  cam.up = {0.0f, 1.0f, 0.0f};
  cam.fov_y_deg = static_cast<float>(kFitFovDeg);
  set_depth_range(cam, d - kDepthMargin * r, d + kDepthMargin * r);
}

void aim_camera(Scene& scene, const CameraSpec& spec) {
  const glm::dvec3 eye(spec.eye), dir = glm::dvec3(spec.at) - eye;
  if (!(glm::length(dir) > 0.0)) throw std::invalid_argument("'eye' and 'at' are the same point");
  const glm::dvec3 fwd = glm::normalize(dir);
  glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (spec.up) {
    check_up(*spec.up, fwd);
    up = glm::vec3(glm::normalize(glm::dvec3(*spec.up)));
  } else if (glm::length(glm::cross(fwd, glm::dvec3(0.0, 1.0, 0.0))) < 1e-6) {
    up = {0.0f, 0.0f, -1.0f};
  }
  // Near and far: the vertices' distances along the view direction, padded by 1% of their
  // range and 0.1% of the farthest (a flat scene seen face-on has no range).
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for_each_world_vertex(scene, [&](const glm::dvec3& w) {
    const double t = glm::dot(w - eye, fwd);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  });
  if (!(hi > 0.0)) throw std::invalid_argument("the whole scene lies behind the eye");
  const double pad = 0.01 * (hi - lo) + 0.001 * hi;
  const double far = hi + pad;
  Camera& cam = scene.camera;
  cam.eye = spec.eye;
  cam.at = spec.at;
  cam.up = up;
  cam.fov_y_deg = spec.fov_y_deg;
  set_depth_range(cam, std::max(lo - pad, far * 1e-4), far);
}

CameraSpec parse_camera_spec(const std::string& spec_text) {
  // Fields start at tokens holding '='; the tokens after one, up to the next, are its numbers.
  std::map<std::string, std::vector<std::string>> fields;
  std::string current;
  for (const std::string& tok : text::split(spec_text, ',')) {
    if (const size_t eq = tok.find('='); eq != std::string::npos) {
      current = tok.substr(0, eq);
      if (current != "eye" && current != "at" && current != "fov" && current != "up")
        throw std::invalid_argument(fmt::format("unknown field '{}' (expected eye, at, fov, up)", current));
      if (fields.count(current)) throw std::invalid_argument(fmt::format("field '{}' given twice", current));
      fields[current].push_back(tok.substr(eq + 1));
    } else if (current.empty()) {
      throw std::invalid_argument(
          fmt::format("'{}' is not a field (expected eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z])", tok));
    } else {
      fields[current].push_back(tok);
    }
  }
  auto numbers = [&](const std::string& name, size_t n) {
    const auto it = fields.find(name);
    if (it == fields.end()) throw std::invalid_argument(fmt::format("field '{}' is missing", name));
    if (it->second.size() != n)
      throw std::invalid_argument(fmt::format("field '{}' needs {} number{}, has {}", name, n,
                                              n > 1 ? "s" : "", it->second.size()));
    std::vector<float> out;
    for (const std::string& s : it->second) {
      double v = 0;
      if (!text::parse_number(s, v) || !std::isfinite(static_cast<float>(v)))
        throw std::invalid_argument(fmt::format("field '{}': '{}' is not a finite number", name, s));
      out.push_back(static_cast<float>(v));
    }
    return out;
  };
  CameraSpec spec;
  const std::vector<float> eye = numbers("eye", 3), at = numbers("at", 3), fov = numbers("fov", 1);
  spec.eye = {eye[0], eye[1], eye[2]};
  spec.at = {at[0], at[1], at[2]};
  spec.fov_y_deg = fov[0];
  if (!(fov[0] >= 1.0f && fov[0] <= 179.0f))
    throw std::invalid_argument(fmt::format("field 'fov': {} is out of range (1 to 179)", fov[0]));
  if (spec.eye == spec.at) throw std::invalid_argument("'eye' and 'at' are the same point");
  if (fields.count("up")) {
    const std::vector<float> up = numbers("up", 3);
    spec.up = glm::vec3(up[0], up[1], up[2]);
    check_up(*spec.up, glm::normalize(glm::dvec3(spec.at) - glm::dvec3(spec.eye)));
  }
  return spec;
}

}  // namespace zb
