// Helpers for building scenes in code: the built-in scenes (scenes.cpp) and the lab's scene
// suite (scene_suite.cpp).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "scene.h"

namespace zb::build {

constexpr float kPi = glm::pi<float>();

// Throws std::invalid_argument(what) unless ok.
void require(bool ok, const char* what);

uint32_t add_vertex(Mesh& m, glm::vec3 p, glm::vec3 n);
// Two triangles of the quad a-b-c-d, given counter-clockwise seen from its front.
void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d);
// Appends `src` to `dst` (indices rebased), transformed by `xf`.
void append(Mesh& dst, const Mesh& src, const glm::mat4& xf = glm::mat4(1.0f));

glm::mat4 translate(glm::vec3 t);
glm::mat4 rotate(float deg, glm::vec3 axis);
glm::mat4 scale(glm::vec3 s);

// Sets the camera's near and far planes tightly around the scene: the nearest and farthest
// vertex along the view direction, widened by 2% of the depth range (at least 0.01) each side,
// so that the depth buffer's precision is spent on the scene.
void fit_depth_range(Scene& s);

uint32_t add_material(Scene& s, const std::string& name, Rgba8 c);
void add_object(Scene& s, const std::string& name, Mesh mesh, uint32_t material, glm::mat4 xf);

// A saturated colour of hue `deg` (HSV with S = 0.85, V = 0.95) and the given alpha.
Rgba8 hue_color(float deg, uint8_t alpha);

// Seeded random numbers for generated scenes (splitmix64): the same seed gives the same scene
// on every platform, which std's distributions do not promise.
class SceneRng {
 public:
  explicit SceneRng(uint64_t seed) : state_(seed) {}
  uint64_t next();
  float uniform(float lo, float hi);  // in [lo, hi)
  glm::vec3 unit_vector();            // uniform on the unit sphere

 private:
  uint64_t state_;
};

}  // namespace zb::build
