// Scenes built to make one kind of method fail: the lab suite's families beyond `layers`
// (scene_suite.h). Each is also a built-in scene (scenes.h); docs/scenes.md "The suite".
#pragma once

#include "scene.h"

namespace zb {

// interpenetrating: three transparent quads through one point, each tilted another way, so
// that each pair's depth order swaps along their line of intersection.
Scene crossing_quads_scene();

// non-convex: a transparent torus seen 14 degrees above its plane, near arc submitted first:
// across the hole's middle a ray crosses the tube twice, four layers, two of them front faces.
Scene glass_torus_scene();

// coplanar: the same triangles twice in different colours, an opaque pair and a transparent
// pair, and a transparent decal made of the wall's own centre cell, submitted before the wall.
Scene coplanar_scene();

// particles: a seeded cloud of small transparent tetrahedra, dense at the centre.
Scene particles_scene();
constexpr int kParticleCount = 600;

// seam: a finely tessellated opaque sphere over a black backdrop (coverage-aa's shared edges).
Scene seam_scene();

}  // namespace zb
