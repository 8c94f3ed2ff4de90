// Scene tests: the built-in scenes and the mesh builders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/builtin_scenes.h"
#include "scene/meshes.h"

namespace zb {
namespace {

// --- helpers ---------------------------------------------------------------------------------

// Checks that every index is in range, there is one unit normal per position, and no
// triangle has (near) zero area. `what` names the mesh in failures.
void expect_well_formed(const Mesh& m, const std::string& what) {
  ASSERT_FALSE(m.triangles.empty()) << what;
  ASSERT_EQ(m.normals.size(), m.positions.size()) << what;
  for (size_t i = 0; i < m.normals.size(); ++i) {
    EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f) << what << " normal " << i;
  }
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const glm::uvec3 tri = m.triangles[t];
    for (int k = 0; k < 3; ++k) ASSERT_LT(tri[k], m.positions.size()) << what << " tri " << t;
    const glm::vec3 a = m.positions[tri.x], b = m.positions[tri.y], c = m.positions[tri.z];
    const float area2 = glm::length(glm::cross(b - a, c - a));
    // Relative to the triangle's longest edge squared: rejects slivers as well as repeats.
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    EXPECT_GT(area2, 1e-4f * longest * longest) << what << " tri " << t << " is degenerate";
  }
}

// Welds vertices by exact position (the builders compute shared corners bit-identically) and
// checks that every directed edge appears exactly once and its reverse exactly once: the mesh is
// closed, 2-manifold at each edge and consistently wound.
void expect_watertight(const Mesh& m, const std::string& what) {
  std::map<std::tuple<float, float, float>, uint32_t> weld;
  std::vector<uint32_t> id(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i];
    id[i] = weld.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(weld.size()))
                .first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (const glm::uvec3& t : m.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{id[t[k]], id[t[(k + 1) % 3]]}];
  }
  int bad = 0;
  for (const auto& [e, count] : edges) {
    const auto rev = edges.find({e.second, e.first});
    if (count != 1 || rev == edges.end() || rev->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << what << ": " << bad << " directed edges not paired exactly once";
}

// Signed volume by the divergence theorem: positive when the triangles wind counter-clockwise
// seen from outside.
double signed_volume(const Mesh& m) {
  double v = 0.0;
  for (const glm::uvec3& t : m.triangles) {
    const glm::dvec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// Every triangle's face normal agrees with its vertex normals (outward shading normals).
void expect_normals_agree_with_winding(const Mesh& m, const std::string& what) {
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const glm::uvec3 tri = m.triangles[t];
    const glm::vec3 a = m.positions[tri.x], b = m.positions[tri.y], c = m.positions[tri.z];
    const glm::vec3 fn = glm::normalize(glm::cross(b - a, c - a));
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(fn, m.normals[tri[k]]), 0.2f) << what << " tri " << t << " vertex " << k;
    }
  }
}

Mesh world_mesh(const Object& o) {
  Mesh w = o.mesh;
  for (glm::vec3& p : w.positions) p = glm::vec3(o.transform * glm::vec4(p, 1.0f));
  return w;
}

// The camera's view-projection at 4:3, built here from GLM's conventions (right-handed eye
// space, clip depth in [-w, w]) so that these tests do not depend on Camera's own code.
glm::mat4 view_projection(const Camera& c, float aspect) {
  return glm::perspective(glm::radians(c.fov_y_deg), aspect, c.near, c.far) *
         glm::lookAt(c.eye, c.at, c.up);
}

// A ray from the eye through normalised device point (x, y) of a 4:3 frame.
struct Ray {
  glm::vec3 o, d;
};
Ray eye_ray(const Camera& c, float ndc_x, float ndc_y, float aspect) {
  const glm::vec3 f = glm::normalize(c.at - c.eye);
  const glm::vec3 r = glm::normalize(glm::cross(f, c.up));
  const glm::vec3 u = glm::cross(r, f);
  const float t = std::tan(glm::radians(c.fov_y_deg) * 0.5f);
  return {c.eye, glm::normalize(f + ndc_x * t * aspect * r + ndc_y * t * u)};
}

