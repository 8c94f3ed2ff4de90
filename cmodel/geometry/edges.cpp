// Tessellation edges (docs/raster.md, "Edges").
#include "edges.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>

namespace zb {
namespace {

__extension__ typedef unsigned __int128 u128;

// welded[i]: the lowest vertex index whose position has the same bits as vertex i.
std::vector<uint32_t> weld(const Mesh& mesh) {
  std::map<std::array<uint32_t, 3>, uint32_t> first;
  std::vector<uint32_t> welded(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &mesh.positions[i], sizeof(key));
    welded[i] = first.emplace(key, static_cast<uint32_t>(i)).first->second;
  }
  return welded;
}

uint64_t magnitude(__int128 v) { return v < 0 ? uint64_t(-v) : uint64_t(v); }

}  // namespace

std::vector<MeshEdge> unique_edges(const Mesh& mesh) {
  const std::vector<uint32_t> welded = weld(mesh);
  std::map<std::pair<uint32_t, uint32_t>, size_t> seen;
  std::vector<MeshEdge> out;
  for (size_t ti = 0; ti < mesh.triangles.size(); ++ti) {
    const glm::uvec3& t = mesh.triangles[ti];
    const uint32_t idx[3] = {t.x, t.y, t.z};
    const uint32_t tri = static_cast<uint32_t>(ti);
    for (int k = 0; k < 3; ++k) {
      if (idx[k] >= welded.size() || idx[(k + 1) % 3] >= welded.size()) continue;
      const uint32_t a = welded[idx[k]], b = welded[idx[(k + 1) % 3]];
      if (a == b) continue;
      const auto [it, first] =
          seen.emplace(std::make_pair(std::min(a, b), std::max(a, b)), out.size());
      if (first) {
        out.push_back({a, b, {tri, kNoFace}});
      } else {
        MeshEdge& e = out[it->second];
        if (e.faces[1] == kNoFace && e.faces[0] != tri) e.faces[1] = tri;
      }
    }
  }
  return out;
}

int64_t line_side(const ScreenLine& l, int64_t px, int64_t py) {
  const int64_t x0 = l.v[0].x, y0 = l.v[0].y;
  return (l.v[1].x - x0) * (py - y0) - (l.v[1].y - y0) * (px - x0);
}

namespace {

// Face `prim` as set up (its first fan piece), and the side of `line` it lies on.
EdgeFace edge_face(const ScreenLine& line, uint32_t prim, const std::vector<int64_t>& piece,
                   const std::vector<ScreenTriangle>& triangles) {
  EdgeFace f;
  if (prim == kNoFace || prim >= piece.size() || piece[prim] < 0) return f;
  const ScreenTriangle& t = triangles[size_t(piece[prim])];
  f.prim = prim;
  int64_t farthest = 0;
  for (int k = 0; k < 3; ++k) {
    f.v[k] = t.v[k];
    const int64_t e = line_side(line, t.v[k].x, t.v[k].y);
    if ((e < 0 ? -e : e) > (farthest < 0 ? -farthest : farthest)) farthest = e;
  }
  f.side = farthest > 0 ? 1 : farthest < 0 ? -1 : 0;
  return f;
}

}  // namespace

uint32_t depth_slope(const ScreenTriangle& t) {
  const ScreenVertex& a = t.v[0];
  const ScreenVertex& b = t.v[1];
  const ScreenVertex& c = t.v[2];
  const __int128 bx = int64_t{b.x} - a.x, by = int64_t{b.y} - a.y;
  const __int128 cx = int64_t{c.x} - a.x, cy = int64_t{c.y} - a.y;
  const __int128 bz = int64_t{b.z} - int64_t{a.z}, cz = int64_t{c.z} - int64_t{a.z};
  const uint64_t area = magnitude(bx * cy - cx * by);
  if (area == 0) return 0;
  // The plane's normal (nx, ny, area) in (1/256 pixel, 1/256 pixel, depth unit):
  // dz/dx = -nx / area per 1/256 pixel, so per pixel 256 |nx| / area.
  const uint64_t nx = magnitude(bz * cy - cz * by);
  const uint64_t ny = magnitude(bx * cz - cx * bz);
  const u128 num = u128(std::max(nx, ny)) * kSubpixelOne;
  const u128 slope = (num + area - 1) / area;
  return slope > UINT32_MAX ? UINT32_MAX : static_cast<uint32_t>(slope);
}

