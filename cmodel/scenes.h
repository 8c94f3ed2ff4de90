// The built-in scenes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene.h"

namespace zb {

struct SceneInfo {
  std::string name;
  std::string description;
};

// Names and one-line descriptions of the built-in scenes, default first.
const std::vector<SceneInfo>& builtin_scenes();

// The built-in scene called `name`, or nothing.
std::optional<Scene> builtin_scene(const std::string& name);

// Mesh builders, in object space, counter-clockwise outside.
Mesh make_quad(float half_w, float half_h);                    // in z = 0, facing +z
Mesh make_box(glm::vec3 half_extent);
Mesh make_sphere(float radius, int slices, int stacks);
Mesh make_torus(float major_r, float minor_r, int major_seg, int minor_seg);

}  // namespace zb