// Distances along `ray` at which it crosses the triangles of `m` (Moller-Trumbore, both faces).
std::vector<float> hits(const Mesh& m, const Ray& ray) {
  std::vector<float> out;
  for (const glm::uvec3& tri : m.triangles) {
    const glm::vec3 a = m.positions[tri.x];
    const glm::vec3 e1 = m.positions[tri.y] - a, e2 = m.positions[tri.z] - a;
    const glm::vec3 p = glm::cross(ray.d, e2);
    const float det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-12f) continue;
    const glm::vec3 s = ray.o - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.d, q) / det;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float dist = glm::dot(e2, q) / det;
    if (dist > 0.0f) out.push_back(dist);
  }
  return out;
}

// Layers of `m` that `ray` crosses: hits closer than 1e-4 apart (a ray through an edge shared
// by two triangles of one surface) count once.
size_t layers(const Mesh& m, const Ray& ray) {
  std::vector<float> h = hits(m, ray);
  std::sort(h.begin(), h.end());
  size_t n = 0;
  for (size_t i = 0; i < h.size(); ++i) {
    if (i == 0 || h[i] - h[i - 1] > 1e-4f) ++n;
  }
  return n;
}

constexpr float kAspect = 4.0f / 3.0f;

const Object* find_object(const Scene& s, const std::string& name) {
  for (const Object& o : s.objects) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

bool is_transparent(const Scene& s, const Object& o) {
  return s.materials[o.material].transparent();
}

// --- mesh builders ---------------------------------------------------------------------------

TEST(SceneMesh, QuadFacesPlusZ) {
  const Mesh q = make_quad(2.0f, 1.0f);
  expect_well_formed(q, "quad");
  EXPECT_EQ(q.triangles.size(), 2u);
  EXPECT_EQ(q.positions.size(), 4u);
  for (const glm::vec3& p : q.positions) {
    EXPECT_EQ(p.z, 0.0f);
    EXPECT_EQ(std::fabs(p.x), 2.0f);
    EXPECT_EQ(std::fabs(p.y), 1.0f);
  }
  for (const glm::vec3& n : q.normals) EXPECT_EQ(n, glm::vec3(0.0f, 0.0f, 1.0f));
  for (const glm::uvec3& t : q.triangles) {
    const glm::vec3 fn = glm::cross(q.positions[t.y] - q.positions[t.x],
                                    q.positions[t.z] - q.positions[t.x]);
    EXPECT_GT(fn.z, 0.0f) << "quad triangle not counter-clockwise seen from +z";
  }
  // The two triangles cover the whole rectangle: their areas add up to 2w * 2h.
  float area = 0.0f;
  for (const glm::uvec3& t : q.triangles) {
    area += 0.5f * glm::length(glm::cross(q.positions[t.y] - q.positions[t.x],
                                          q.positions[t.z] - q.positions[t.x]));
  }
  EXPECT_NEAR(area, 8.0f, 1e-5f);
}

TEST(SceneMesh, BoxIsClosedFlatAndOutward) {
  const glm::vec3 h{1.0f, 0.5f, 2.0f};
  const Mesh b = make_box(h);
  expect_well_formed(b, "box");
  EXPECT_EQ(b.triangles.size(), 12u);
  EXPECT_EQ(b.positions.size(), 24u);
  expect_watertight(b, "box");
  expect_normals_agree_with_winding(b, "box");
  EXPECT_NEAR(signed_volume(b), 8.0 * h.x * h.y * h.z, 1e-4);
  // Flat: each vertex normal is exactly its face normal, an axis.
  for (const glm::uvec3& t : b.triangles) {
    const glm::vec3 fn = glm::normalize(glm::cross(b.positions[t.y] - b.positions[t.x],
                                                   b.positions[t.z] - b.positions[t.x]));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(b.normals[t[k]], fn);
  }
  for (const glm::vec3& p : b.positions) {
    EXPECT_EQ(glm::abs(p), h);
  }
}

TEST(SceneMesh, SphereIsClosedSmoothAndOutward) {
  for (auto [slices, stacks] : {std::pair{3, 2}, std::pair{8, 3}, std::pair{32, 16}}) {
    const std::string what = "sphere " + std::to_string(slices) + "x" + std::to_string(stacks);
    const float r = 1.5f;
    const Mesh s = make_sphere(r, slices, stacks);
    expect_well_formed(s, what);
    // One triangle per pole segment, two per band segment.
    EXPECT_EQ(s.triangles.size(), static_cast<size_t>(2 * slices + 2 * slices * (stacks - 2)))
        << what;
    EXPECT_EQ(s.positions.size(), static_cast<size_t>(2 + slices * (stacks - 1))) << what;
    expect_watertight(s, what);
    expect_normals_agree_with_winding(s, what);
    EXPECT_GT(signed_volume(s), 0.0) << what;
    for (size_t i = 0; i < s.positions.size(); ++i) {
      EXPECT_NEAR(glm::length(s.positions[i]), r, 1e-5f) << what;
      EXPECT_NEAR(glm::dot(s.normals[i], s.positions[i] / r), 1.0f, 1e-5f) << what;  // smooth
    }
  }
  // A fine sphere's volume approaches 4/3 pi r^3 from below (inscribed polyhedron).
  const double v = signed_volume(make_sphere(1.0f, 64, 32));
  EXPECT_LT(v, 4.0 / 3.0 * M_PI);
  EXPECT_GT(v, 0.98 * 4.0 / 3.0 * M_PI);
}

TEST(SceneMesh, TorusIsClosedSmoothAndOutward) {
  for (auto [major, minor] : {std::pair{3, 3}, std::pair{48, 24}}) {
    const std::string what = "torus " + std::to_string(major) + "x" + std::to_string(minor);
    const float R = 1.0f, r = 0.3f;
    const Mesh t = make_torus(R, r, major, minor);
    expect_well_formed(t, what);
    EXPECT_EQ(t.triangles.size(), static_cast<size_t>(2 * major * minor)) << what;
    expect_watertight(t, what);
    EXPECT_GT(signed_volume(t), 0.0) << what;
    // Around the y axis; each normal points from the tube's centre circle to the vertex.
    for (size_t i = 0; i < t.positions.size(); ++i) {
      const glm::vec3 p = t.positions[i];
      const glm::vec3 c = R * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
      EXPECT_NEAR(glm::length(p - c), r, 1e-5f) << what;
      EXPECT_NEAR(glm::dot(t.normals[i], (p - c) / r), 1.0f, 1e-4f) << what;
    }
    if (major >= 8) expect_normals_agree_with_winding(t, what);
  }
  const double v = signed_volume(make_torus(1.0f, 0.3f, 96, 48));
  const double exact = 2.0 * M_PI * M_PI * 1.0 * 0.3 * 0.3;
  EXPECT_NEAR(v, exact, 0.01 * exact);
}

TEST(SceneMesh, BuildersRejectDegenerateParameters) {
  EXPECT_THROW(make_quad(0.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(make_box({1.0f, 0.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(make_sphere(1.0f, 2, 4), std::invalid_argument);
  EXPECT_THROW(make_sphere(1.0f, 8, 1), std::invalid_argument);
  EXPECT_THROW(make_torus(0.3f, 1.0f, 8, 8), std::invalid_argument);
  EXPECT_THROW(make_torus(1.0f, 0.3f, 2, 8), std::invalid_argument);
}

// --- the catalogue ---------------------------------------------------------------------------

TEST(SceneCatalogue, DefaultIsCadAndNamesRoundTrip) {
  const auto& infos = builtin_scenes();
  ASSERT_GE(infos.size(), 3u);
  EXPECT_EQ(infos.front().name, "cad");
  std::set<std::string> names;
  for (const SceneInfo& info : infos) {
    EXPECT_TRUE(names.insert(info.name).second) << "duplicate " << info.name;
    EXPECT_FALSE(info.description.empty()) << info.name;
    EXPECT_EQ(info.description.find('\n'), std::string::npos) << info.name;
    const std::optional<Scene> s = builtin_scene(info.name);
    ASSERT_TRUE(s.has_value()) << info.name;
    EXPECT_EQ(s->name, info.name);
    EXPECT_EQ(s->description, info.description);
  }
  for (const char* n : {"cad", "quads", "sphere-torus"}) EXPECT_EQ(names.count(n), 1u) << n;
}

TEST(SceneCatalogue, UnknownNameGivesNothing) {
  EXPECT_FALSE(builtin_scene("").has_value());
  EXPECT_FALSE(builtin_scene("no-such-scene").has_value());
  EXPECT_FALSE(builtin_scene("CAD").has_value());
}

TEST(SceneCatalogue, ScenesAreDeterministic) {
  for (const SceneInfo& info : builtin_scenes()) {
    const Scene a = *builtin_scene(info.name), b = *builtin_scene(info.name);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) {
      EXPECT_EQ(a.objects[i].mesh.positions, b.objects[i].mesh.positions) << info.name;
      EXPECT_EQ(a.objects[i].mesh.triangles, b.objects[i].mesh.triangles) << info.name;
    }
  }
}

// Every built-in scene: valid materials, well-formed meshes (closed ones watertight and
// outward), both opaque and transparent content, moderate size, fully in view at 4:3 with a
// tight depth range.
TEST(SceneCatalogue, EveryBuiltinIsWellFormedAndInView) {
  for (const SceneInfo& info : builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene s = *builtin_scene(info.name);
    EXPECT_EQ(s.background, (Rgba8{255, 255, 255, 255}));
    size_t tris = 0, opaque = 0, transparent = 0;
    for (const Object& o : s.objects) {
      ASSERT_LT(o.material, s.materials.size()) << o.name;
      expect_well_formed(o.mesh, o.name);
      (is_transparent(s, o) ? transparent : opaque)++;
      tris += o.mesh.triangles.size();
      // Meshes that enclose volume (everything but the quads) must be closed and outward.
      if (o.mesh.triangles.size() > 2) {
        const Mesh w = world_mesh(o);
        expect_watertight(w, o.name);
        EXPECT_GT(signed_volume(w), 0.0) << o.name;
      }
    }
    EXPECT_GE(opaque, 1u);
    EXPECT_GE(transparent, 1u);
    EXPECT_LT(tris, 5000u);

    // In view: every vertex inside the 4:3 frustum, with a little margin at the sides.
    const glm::mat4 vp = view_projection(s.camera, kAspect);
    float depth_lo = std::numeric_limits<float>::max();
    float depth_hi = std::numeric_limits<float>::lowest();
    for (const Object& o : s.objects) {
      for (const glm::vec3& p : o.mesh.positions) {
        const glm::vec4 c = vp * o.transform * glm::vec4(p, 1.0f);
        ASSERT_GT(c.w, 0.0f) << o.name;
        EXPECT_LE(std::fabs(c.x / c.w), 0.98f) << o.name << " leaves the frame in x";
        EXPECT_LE(std::fabs(c.y / c.w), 0.98f) << o.name << " leaves the frame in y";
        EXPECT_LT(std::fabs(c.z / c.w), 1.0f) << o.name << " crosses the near or far plane";
        const float eye_d = c.w;  // eye-space distance along the view axis
        depth_lo = std::min(depth_lo, eye_d);
        depth_hi = std::max(depth_hi, eye_d);
      }
    }
    // Tight depth range: near and far hug the scene (within 10% of its depth range).
    const float range = depth_hi - depth_lo;
    EXPECT_GT(s.camera.near, depth_lo - 0.1f * range);
    EXPECT_LT(s.camera.far, depth_hi + 0.1f * range);
  }
}

// --- scene content ---------------------------------------------------------------------------

TEST(SceneCad, OnePartInsideTwoShellsSubmittedOuterFirst) {
  const Scene s = *builtin_scene("cad");
  ASSERT_EQ(s.objects.size(), 3u);
  const Object& outer = s.objects[0];
  const Object& inner = s.objects[1];
  const Object& part = s.objects[2];
  EXPECT_EQ(outer.name, "outer_shell");
  EXPECT_EQ(inner.name, "inner_shell");
  EXPECT_EQ(part.name, "part");
  EXPECT_FALSE(is_transparent(s, part));
  EXPECT_TRUE(is_transparent(s, inner));
  EXPECT_TRUE(is_transparent(s, outer));
  EXPECT_NEAR(s.materials[inner.material].color.a, 128, 10);
  EXPECT_NEAR(s.materials[outer.material].color.a, 77, 10);
  EXPECT_NE(s.materials[inner.material].color, s.materials[outer.material].color);

  // Nesting: every vertex of the part is inside the inner shell (a sphere about the origin),
  // and the inner shell is inside the outer box.
  const Mesh wi = world_mesh(inner), wp = world_mesh(part), wo = world_mesh(outer);
  float inner_r = 1e9f;
  for (const glm::vec3& p : wi.positions) inner_r = std::min(inner_r, glm::length(p));
  for (const glm::vec3& p : wp.positions) EXPECT_LT(glm::length(p), inner_r);
  const glm::mat4 to_outer = glm::inverse(outer.transform);
  glm::vec3 outer_half{0.0f};
  for (const glm::vec3& p : outer.mesh.positions) outer_half = glm::max(outer_half, glm::abs(p));
  for (const glm::vec3& p : wi.positions) {
    const glm::vec3 q = glm::abs(glm::vec3(to_outer * glm::vec4(p, 1.0f)));
    EXPECT_TRUE(q.x < outer_half.x && q.y < outer_half.y && q.z < outer_half.z);
  }

  // Oblique view: the ray through the centre crosses outer front, inner front, then the part;
  // somewhere (beside the part) a ray crosses both shells twice: four transparent layers.
  const Ray centre = eye_ray(s.camera, 0.0f, 0.0f, kAspect);
  EXPECT_EQ(layers(wo, centre), 2u);
  EXPECT_EQ(layers(wi, centre), 2u);
  EXPECT_GE(layers(wp, centre), 2u);
  const Ray side = eye_ray(s.camera, 0.15f, 0.0f, kAspect);
  EXPECT_EQ(layers(wo, side) + layers(wi, side), 4u);
  EXPECT_GT(std::fabs(glm::dot(glm::normalize(s.camera.at - s.camera.eye), glm::vec3(1, 0, 0))),
            0.2f);
  EXPECT_GT(std::fabs(glm::dot(glm::normalize(s.camera.at - s.camera.eye), glm::vec3(0, 1, 0))),
            0.2f);
}

TEST(SceneQuads, KnownDepthsAndBothSubmitOrders) {
  const Scene s = *builtin_scene("quads");
  // Camera straight down -z: each quad (facing +z) has one constant depth.
  EXPECT_EQ(s.camera.eye.x, s.camera.at.x);
  EXPECT_EQ(s.camera.eye.y, s.camera.at.y);
  EXPECT_GT(s.camera.eye.z, s.camera.at.z);
  const struct {
    const char* name;
    float z;
  } expected[] = {{"A_left", 1.0f},  {"B_left", 0.0f},  {"C_left", -1.0f},
                  {"C_right", -1.0f}, {"B_right", 0.0f}, {"A_right", 1.0f}};
  std::vector<size_t> order;
  for (const auto& e : expected) {
    const Object* o = find_object(s, e.name);
    ASSERT_NE(o, nullptr) << e.name;
    EXPECT_TRUE(is_transparent(s, *o)) << e.name;
    for (const glm::vec3& p : world_mesh(*o).positions) EXPECT_EQ(p.z, e.z) << e.name;
    order.push_back(static_cast<size_t>(o - s.objects.data()));
  }
  // Left: A, B, C in submit order (near to far); right: C, B, A (far to near).
  EXPECT_TRUE(order[0] < order[1] && order[1] < order[2]);
  EXPECT_TRUE(order[3] < order[4] && order[4] < order[5]);
  // The same letter shares one material on both sides; the three materials differ.
  const Object* backdrop = find_object(s, "backdrop");
  ASSERT_NE(backdrop, nullptr);
  EXPECT_FALSE(is_transparent(s, *backdrop));
  for (const glm::vec3& p : world_mesh(*backdrop).positions) EXPECT_LT(p.z, -1.0f);
  EXPECT_EQ(s.objects[order[0]].material, s.objects[order[5]].material);
  EXPECT_NE(s.objects[order[0]].material, s.objects[order[1]].material);
  EXPECT_NE(s.objects[order[1]].material, s.objects[order[2]].material);

  // Each half has regions of exactly 1, 2 and 3 transparent layers, all over the backdrop.
  const Mesh wb = world_mesh(*backdrop);
  std::vector<Mesh> wq;
  for (size_t i : order) wq.push_back(world_mesh(s.objects[i]));
  for (int side = 0; side < 2; ++side) {
    std::set<size_t> layer_counts;
    for (int iy = -20; iy <= 20; ++iy) {
      for (int ix = 0; ix <= 40; ++ix) {
        const float x = (side == 0 ? -1.0f : 0.0f) + static_cast<float>(ix) / 40.0f;
        const Ray r = eye_ray(s.camera, x, static_cast<float>(iy) / 20.0f, kAspect);
        size_t n = 0;
        for (int k = 0; k < 3; ++k) n += layers(wq[side * 3 + k], r);
        if (n > 0) {
          EXPECT_EQ(layers(wb, r), 1u) << "quad not over the backdrop";
        }
        layer_counts.insert(n);
      }
    }
    for (size_t n : {1u, 2u, 3u}) EXPECT_EQ(layer_counts.count(n), 1u) << side << " " << n;
  }
}

TEST(SceneSphereTorus, TorusOverlapsItselfOnScreen) {
  const Scene s = *builtin_scene("sphere-torus");
  const Object* sphere = find_object(s, "sphere");
  const Object* torus = find_object(s, "torus");
  const Object* ground = find_object(s, "ground");
  ASSERT_TRUE(sphere && torus && ground);
  EXPECT_TRUE(is_transparent(s, *sphere));
  EXPECT_TRUE(is_transparent(s, *torus));
  EXPECT_FALSE(is_transparent(s, *ground));
  EXPECT_NEAR(s.materials[sphere->material].color.a, 128, 10);
  EXPECT_NEAR(s.materials[torus->material].color.a, 128, 10);
  EXPECT_NE(s.materials[sphere->material].color, s.materials[torus->material].color);

  // Some ray crosses the torus four times (its tube twice), and some crosses the sphere and
  // the torus both: the transparent objects overlap on screen and the torus overlaps itself.
  const Mesh wt = world_mesh(*torus), ws = world_mesh(*sphere);
  size_t most_torus = 0;
  bool sphere_and_torus = false;
  for (int iy = -24; iy <= 24; ++iy) {
    for (int ix = -32; ix <= 32; ++ix) {
      const Ray r = eye_ray(s.camera, static_cast<float>(ix) / 32.0f,
                            static_cast<float>(iy) / 24.0f, kAspect);
      const size_t nt = layers(wt, r);
      most_torus = std::max(most_torus, nt);
      if (nt > 0 && layers(ws, r) > 0) sphere_and_torus = true;
    }
  }
  EXPECT_GE(most_torus, 4u);
  EXPECT_TRUE(sphere_and_torus);

  // The two transparent objects do not intersect: no torus vertex inside the sphere.
  const glm::vec3 centre = glm::vec3(sphere->transform[3]);
  float radius = 0.0f;
  for (const glm::vec3& p : ws.positions) radius = std::max(radius, glm::length(p - centre));
  for (const glm::vec3& p : wt.positions) EXPECT_GT(glm::length(p - centre), radius);
}

}  // namespace
}  // namespace zb
