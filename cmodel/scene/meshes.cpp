// The mesh builders of the built-in scenes (meshes.h).
#include "meshes.h"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/constants.hpp>

#include "scene_build.h"

namespace zb {

using namespace build;

Mesh make_quad(float half_w, float half_h) {
  require(half_w > 0.0f && half_h > 0.0f, "make_quad: half sizes must be positive");
  Mesh m;
  const glm::vec3 n{0.0f, 0.0f, 1.0f};
  const uint32_t a = add_vertex(m, {-half_w, -half_h, 0.0f}, n);
  const uint32_t b = add_vertex(m, {half_w, -half_h, 0.0f}, n);
  const uint32_t c = add_vertex(m, {half_w, half_h, 0.0f}, n);
  const uint32_t d = add_vertex(m, {-half_w, half_h, 0.0f}, n);
  add_quad(m, a, b, c, d);
  return m;
}

namespace {

// A box face: outward normal n and in-plane axes u, v with u x v = n, so that the corners
// -u-v, +u-v, +u+v, -u+v run counter-clockwise seen from outside.
struct BoxFace {
  glm::vec3 n, u, v;
};
constexpr int kFaceZ = 4;  // index of the face +z in kBoxFaces
const BoxFace kBoxFaces[6] = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
    {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
};

// The cells [i0, i1) x [j0, j1) of face f cut into cells x cells. Every coordinate is
// +-half_extent or -1 + 2 k / cells times it, computed the same way for every face and cell,
// so corners shared by faces or by two calls are bit-equal.
void add_face_cells(Mesh& m, const BoxFace& f, glm::vec3 half_extent, int cells, int i0, int i1,
                    int j0, int j1) {
  auto at = [cells](int k) { return -1.0f + 2.0f * float(k) / float(cells); };
  const auto base = static_cast<uint32_t>(m.positions.size());
  const int cols = i1 - i0 + 1;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i)
      add_vertex(m, (f.n + at(i) * f.u + at(j) * f.v) * half_extent, f.n);
  auto idx = [&](int i, int j) { return base + static_cast<uint32_t>((j - j0) * cols + (i - i0)); };
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i)
      add_quad(m, idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
}

void require_box(glm::vec3 half_extent, int cells) {
  require(half_extent.x > 0.0f && half_extent.y > 0.0f && half_extent.z > 0.0f,
          "make_box: half extents must be positive");
  require(cells >= 1, "make_grid_box: needs at least one cell");
}

}  // namespace

Mesh make_box(glm::vec3 half_extent) {
  require_box(half_extent, 1);
  static const glm::vec2 kCorners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Mesh m;
  for (const BoxFace& f : kBoxFaces) {
    uint32_t idx[4];
    for (int k = 0; k < 4; ++k) {
      // Every coordinate is exactly +-half_extent, so corners shared by faces are bit-equal.
      const glm::vec3 sign = f.n + kCorners[k].x * f.u + kCorners[k].y * f.v;
      idx[k] = add_vertex(m, sign * half_extent, f.n);
    }
    add_quad(m, idx[0], idx[1], idx[2], idx[3]);
  }
  return m;
}

Mesh make_grid_box(glm::vec3 half_extent, int cells) {
  require_box(half_extent, cells);
  Mesh m;
  for (const BoxFace& f : kBoxFaces) add_face_cells(m, f, half_extent, cells, 0, cells, 0, cells);
  return m;
}

Mesh make_box_face_cells(glm::vec3 half_extent, int cells, int i0, int i1, int j0, int j1) {
  require_box(half_extent, cells);
  require(0 <= i0 && i0 < i1 && i1 <= cells && 0 <= j0 && j0 < j1 && j1 <= cells,
          "make_box_face_cells: cells out of range");
  Mesh m;
  add_face_cells(m, kBoxFaces[kFaceZ], half_extent, cells, i0, i1, j0, j1);
  return m;
}

