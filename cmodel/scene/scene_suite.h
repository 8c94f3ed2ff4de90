// The lab's scene suite: scenes built to make transparency methods fail, one family each
// (docs/scenes.md "The suite"). Every suite scene is also a built-in scene (builtin_scene).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene.h"

namespace zb {

struct SuiteScene {
  std::string name;         // as given to --scene
  std::string family;       // e.g. "layers", "coplanar"; the lab charts one family per chart
  std::string description;
};

// The suite the lab runs by default, family by family: shells, layers, interpenetrating,
// non-convex, coplanar, particles, seam, hidden-line. `layers` appears at the layer counts and
// alphas below; layers_scene builds any of them.
const std::vector<SuiteScene>& scene_suite();
constexpr int kSuiteLayers[] = {1, 2, 4, 8, 16};
constexpr int kSuiteAlphaPercent[] = {10, 50, 90};

// A suite scene by name, including every `layers-N-aP` (N = 1..16 layers, P = alpha in percent,
// 1..99), or nothing.
std::optional<Scene> suite_scene(const std::string& name);

// N transparent quads of alpha `alpha` (0 < alpha < 1), each in its own colour, covering the
// same screen rectangle at evenly spaced depths in front of an opaque two-tone backdrop, and
// submitted near to far: every pixel of the rectangle sees exactly N layers.
Scene layers_scene(int layers, float alpha);
std::string layers_scene_name(int layers, float alpha);  // "layers-N-aP"

// Two opaque quads tilted 60 degrees, the blue one `separation` world units in front of the
// red one along their normal, submitted far first; near and far planes fixed at 1 and 100, so
// that where the depth buffer cannot tell them apart the red one shows through (z-fighting).
Scene two_layers_scene(float separation);

}  // namespace zb
