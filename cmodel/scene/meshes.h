// Mesh builders, for the built-in scenes and for tests.
#pragma once

#include <glm/glm.hpp>

#include "scene.h"

namespace zb {

// Mesh builders, in object space, counter-clockwise outside.
Mesh make_quad(float half_w, float half_h);                    // in z = 0, facing +z
Mesh make_box(glm::vec3 half_extent);
Mesh make_sphere(float radius, int slices, int stacks);
Mesh make_torus(float major_r, float minor_r, int major_seg, int minor_seg);
// A regular tetrahedron about the origin, corners at distance `radius`; flat normals.
Mesh make_tetrahedron(float radius);
// make_box with every face cut into cells x cells squares: a sub-mesh built from the same cells
// (make_box_face_cells) has bit-identical vertices, hence exactly the face's depths.
Mesh make_grid_box(glm::vec3 half_extent, int cells);
// The cells [i0, i1) x [j0, j1) of make_grid_box's face +z (i along +x, j along +y).
Mesh make_box_face_cells(glm::vec3 half_extent, int cells, int i0, int i1, int j0, int j1);

}  // namespace zb
