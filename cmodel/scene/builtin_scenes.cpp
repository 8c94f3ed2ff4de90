// The built-in scenes and their registry.
//
// Every scene is chosen to make some transparency method fail (docs/scenes.md, "The suite"):
// transparent objects are never submitted back to front, and closed transparent shells show
// their back faces through their front faces.
#include "builtin_scenes.h"

#include "failure_scenes.h"
#include "meshes.h"
#include "scene_build.h"
#include "scene_suite.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace zb {

using namespace build;

namespace {

// The CAD use case of US 7,834,879: an opaque part inside two nested transparent shells.
// Submitted outer shell, inner shell, part: front to back, the worst order for one-pass blending.
Scene cad_scene() {
  Scene s;
  const uint32_t part = add_material(s, "part", Rgba8{70, 80, 110, 255});             // blue-grey
  const uint32_t inner = add_material(s, "inner_shell", Rgba8{255, 170, 0, 128});     // amber
  const uint32_t outer = add_material(s, "outer_shell", Rgba8{0, 190, 220, 77});      // cyan

  // Outer shell: a box of half extent (1.5, 1.3, 1.5), turned 20 degrees about y.
  add_object(s, "outer_shell", make_box({1.5f, 1.3f, 1.5f}), outer, rotate(20.0f, {0, 1, 0}));
  // Inner shell: a sphere of radius 1.1 (inside the outer box whatever its turn).
  add_object(s, "inner_shell", make_sphere(1.1f, 32, 16), inner, glm::mat4(1.0f));
  // The part: a block of half extent (0.7, 0.25, 0.4) with a ball of radius 0.35 on top
  // (two closed surfaces in one mesh), turned -30 degrees about y; inside the inner sphere.
  Mesh body = make_box({0.7f, 0.25f, 0.4f});
  append(body, make_sphere(0.35f, 16, 8), translate({0.2f, 0.3f, 0.0f}));
  add_object(s, "part", std::move(body), part, rotate(-30.0f, {0, 1, 0}));

  s.camera.eye = {4.5f, 3.5f, 5.5f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  fit_depth_range(s);
  return s;
}

// Three transparent quads facing the camera, on each half of the frame, in opposite submit
// orders, over one opaque backdrop. The camera looks straight down -z from z = 8, so every quad
// has one constant depth (world z; eye distance 8 - z):
//   A (near)   z = +1.0   red   (230, 30, 30, 128)
//   B (middle) z =  0.0   green (30, 200, 60, 100)
//   C (far)    z = -1.0   blue  (30, 70, 230, 200)
//   backdrop   z = -2.0   grey  (110, 110, 110, 255), opaque
// Left half (x < 0): A, B, C submitted near to far. Right half (x > 0): C, B, A, far to near.
// Each quad is laid out on the plane z = 0 (half size 0.8, centred at its group's centre
// x = -+2.2 plus its offset) and then scaled about the eye onto its own depth, so that it
// covers the same screen rectangle at every depth: the two halves are the same picture, with
// regions of 1, 2 and 3 transparent layers, and differ only in submit order.
Scene quads_scene() {
  Scene s;
  const uint32_t grey = add_material(s, "backdrop", Rgba8{110, 110, 110, 255});
  const uint32_t red = add_material(s, "A_red", Rgba8{230, 30, 30, 128});
  const uint32_t green = add_material(s, "B_green", Rgba8{30, 200, 60, 100});
  const uint32_t blue = add_material(s, "C_blue", Rgba8{30, 70, 230, 200});

  constexpr float kEyeZ = 8.0f;
  constexpr float kZa = 1.0f, kZb = 0.0f, kZc = -1.0f, kZbackdrop = -2.0f;
  constexpr float kHalf = 0.8f;   // half size on the plane z = 0
  constexpr float kSideX = 2.2f;  // centre of each half's group on the plane z = 0
  // Offsets of A, B, C within a group, on the plane z = 0: overlapping like a Venn diagram.
  const glm::vec2 oa{-0.4f, 0.3f}, ob{0.4f, 0.3f}, oc{0.0f, -0.35f};

  add_object(s, "backdrop", make_quad(4.8f, 2.0f), grey, translate({0.0f, 0.0f, kZbackdrop}));
  auto quad = [&](const char* name, uint32_t mat, float side, glm::vec2 o, float z) {
    const float k = (kEyeZ - z) / kEyeZ;  // scale about the eye from z = 0 to depth z
    add_object(s, name, make_quad(k * kHalf, k * kHalf), mat,
               translate({k * (side + o.x), k * o.y, z}));
  };
  quad("A_left", red, -kSideX, oa, kZa);
  quad("B_left", green, -kSideX, ob, kZb);
  quad("C_left", blue, -kSideX, oc, kZc);
  quad("C_right", blue, kSideX, oc, kZc);
  quad("B_right", green, kSideX, ob, kZb);
  quad("A_right", red, kSideX, oa, kZa);

  s.camera.eye = {0.0f, 0.0f, kEyeZ};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  fit_depth_range(s);
  return s;
}

// A convex transparent sphere and a non-convex transparent torus over an opaque ground slab.
// The torus (radii 1.0 and 0.35) is tilted so that the camera sees its ring at about 25
// degrees: the hole shows, and near the ends of the ring its near and far arcs overlap on
// screen (four layers of one object). Its left end overlaps the sphere on screen (up to six
// transparent layers); the two do not intersect. Submitted sphere (in front) before torus.
Scene sphere_torus_scene() {
  Scene s;
  const uint32_t ground = add_material(s, "ground", Rgba8{150, 140, 120, 255});
  const uint32_t sphere = add_material(s, "sphere", Rgba8{220, 50, 90, 128});  // rose
  const uint32_t torus = add_material(s, "torus", Rgba8{40, 190, 110, 128});   // green

  add_object(s, "ground", make_box({2.6f, 0.1f, 2.0f}), ground, translate({0.0f, -1.6f, 0.0f}));
  add_object(s, "sphere", make_sphere(0.9f, 32, 16), sphere, translate({-0.9f, -0.4f, 0.6f}));
  add_object(s, "torus", make_torus(1.0f, 0.35f, 48, 24), torus,
             translate({0.8f, -0.45f, -1.0f}) * rotate(25.0f, {0, 0, 1}) * rotate(5.0f, {1, 0, 0}));

  s.camera.eye = {0.0f, 2.2f, 6.5f};
  s.camera.at = {0.0f, -0.4f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  fit_depth_range(s);
  return s;
}

// Opaque solid parts for hidden-line (US 5,359,704). Top row: four square plates (boxes of
// half size 0.8 x 0.8 x 0.06) whose large face is tilted 0, 60, 85 and 89 degrees away from
// the direction to the eye (measured at the plate's centre, about a horizontal axis), left to
// right: the faces an edge offset must keep their edges visible on. Bottom row: a turned block
// in front of a taller one (hidden edges), and a transparent ball around an opaque cube (the
// catalogue asks every scene for both kinds).
Scene parts_scene() {
  Scene s;
  const uint32_t steel = add_material(s, "plate", Rgba8{120, 140, 170, 255});
  const uint32_t block = add_material(s, "block", Rgba8{170, 120, 80, 255});
  const uint32_t glass = add_material(s, "glass", Rgba8{120, 200, 230, 90});

  s.camera.eye = {0.0f, 0.0f, 10.0f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  const float tilts[4] = {0.0f, 60.0f, 85.0f, 89.0f};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 centre{-3.3f + 2.2f * static_cast<float>(i), 1.5f, 0.0f};
    // Basis: n is the direction to the eye turned by the tilt about the horizontal axis u.
    const glm::vec3 d = glm::normalize(s.camera.eye - centre);
    const glm::vec3 u = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), d));
    const glm::vec3 n = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(tilts[i]), u) *
                                  glm::vec4(d, 0.0f));
    const glm::vec3 v = glm::cross(n, u);
    glm::mat4 xf(1.0f);
    xf[0] = glm::vec4(u, 0.0f);
    xf[1] = glm::vec4(v, 0.0f);
    xf[2] = glm::vec4(n, 0.0f);
    xf[3] = glm::vec4(centre, 1.0f);
    static const char* kNames[4] = {"plate_0", "plate_60", "plate_85", "plate_89"};
    add_object(s, kNames[i], make_box({0.8f, 0.8f, 0.06f}), steel, xf);
  }
  add_object(s, "block_back", make_box({0.7f, 1.0f, 0.5f}), block,
             translate({-1.5f, -1.5f, -1.2f}) * rotate(-15.0f, {0, 1, 0}));
  add_object(s, "block_front", make_box({1.0f, 0.5f, 0.6f}), block,
             translate({-2.4f, -1.8f, 0.6f}) * rotate(30.0f, {0, 1, 0}) * rotate(15.0f, {1, 0, 0}));
  add_object(s, "cube", make_box({0.35f, 0.35f, 0.35f}), block,
             translate({2.2f, -1.6f, 0.0f}) * rotate(35.0f, {0, 1, 0}) * rotate(25.0f, {1, 0, 0}));
  add_object(s, "glass_ball", make_sphere(0.9f, 24, 12), glass, translate({2.2f, -1.6f, 0.0f}));
  fit_depth_range(s);
  return s;
}