std::vector<ScreenLine> setup_lines(const Scene& scene, const Viewport& vp,
                                    const std::vector<ScreenTriangle>& triangles) {
  // Slope of each source triangle (the largest of its fan pieces when clipped), and its first
  // piece.
  std::vector<uint32_t> prim_slope(scene.triangle_count(), 0);
  std::vector<int64_t> piece(scene.triangle_count(), -1);
  for (size_t i = 0; i < triangles.size(); ++i) {
    const ScreenTriangle& t = triangles[i];
    if (t.prim >= prim_slope.size()) continue;
    prim_slope[t.prim] = std::max(prim_slope[t.prim], depth_slope(t));
    if (piece[t.prim] < 0) piece[t.prim] = int64_t(i);
  }

  const glm::mat4 view_proj =
      scene.camera.projection(float(vp.width) / float(vp.height)) * scene.camera.view();
  std::vector<ScreenLine> out;
  uint32_t prim_base = 0;  // first triangle prim of the object
  uint32_t edge_id = 0;
  for (const Object& obj : scene.objects) {
    const Mesh& mesh = obj.mesh;
    const std::vector<uint32_t> welded = weld(mesh);
    // Largest slope of the triangles touching each welded vertex.
    std::vector<uint32_t> vertex_slope(mesh.positions.size(), 0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      const uint32_t s = prim_slope[prim_base + t];
      for (int k = 0; k < 3; ++k) {
        const uint32_t i = mesh.triangles[t][k];
        if (i < welded.size()) vertex_slope[welded[i]] = std::max(vertex_slope[welded[i]], s);
      }
    }
    for (const MeshEdge& e : unique_edges(mesh)) {
      const uint32_t id = edge_id++;
      // The same float expressions as setup_triangles: bit-equal clip coordinates.
      glm::vec4 c[2];
      const uint32_t ends[2] = {e.a, e.b};
      for (int k = 0; k < 2; ++k) {
        const glm::vec3 world = glm::vec3(obj.transform * glm::vec4(mesh.positions[ends[k]], 1.0f));
        c[k] = view_proj * glm::vec4(world, 1.0f);
      }
      bool keep = true;
      for (int plane = 0; plane < kClipPlaneCount && keep; ++plane) {
        const float d0 = clip_plane_distance(plane, c[0]);
        const float d1 = clip_plane_distance(plane, c[1]);
        const bool in0 = d0 >= 0.0f, in1 = d1 >= 0.0f;
        if (in0 && in1) continue;
        if (!in0 && !in1) {
          keep = false;
        } else if (in0) {
          c[1] = clip_crossing(plane, c[0], d0, c[1], d1);
        } else {
          c[0] = clip_crossing(plane, c[1], d1, c[0], d0);
        }
      }
      ScreenLine line;
      if (!keep || !clip_to_window(c[0], vp, line.v[0]) || !clip_to_window(c[1], vp, line.v[1]))
        continue;
      line.depth_slope = std::max(vertex_slope[e.a], vertex_slope[e.b]);
      line.prim = id;
      for (int k = 0; k < 2; ++k)
        line.faces[k] = edge_face(line, e.faces[k] == kNoFace ? kNoFace : prim_base + e.faces[k],
                                  piece, triangles);
      out.push_back(line);
    }
    prim_base += static_cast<uint32_t>(mesh.triangles.size());
  }
  return out;
}

}  // namespace zb
