// What both scene-file loaders build meshes with: material colours to unorm8, triangles over
// shared position and normal arrays. Internal to the golden model.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace zb {

inline uint8_t to_unorm8(double v) {
  if (!(v >= 0.0)) return 0;  // NaN too
  return static_cast<uint8_t>(std::lround(std::min(v, 1.0) * 255.0));
}

// Builds a mesh from triangles over shared position and normal arrays. A corner with a usable
// normal from the file shares its vertex with the other corners of the same (position, normal);
// a triangle without usable normals for all three corners gets its own vertices and the flat
// face normal ((0, 0, 1) when the triangle has zero area).
struct MeshBuilder {
  const std::vector<glm::vec3>& positions;
  const std::vector<glm::vec3>& normals;
  Mesh mesh;
  std::unordered_map<uint64_t, uint32_t> shared;

  void add(const uint32_t p[3], const int64_t n[3]) {
    bool smooth = true;
    for (int k = 0; k < 3; ++k)
      smooth = smooth && n[k] >= 0 && static_cast<size_t>(n[k]) < normals.size() &&
               glm::length(normals[n[k]]) > 0.0f;
    glm::uvec3 tri;
    if (smooth) {
      for (int k = 0; k < 3; ++k) {
        const uint64_t key = (uint64_t{p[k]} << 32) | static_cast<uint32_t>(n[k]);
        auto [it, inserted] = shared.try_emplace(key, static_cast<uint32_t>(mesh.positions.size()));
        if (inserted) {
          mesh.positions.push_back(positions[p[k]]);
          mesh.normals.push_back(glm::normalize(normals[n[k]]));
        }
        tri[k] = it->second;
      }
    } else {
      const glm::vec3 a = positions[p[0]], b = positions[p[1]], c = positions[p[2]];
      glm::vec3 fn = glm::cross(b - a, c - a);
      const float len = glm::length(fn);
      fn = (len > 0.0f && std::isfinite(len)) ? fn / len : glm::vec3(0.0f, 0.0f, 1.0f);
      for (int k = 0; k < 3; ++k) {
        tri[k] = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.push_back(positions[p[k]]);
        mesh.normals.push_back(fn);
      }
    }
    mesh.triangles.push_back(tri);
  }
};

}  // namespace zb