struct Builtin {
  SceneInfo info;
  Scene (*build)();
};

const std::vector<Builtin>& builtins() {
  static const std::vector<Builtin> kBuiltins = {
      {{"cad", "opaque part inside two nested transparent shells (amber sphere, cyan box), "
               "submitted outer to inner"},
       cad_scene},
      {{"quads", "three transparent quads at known depths, near-to-far on the left, "
                 "far-to-near on the right, over an opaque backdrop"},
       quads_scene},
      {{"sphere-torus", "transparent convex sphere and self-overlapping transparent torus "
                        "over an opaque ground slab"},
       sphere_torus_scene},
      {{"parts", "opaque solid parts for hidden-line: plates tilted 0, 60, 85 and 89 degrees to "
                 "the view, overlapping blocks, a cube in a transparent ball"},
       parts_scene},
      // The lab suite's own scenes (failure_scenes.h) and one of the layers family, so that
      // the testbench's scenes suite runs them through the RTL too.
      {{"crossing-quads", "breaks unsorted, three-pass, back-front, facing-additive: three "
                          "transparent quads cut through each other, so no submit order is right"},
       crossing_quads_scene},
      {{"glass-torus", "breaks back-front: a transparent torus seen 14 degrees above its plane is "
                       "4 layers deep, front faces of the far arc behind back faces of the near"},
       glass_torus_scene},
      {{"coplanar", "breaks coverage-aa and one-pass blending: boxes drawn twice in two colours "
                    "(opaque, transparent) and a decal, at equal depths that submit order decides"},
       coplanar_scene},
      {{"particles", "breaks depth-peel-2/4/8 and one-pass blending: 600 transparent tetrahedra "
                     "in random order, 40 or more layers at the centre"},
       particles_scene},
      {{"seam", "breaks coverage-aa: one coverage count per pixel lets the black backdrop leak "
                "through the shared edges of an opaque tessellated sphere"},
       seam_scene},
      {{"layers-16-a50", layers_scene(16, 0.5f).description},
       [] { return layers_scene(16, 0.5f); }},
  };
  return kBuiltins;
}

}  // namespace

const std::vector<SceneInfo>& builtin_scenes() {
  static const std::vector<SceneInfo> kInfos = [] {
    std::vector<SceneInfo> v;
    for (const Builtin& b : builtins()) v.push_back(b.info);
    return v;
  }();
  return kInfos;
}

std::optional<Scene> builtin_scene(const std::string& name) {
  for (const Builtin& b : builtins()) {
    if (b.info.name == name) {
      Scene s = b.build();
      s.name = b.info.name;
      s.description = b.info.description;
      return s;
    }
  }
  return suite_scene(name);
}

}  // namespace zb
