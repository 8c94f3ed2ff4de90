#include "scene_build.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace zb::build {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

uint32_t add_vertex(Mesh& m, glm::vec3 p, glm::vec3 n) {
  m.positions.push_back(p);
  m.normals.push_back(glm::normalize(n));
  return static_cast<uint32_t>(m.positions.size() - 1);
}

void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  m.triangles.emplace_back(a, b, c);
  m.triangles.emplace_back(a, c, d);
}

void append(Mesh& dst, const Mesh& src, const glm::mat4& xf) {
  const auto base = static_cast<uint32_t>(dst.positions.size());
  const glm::mat3 nxf = glm::transpose(glm::inverse(glm::mat3(xf)));
  for (size_t i = 0; i < src.positions.size(); ++i) {
    dst.positions.push_back(glm::vec3(xf * glm::vec4(src.positions[i], 1.0f)));
    dst.normals.push_back(glm::normalize(nxf * src.normals[i]));
  }
  for (const glm::uvec3& t : src.triangles) dst.triangles.push_back(t + glm::uvec3(base));
}

glm::mat4 translate(glm::vec3 t) { return glm::translate(glm::mat4(1.0f), t); }
glm::mat4 rotate(float deg, glm::vec3 axis) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(deg), axis);
}
glm::mat4 scale(glm::vec3 s) { return glm::scale(glm::mat4(1.0f), s); }

void fit_depth_range(Scene& s) {
  const glm::vec3 fwd = glm::normalize(s.camera.at - s.camera.eye);
  float lo = std::numeric_limits<float>::max();
  float hi = std::numeric_limits<float>::lowest();
  for (const Object& o : s.objects) {
    for (const glm::vec3& p : o.mesh.positions) {
      const glm::vec3 w = glm::vec3(o.transform * glm::vec4(p, 1.0f));
      const float d = glm::dot(w - s.camera.eye, fwd);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  const float margin = std::max(0.01f, 0.02f * (hi - lo));
  s.camera.near = std::max(0.01f, lo - margin);
  s.camera.far = hi + margin;
}

uint32_t add_material(Scene& s, const std::string& name, Rgba8 c) {
  s.materials.push_back(Material{name, c});
  return static_cast<uint32_t>(s.materials.size() - 1);
}

void add_object(Scene& s, const std::string& name, Mesh mesh, uint32_t material, glm::mat4 xf) {
  s.objects.push_back(Object{name, std::move(mesh), material, xf});
}

Rgba8 hue_color(float deg, uint8_t alpha) {
  const float h = std::fmod(deg, 360.0f) / 60.0f;
  const float c = 0.95f * 0.85f, m = 0.95f - c;
  const float x = c * (1.0f - std::fabs(std::fmod(h, 2.0f) - 1.0f));
  float r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = c; g = x; break;
    case 1: r = x; g = c; break;
    case 2: g = c; b = x; break;
    case 3: g = x; b = c; break;
    case 4: r = x; b = c; break;
    default: r = c; b = x; break;
  }
  auto u8 = [](float v) { return static_cast<uint8_t>(std::lround(255.0f * v)); };
  return Rgba8{u8(r + m), u8(g + m), u8(b + m), alpha};
}

uint64_t SceneRng::next() {
  uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

float SceneRng::uniform(float lo, float hi) {
  // 24 random bits: exact in a float, so the result is the same wherever it runs.
  const float u = static_cast<float>(next() >> 40) / 16777216.0f;
  return lo + (hi - lo) * u;
}

glm::vec3 SceneRng::unit_vector() {
  const float z = uniform(-1.0f, 1.0f);
  const float phi = uniform(0.0f, 2.0f * kPi);
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace zb::build