Mesh make_tetrahedron(float radius) {
  require(radius > 0.0f, "make_tetrahedron: radius must be positive");
  // Alternate corners of a cube; each face listed counter-clockwise seen from outside.
  const float k = radius / std::sqrt(3.0f);
  const glm::vec3 c[4] = {{k, k, k}, {k, -k, -k}, {-k, k, -k}, {-k, -k, k}};
  static const int kFaces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  Mesh m;
  for (const auto& f : kFaces) {
    const glm::vec3 n = glm::cross(c[f[1]] - c[f[0]], c[f[2]] - c[f[0]]);
    const uint32_t a = add_vertex(m, c[f[0]], n), b = add_vertex(m, c[f[1]], n),
                   d = add_vertex(m, c[f[2]], n);
    m.triangles.emplace_back(a, b, d);
  }
  return m;
}

Mesh make_sphere(float radius, int slices, int stacks) {
  require(radius > 0.0f, "make_sphere: radius must be positive");
  require(slices >= 3 && stacks >= 2, "make_sphere: needs slices >= 3 and stacks >= 2");
  // Direction at polar angle theta (from +y) and azimuth phi; phi runs counter-clockwise
  // seen from +y (from +x toward -z).
  auto dir = [](float theta, float phi) {
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                     -std::sin(theta) * std::sin(phi));
  };
  Mesh m;
  const uint32_t top = add_vertex(m, {0.0f, radius, 0.0f}, {0.0f, 1.0f, 0.0f});
  // Rings 1 .. stacks-1, each of `slices` vertices (no seam duplicate: normals are smooth).
  auto ring = [&](int i, int j) {
    return 1u + static_cast<uint32_t>((i - 1) * slices + (j % slices));
  };
  for (int i = 1; i < stacks; ++i) {
    const float theta = kPi * static_cast<float>(i) / static_cast<float>(stacks);
    for (int j = 0; j < slices; ++j) {
      const float phi = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(slices);
      const glm::vec3 d = dir(theta, phi);
      add_vertex(m, radius * d, d);
    }
  }
  const uint32_t bottom = add_vertex(m, {0.0f, -radius, 0.0f}, {0.0f, -1.0f, 0.0f});
  // One triangle per pole segment; two per segment of the bands between rings.
  for (int j = 0; j < slices; ++j) m.triangles.emplace_back(top, ring(1, j), ring(1, j + 1));
  for (int i = 1; i + 1 < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      add_quad(m, ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  }
  for (int j = 0; j < slices; ++j) {
    m.triangles.emplace_back(bottom, ring(stacks - 1, j + 1), ring(stacks - 1, j));
  }
  return m;
}

Mesh make_torus(float major_r, float minor_r, int major_seg, int minor_seg) {
  require(major_r > minor_r && minor_r > 0.0f, "make_torus: needs major_r > minor_r > 0");
  require(major_seg >= 3 && minor_seg >= 3, "make_torus: needs at least 3 segments each way");
  Mesh m;
  // Vertex (i, j): major angle u_i about +y (from +x toward -z), minor angle v_j around the
  // tube (0 = outermost, pi/2 = top).
  auto index = [&](int i, int j) {
    return static_cast<uint32_t>((i % major_seg) * minor_seg + (j % minor_seg));
  };
  for (int i = 0; i < major_seg; ++i) {
    const float u = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(major_seg);
    const glm::vec3 radial{std::cos(u), 0.0f, -std::sin(u)};
    for (int j = 0; j < minor_seg; ++j) {
      const float v = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(minor_seg);
      const glm::vec3 n = std::cos(v) * radial + glm::vec3(0.0f, std::sin(v), 0.0f);
      add_vertex(m, major_r * radial + minor_r * n, n);
    }
  }
  for (int i = 0; i < major_seg; ++i) {
    for (int j = 0; j < minor_seg; ++j) {
      add_quad(m, index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
    }
  }
  return m;
}

}  // namespace zb
