// The lab's scene suite (scene_suite.h).
#include "scene_suite.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "scene_build.h"
#include "builtin_scenes.h"
#include "meshes.h"

namespace zb {

using namespace build;

std::string layers_scene_name(int layers, float alpha) {
  return fmt::format("layers-{}-a{}", layers, static_cast<int>(std::lround(alpha * 100.0f)));
}

Scene layers_scene(int layers, float alpha) {
  require(layers >= 1 && layers <= 16, "layers_scene: 1 to 16 layers");
  require(alpha > 0.0f && alpha < 1.0f, "layers_scene: alpha in (0, 1)");
  Scene s;
  s.name = layers_scene_name(layers, alpha);
  s.description = fmt::format("{} transparent layers of alpha {:.2f} over a two-tone backdrop, "
                              "submitted near to far", layers, alpha);
  constexpr float kEyeZ = 10.0f;
  s.camera.eye = {0.0f, 0.0f, kEyeZ};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 30.0f;

  // Backdrop at z = -1.5: light on the left, dark on the right, so that every layer's error
  // shows against both.
  const uint32_t light = add_material(s, "backdrop_light", Rgba8{225, 225, 225, 255});
  const uint32_t dark = add_material(s, "backdrop_dark", Rgba8{40, 40, 40, 255});
  add_object(s, "backdrop_light", make_quad(2.0f, 3.0f), light, translate({-2.0f, 0.0f, -1.5f}));
  add_object(s, "backdrop_dark", make_quad(2.0f, 3.0f), dark, translate({2.0f, 0.0f, -1.5f}));

  // Layer k at z = 1 - k / 15 (near to far over [-0.067 .. 1]), scaled about the eye so that
  // each covers the same screen rectangle as a 3.6 x 2.6 quad on the plane z = 0.
  const auto a8 = static_cast<uint8_t>(std::lround(alpha * 255.0f));
  for (int k = 0; k < layers; ++k) {
    const float z = 1.0f - float(k) / 15.0f;
    const float grow = (kEyeZ - z) / kEyeZ;
    const uint32_t mat = add_material(s, fmt::format("layer{}", k), hue_color(137.5f * k, a8));
    add_object(s, fmt::format("layer{}", k), make_quad(1.8f * grow, 1.3f * grow), mat,
               translate({0.0f, 0.0f, z}));
  }
  fit_depth_range(s);
  return s;
}

Scene two_layers_scene(float separation) {
  require(separation >= 0.0f, "two_layers_scene: separation >= 0");
  Scene s;
  s.name = fmt::format("two-layers-{}", separation);
  s.description = "two opaque tilted quads, the near one submitted second";
  s.camera.eye = {0.0f, 0.0f, 10.0f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 30.0f;
  s.camera.near = 1.0f;
  s.camera.far = 100.0f;
  const uint32_t red = add_material(s, "far_red", Rgba8{220, 40, 40, 255});
  const uint32_t blue = add_material(s, "near_blue", Rgba8{40, 80, 220, 255});
  const glm::mat4 tilt = rotate(-60.0f, {1.0f, 0.0f, 0.0f});
  // The quad's normal is +z before the tilt: the blue one sits `separation` along it.
  add_object(s, "far_red", make_quad(1.6f, 2.4f), red, tilt);
  add_object(s, "near_blue", make_quad(1.2f, 2.0f), blue, tilt * translate({0, 0, separation}));
  return s;
}

namespace {

constexpr const char* kPartsBreaks =
    "breaks hidden-line: on plates tilted 0 to 89 degrees the edge offset must outrun a steep "
    "face's depth slope without lifting the thin plates' hidden edges through their faces";

// What a layers scene breaks: submitted near to far, one-pass blending reverses the order;
// depth-peel-K keeps only the nearest K.
std::string layers_breaks(int n, int percent) {
  const std::string what = fmt::format("{} transparent layer{} of alpha {:.2f} over a two-tone "
                                       "backdrop", n, n == 1 ? "" : "s", percent / 100.0);
  if (n == 1)
    return "the control: " + what + ", which unsorted, back-front and depth peeling get right";
  std::string peels;
  for (const int k : kDepthPeelLayers)
    if (k < n) peels += fmt::format("{}{}", peels.empty() ? "" : "/", k);
  return fmt::format("breaks unsorted and back-front{}: {}, submitted near to far",
                     peels.empty() ? "" : ", depth-peel-" + peels, what);
}

}  // namespace

const std::vector<SuiteScene>& scene_suite() {
  static const std::vector<SuiteScene> kSuite = [] {
    std::vector<SuiteScene> v;
    v.push_back({"cad", "shells",
                 "breaks one-pass blending, three-pass, depth-peel-2: two nested transparent "
                 "shells around an opaque part, submitted outer first, up to 4 layers"});
    for (const int n : kSuiteLayers)
      for (const int p : kSuiteAlphaPercent)
        v.push_back({layers_scene_name(n, float(p) / 100.0f), "layers", layers_breaks(n, p)});
    // The rest are built-in scenes (scenes.cpp), described there.
    for (const auto& [name, family] : {std::pair{"crossing-quads", "interpenetrating"},
                                       {"glass-torus", "non-convex"},
                                       {"coplanar", "coplanar"},
                                       {"particles", "particles"},
                                       {"seam", "seam"}})
      for (const SceneInfo& b : builtin_scenes())
        if (b.name == name) v.push_back({name, family, b.description});
    v.push_back({"parts", "hidden-line", kPartsBreaks});
    return v;
  }();
  return kSuite;
}

std::optional<Scene> suite_scene(const std::string& name) {
  int n = 0, p = 0, used = 0;
  if (std::sscanf(name.c_str(), "layers-%d-a%d%n", &n, &p, &used) == 2 &&
      used == static_cast<int>(name.size()) && n >= 1 && n <= 16 && p >= 1 && p <= 99 &&
      name == layers_scene_name(n, float(p) / 100.0f))
    return layers_scene(n, float(p) / 100.0f);
  // Every other suite scene is a built-in; asking builtin_scene only for names it lists keeps
  // its fallback to this function from coming back here.
  for (const SuiteScene& e : scene_suite()) {
    if (e.name != name) continue;
    for (const SceneInfo& b : builtin_scenes())
      if (b.name == name) return builtin_scene(name);
  }
  return std::nullopt;
}

}  // namespace zb
