// Scene: camera matrices (GL conventions) and counts.
#include "scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace zb {

// Right-handed view matrix: the camera looks from `eye` toward `at`, `up` is screen up.
glm::mat4 Camera::view() const { return glm::lookAtRH(eye, at, up); }

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
