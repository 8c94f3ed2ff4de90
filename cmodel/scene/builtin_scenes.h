// The registry of built-in scenes: their names, descriptions and builders (the scenes
// themselves are in builtin_scenes.cpp, failure_scenes.h and scene_suite.h).
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

}  // namespace zb
