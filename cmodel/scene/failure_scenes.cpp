// The scenes built to make methods fail (failure_scenes.h). Every one has an opaque backdrop or
// part and at least one transparent object, as the built-in catalogue asks.
#include "failure_scenes.h"

#include <cmath>

#include <fmt/core.h>

#include "scene_build.h"
#include "meshes.h"

namespace zb {

using namespace build;

namespace {

// Two opaque quads side by side, light left and dark right, on the plane z = `z`: every
// transparent error shows against both.
void add_two_tone_backdrop(Scene& s, float half_w, float half_h, float z) {
  const uint32_t light = add_material(s, "backdrop_light", Rgba8{225, 225, 225, 255});
  const uint32_t dark = add_material(s, "backdrop_dark", Rgba8{40, 40, 40, 255});
  add_object(s, "backdrop_light", make_quad(half_w / 2, half_h), light,
             translate({-half_w / 2, 0.0f, z}));
  add_object(s, "backdrop_dark", make_quad(half_w / 2, half_h), dark,
             translate({half_w / 2, 0.0f, z}));
}

void look_down_z(Scene& s, float eye_z, float fov_y_deg) {
  s.camera.eye = {0.0f, 0.0f, eye_z};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = fov_y_deg;
}

}  // namespace

Scene crossing_quads_scene() {
  Scene s;
  look_down_z(s, 8.0f, 40.0f);
  add_two_tone_backdrop(s, 3.6f, 2.2f, -2.0f);
  // Through the origin: A turned +40 degrees about y (its right half recedes), B -40 (its left
  // half recedes), C 40 about x (its top comes forward). All three face the camera.
  const uint32_t a = add_material(s, "A_red", Rgba8{230, 40, 40, 128});
  const uint32_t b = add_material(s, "B_green", Rgba8{40, 190, 70, 128});
  const uint32_t c = add_material(s, "C_blue", Rgba8{40, 80, 230, 128});
  add_object(s, "A_red", make_quad(1.5f, 1.1f), a, rotate(40.0f, {0, 1, 0}));
  add_object(s, "B_green", make_quad(1.5f, 1.1f), b, rotate(-40.0f, {0, 1, 0}));
  add_object(s, "C_blue", make_quad(1.4f, 1.2f), c, rotate(40.0f, {1, 0, 0}));
  fit_depth_range(s);
  return s;
}

Scene glass_torus_scene() {
  Scene s;
  look_down_z(s, 7.0f, 35.0f);
  add_two_tone_backdrop(s, 3.6f, 1.6f, -2.0f);
  const uint32_t glass = add_material(s, "torus", Rgba8{60, 170, 230, 110});
  // make_torus starts its ring at +x and runs toward -z first (the far arc); turned 180 degrees
  // about y, the near arc comes first, the worst order for blending in submit order. Then the
  // ring is tipped 14 degrees toward the eye: the arcs' centre lines lie 2 x 1.2 x sin 14 = 0.58
  // apart on screen and the tube is 0.92 across, so they overlap, four layers deep.
  add_object(s, "torus", make_torus(1.2f, 0.46f, 48, 24), glass,
             rotate(14.0f, {1, 0, 0}) * rotate(180.0f, {0, 1, 0}));
  fit_depth_range(s);
  return s;
}

Scene coplanar_scene() {
  Scene s;
  s.camera.eye = {0.0f, 1.0f, 7.0f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 40.0f;
  // The wall: a slab whose faces are cut 3 x 3; the decal is its front face's centre cell, built
  // from the same vertices, so it has exactly the wall's depth there. It is submitted first: by
  // submit order (depth less, the reference's tie rule) it lies on top.
  constexpr glm::vec3 kWall{2.6f, 1.5f, 0.1f};
  constexpr int kCells = 3;
  const glm::mat4 wall_xf = translate({0.0f, 0.0f, -1.2f});
  const uint32_t decal = add_material(s, "decal", Rgba8{250, 200, 30, 160});
  const uint32_t wall = add_material(s, "wall", Rgba8{150, 150, 160, 255});
  add_object(s, "decal", make_box_face_cells(kWall, kCells, 1, 2, 1, 2), decal, wall_xf);
  add_object(s, "wall", make_grid_box(kWall, kCells), wall, wall_xf);
  // Two boxes drawn twice each, the same triangles in another colour: opaque on the left,
  // transparent on the right.
  const Mesh box = make_box({0.5f, 0.5f, 0.5f});
  const glm::mat4 turn = rotate(20.0f, {1, 0, 0}) * rotate(30.0f, {0, 1, 0});
  const glm::mat4 left = translate({-1.4f, 0.0f, 0.4f}) * turn;
  const glm::mat4 right = translate({1.4f, 0.0f, 0.4f}) * turn;
  add_object(s, "opaque_first", box, add_material(s, "opaque_red", Rgba8{210, 50, 40, 255}), left);
  add_object(s, "opaque_second", box, add_material(s, "opaque_green", Rgba8{40, 170, 60, 255}),
             left);
  add_object(s, "glass_first", box, add_material(s, "glass_cyan", Rgba8{0, 180, 220, 128}), right);
  add_object(s, "glass_second", box, add_material(s, "glass_magenta", Rgba8{220, 0, 160, 128}),
             right);
  fit_depth_range(s);
  return s;
}

Scene particles_scene() {
  Scene s;
  look_down_z(s, 6.0f, 40.0f);
  add_two_tone_backdrop(s, 3.0f, 1.8f, -1.6f);
  // Fixed seed. Radius 1.1 sqrt(u) (uniform in the ball would be the cube root) packs the
  // particles toward the centre, where a ray crosses about two dozen of them, each two layers
  // (its front and its back). One object per particle, in one of eight hues, so that colours
  // interleave in submit order.
  constexpr int kHues = 8;
  uint32_t hues[kHues];
  for (int h = 0; h < kHues; ++h)
    hues[h] = add_material(s, fmt::format("hue{}", h), hue_color(45.0f * float(h), 48));
  SceneRng rng(0x5eed0006u);
  const Mesh tet = make_tetrahedron(0.16f);
  for (int i = 0; i < kParticleCount; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    const glm::vec3 dir = rng.unit_vector();
    const glm::vec3 at = dir * (1.1f * std::pow(rng.uniform(0.0f, 1.0f), 0.5f));
    const float spin = rng.uniform(0.0f, 360.0f);
    const glm::vec3 axis = rng.unit_vector();
    const auto hue = static_cast<int>(rng.next() % kHues);
    add_object(s, fmt::format("particle{}", i), tet, hues[hue], translate(at) * rotate(spin, axis));
  }
  fit_depth_range(s);
  return s;
}

Scene seam_scene() {
  Scene s;
  look_down_z(s, 7.0f, 40.0f);
  const uint32_t black = add_material(s, "backdrop", Rgba8{15, 15, 20, 255});
  const uint32_t cream = add_material(s, "sphere", Rgba8{245, 235, 205, 255});
  const uint32_t glass = add_material(s, "pane", Rgba8{120, 200, 230, 90});
  add_object(s, "backdrop", make_quad(2.2f, 1.6f), black, translate({0.0f, 0.0f, -1.5f}));
  add_object(s, "sphere", make_sphere(1.1f, 40, 20), cream, rotate(20.0f, {1, 0, 0}));
  // Beside the sphere, not over it: only so that the scene has both kinds (the catalogue asks).
  add_object(s, "pane", make_quad(0.35f, 0.35f), glass, translate({2.0f, 1.3f, 0.0f}));
  fit_depth_range(s);
  return s;
}

}  // namespace zb
