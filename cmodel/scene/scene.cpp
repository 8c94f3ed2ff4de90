// Scene: camera matrices (GL conventions) and counts.
#include "scene.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace zb {

// Right-handed view matrix: the camera looks from `eye` toward `at`, `up` is screen up.
glm::mat4 Camera::view() const {
  // lookAt normalizes at - eye in float, whose squared length overflows beyond about 1.8e19.
  // Such a direction is scaled down by a power of two first (exact), and the translation
  // applied on its own; ordinary cameras keep lookAt's bits.
  const glm::vec3 d = at - eye;
  const float longest = std::fmax(std::fabs(d.x), std::fmax(std::fabs(d.y), std::fabs(d.z)));
  if (!(longest > 0x1p60f) || !std::isfinite(longest)) return glm::lookAtRH(eye, at, up);
  const glm::vec3 unit = d * std::ldexp(1.0f, -std::ilogb(longest));
  return glm::lookAtRH(glm::vec3(0.0f), unit, up) * glm::translate(glm::mat4(1.0f), -eye);
}

// GL perspective: right-handed eye space, clip z in [-w, w] (near maps to -1, far to +1).
glm::mat4 Camera::projection(float aspect) const {
  return glm::perspectiveRH_NO(glm::radians(fov_y_deg), aspect, near, far);
}

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const Object& o : objects) n += o.mesh.triangles.size();
  return n;
}

}  // namespace zb
