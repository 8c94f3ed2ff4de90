// Scene description: meshes, materials, object transforms and a camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "rop/fixed.h"

namespace zb {

struct Material {
  std::string name;
  Rgba8 color{255, 255, 255, 255};  // alpha < 255 means transparent
  bool transparent() const { return color.a < 255; }
};

// Indexed triangle mesh. Triangles wind counter-clockwise seen from their front side.
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;       // one per position
  std::vector<glm::uvec3> triangles;    // indices into positions
};

struct Object {
  std::string name;
  Mesh mesh;
  uint32_t material = 0;                // index into Scene::materials
  glm::mat4 transform{1.0f};            // object to world
};

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 at{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;
  float near = 0.1f;
  float far = 100.0f;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

struct Scene {
  std::string name;
  std::string description;
  std::vector<Material> materials;
  std::vector<Object> objects;
  Camera camera;
  Rgba8 background{255, 255, 255, 255};
  std::vector<std::string> warnings;    // what the loader read but could not use, one line each

  size_t triangle_count() const;
};

}  // namespace zb
