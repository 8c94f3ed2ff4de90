// Geometry stage tests: camera conventions, viewport mapping (y down), clipping, facing,
// flat Lambert shading, robustness. Expected values are derived by hand from the GL formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/geometry.h"
#include "raster/raster.h"
#include "scene/scene.h"

namespace zb {
namespace {

constexpr int32_t kOne = 256;

// Camera at +z looking at the origin, 90 degree vertical field of view.
Scene one_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, Rgba8 color = {200, 40, 8, 255}) {
  Scene s;
  s.materials.push_back(Material{"m", color});
  Object o;
  o.name = "tri";
  o.mesh.positions = {a, b, c};
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  o.mesh.normals = {n, n, n};
  o.mesh.triangles = {{0, 1, 2}};
  s.objects.push_back(o);
  s.camera.eye = {0, 0, 5};
  s.camera.at = {0, 0, 0};
  s.camera.fov_y_deg = 90.0f;
  s.camera.near = 1.0f;
  s.camera.far = 100.0f;
  return s;
}

// Window depth of a point at eye distance d (GL perspective, depth range [0, 1]).
double window_depth(double d, double n, double f) {
  const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * d);
  return (ndc + 1.0) / 2.0;
}

TEST(Geometry, CameraMatricesFollowGl) {
  Camera cam;
  cam.eye = {0, 0, 5};
  cam.near = 1.0f;
  cam.far = 10.0f;
  const glm::mat4 pv = cam.projection(2.0f) * cam.view();
  const glm::vec4 on_near = pv * glm::vec4(0, 0, 4, 1);   // 1 unit in front of the eye
  const glm::vec4 on_far = pv * glm::vec4(0, 0, -5, 1);   // 10 units in front
  EXPECT_NEAR(on_near.z / on_near.w, -1.0f, 1e-6f);
  EXPECT_NEAR(on_far.z / on_far.w, 1.0f, 1e-6f);
  EXPECT_GT(on_near.w, 0.0f);
}

TEST(Geometry, TriangleCount) {
  Scene s = one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  s.objects.push_back(s.objects[0]);
  s.objects[1].mesh.triangles.push_back({2, 1, 0});
  EXPECT_EQ(s.triangle_count(), 3u);
  EXPECT_EQ(Scene{}.triangle_count(), 0u);
}

TEST(Geometry, ViewportMappingKnownPoints) {
  // A vertex on the camera axis lands exactly at the window centre; with fov 90 and the
  // vertex at distance 5, a vertex at (5 * aspect, 5, 0) is on the top-right frustum corner.
  const Viewport vp = Viewport{640, 480};
  const float aspect = 640.0f / 480.0f;
  const Scene s = one_triangle({0, 0, 0}, {5 * aspect, 0, 0}, {0, 5, 0});
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  const ScreenTriangle& t = tris[0];
  EXPECT_EQ(t.v[0].x, 320 * kOne);
  EXPECT_EQ(t.v[0].y, 240 * kOne);
  EXPECT_NEAR(t.v[1].x, 640 * kOne, 2);  // right edge of the window
  EXPECT_EQ(t.v[1].y, 240 * kOne);
  EXPECT_EQ(t.v[2].x, 320 * kOne);
  EXPECT_NEAR(t.v[2].y, 0, 2);           // world up is window row 0 (y down)
  const double zw = window_depth(5.0, 1.0, 100.0);
  for (const ScreenVertex& v : t.v) {
    EXPECT_NEAR(v.z_exact, zw, 1e-6);
    EXPECT_EQ(v.z, uint32_t(std::llround(v.z_exact * depth_max(kDefaultDepthBits))));
  }
}

TEST(Geometry, DepthUnormRounding) {
  for (int bits : {16, 24, 32}) {
    const Viewport vp = Viewport{64, 64, bits};
    const Scene s = one_triangle({0, 0, 1}, {1, 0, -20}, {0, 1, -50});
    const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
    ASSERT_EQ(tris.size(), 1u);
    for (const ScreenVertex& v : tris[0].v) {
      EXPECT_GE(v.z_exact, 0.0);
      EXPECT_LE(v.z_exact, 1.0);
      EXPECT_EQ(v.z, uint32_t(std::llround(v.z_exact * double(depth_max(bits)))));
    }
    EXPECT_NEAR(tris[0].v[0].z_exact, window_depth(4.0, 1.0, 100.0), 1e-6);
  }
}

TEST(Geometry, NearPlaneCrossingIsClippedNotDropped) {
  // One vertex behind the eye (z = 8 > 5), two in front.
  const Viewport vp = Viewport{200, 100};
  const Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, -1, 8});
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_FALSE(tris.empty());
  uint32_t zmin = UINT32_MAX;
  for (const ScreenTriangle& t : tris) {
    EXPECT_EQ(t.prim, 0u);
    EXPECT_EQ(t.color, tris[0].color);
    EXPECT_EQ(t.front, tris[0].front);
    for (const ScreenVertex& v : t.v) {
      EXPECT_GE(v.z_exact, 0.0);
      EXPECT_LE(v.z_exact, 1.0);
      EXPECT_LE(v.z, depth_max(vp.depth_bits));
      zmin = std::min(zmin, v.z);
      // Guard band: window coordinates within [-1.5W, 2.5W] x [-1.5H, 2.5H].
      EXPECT_GE(v.x, -3 * vp.width * kOne / 2);
      EXPECT_LE(v.x, 5 * vp.width * kOne / 2);
      EXPECT_GE(v.y, -3 * vp.height * kOne / 2);
      EXPECT_LE(v.y, 5 * vp.height * kOne / 2);
    }
  }
  // The clipped vertices lie on the near plane: window depth 0.
  EXPECT_LE(zmin, depth_max(vp.depth_bits) / 100000);
  // The visible part still covers pixels: the bottom centre of the window.
  std::vector<Fragment> fr;
  for (const ScreenTriangle& t : tris) rasterize(t, vp, fr);
  EXPECT_FALSE(fr.empty());
}

TEST(Geometry, OutsideFrustumDropped) {
  const Viewport vp = Viewport{64, 64};
  EXPECT_TRUE(setup_triangles(one_triangle({0, 0, 6}, {1, 0, 6}, {0, 1, 7}), vp).empty());
  EXPECT_TRUE(setup_triangles(one_triangle({0, 0, -200}, {1, 0, -200}, {0, 1, -200}), vp).empty());
  EXPECT_TRUE(setup_triangles(one_triangle({50, 0, 0}, {51, 0, 0}, {50, 1, 0}), vp).empty());
}

TEST(Geometry, GuardBandClippedTriangleCoversWindowOnce) {
  // A huge triangle in front of the camera covers the whole window; it is clipped against the
  // guard band into a fan that must cover each pixel exactly once.
  const Viewport vp = Viewport{80, 60};
  const Scene s = one_triangle({-1000, -1000, 0}, {1000, -1000, 0}, {0, 1500, 0});
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_GE(tris.size(), 2u);
  std::vector<int> count(size_t(vp.width) * vp.height, 0);
  std::vector<Fragment> fr;
  for (const ScreenTriangle& t : tris) {
    for (const ScreenVertex& v : t.v) {
      EXPECT_GE(v.x, -3 * vp.width * kOne / 2 - 1);
      EXPECT_LE(v.x, 5 * vp.width * kOne / 2 + 1);
      EXPECT_GE(v.y, -3 * vp.height * kOne / 2 - 1);
      EXPECT_LE(v.y, 5 * vp.height * kOne / 2 + 1);
    }
    rasterize(t, vp, fr);
  }
  for (const Fragment& f : fr) ++count[size_t(f.y) * vp.width + f.x];
  for (int c : count) EXPECT_EQ(c, 1);
}

TEST(Geometry, FacingFromWinding) {
  const Viewport vp = Viewport{64, 64};
  // Counter-clockwise seen from +z, where the camera is: front.
  Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_TRUE(tris[0].front);
  // Its fixed-point signed area (x right, y down) is negative.
  const ScreenVertex *a = &tris[0].v[0], *b = &tris[0].v[1], *c = &tris[0].v[2];
  EXPECT_LT(int64_t(b->x - a->x) * (c->y - a->y) - int64_t(c->x - a->x) * (b->y - a->y), 0);
  // The same triangle seen from behind: back.
  s.camera.eye = {0, 0, -5};
  tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_FALSE(tris[0].front);
  // Reversed winding seen from the front: back.
  s = one_triangle({-1, -1, 0}, {0, 1, 0}, {1, -1, 0});
  tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_FALSE(tris[0].front);
  // A triangle below the eye crossing the near plane, seen from above: counter-clockwise about
  // +y is front, about -y back; every fan triangle keeps that facing.
  s = one_triangle({-1, -1, 0}, {0, -1, 8}, {1, -1, 0});
  tris = setup_triangles(s, vp);
  ASSERT_GE(tris.size(), 2u);
  for (const ScreenTriangle& t : tris) EXPECT_TRUE(t.front);
  s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, -1, 8});
  tris = setup_triangles(s, vp);
  ASSERT_GE(tris.size(), 2u);
  for (const ScreenTriangle& t : tris) EXPECT_FALSE(t.front);
}

TEST(Geometry, LambertFacingEyeIsMaterialColour) {
  const Viewport vp = Viewport{64, 64};
  const Rgba8 mat{200, 100, 50, 128};
  // Centroid on the camera axis, normal toward the eye.
  Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 2, 0}, mat);
  std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].color, mat);
  EXPECT_TRUE(tris[0].transparent);
  // Without vertex normals the face normal is used; from behind, two-sided: same colour.
  s.objects[0].mesh.normals.clear();
  s.camera.eye = {0, 0, -5};
  tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].color, mat);
  // Normals that cancel fall back to the face normal too.
  s.objects[0].mesh.normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 0}};
  tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].color, mat);
  // Opaque material.
  s.materials[0].color.a = 255;
  EXPECT_FALSE(setup_triangles(s, vp).at(0).transparent);
}

TEST(Geometry, LambertOblique) {
  // Rotated 60 degrees about y: |n . l| = 0.5, shade = 0.25 + 0.75 * 0.5 = 0.625.
  const Viewport vp = Viewport{64, 64};
  Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 2, 0}, Rgba8{200, 40, 8, 77});
  s.objects[0].transform = glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(0, 1, 0));
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  EXPECT_EQ(tris[0].color, (Rgba8{125, 25, 5, 77}));
}

TEST(Geometry, NormalMatrixIsInverseTranspose) {
  // Non-uniform scale of a slanted triangle: the shading normal must be the transformed
  // surface's normal, computed here from the transformed positions in double.
  const Viewport vp = Viewport{64, 64};
  const glm::vec3 p[3] = {{-1, -1, 1}, {1, -1, -1}, {0, 1, 0}};
  Scene s = one_triangle(p[0], p[1], p[2], Rgba8{255, 255, 255, 255});
  const glm::mat4 m = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.0f, 4.0f));
  s.objects[0].transform = m;
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 1u);
  glm::dvec3 w[3];
  for (int i = 0; i < 3; ++i) w[i] = glm::dvec3(m * glm::vec4(p[i], 1.0f));
  const glm::dvec3 n = glm::normalize(glm::cross(w[1] - w[0], w[2] - w[0]));
  const glm::dvec3 l = glm::normalize(glm::dvec3(0, 0, 5) - (w[0] + w[1] + w[2]) / 3.0);
  const double shade = 0.25 + 0.75 * std::fabs(glm::dot(n, l));
  EXPECT_NEAR(tris[0].color.r, 255.0 * shade, 0.51);
  EXPECT_LT(tris[0].color.r, 250);  // not facing the eye: visibly darker
}

TEST(Geometry, NonFiniteVerticesDropped) {
  const Viewport vp = Viewport{64, 64};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  Mesh& m = s.objects[0].mesh;
  m.positions.push_back({nan, 0, 0});
  m.positions.push_back({0, inf, 0});
  m.positions.push_back({1e30f, -1e30f, 1e30f});
  m.normals.resize(m.positions.size(), glm::vec3(0, 0, 1));
  m.triangles = {{3, 1, 2}, {0, 4, 2}, {0, 1, 2}, {5, 1, 2}, {0, 1, 2}};
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  // Prim ids count the dropped triangles: the finite ones are prims 2 and 4; prim 3 (huge but
  // finite) may survive clipping, and if so must lie within the guard band.
  ASSERT_GE(tris.size(), 2u);
  EXPECT_EQ(tris.front().prim, 2u);
  EXPECT_EQ(tris.back().prim, 4u);
  for (const ScreenTriangle& t : tris) {
    EXPECT_TRUE(t.prim == 2 || t.prim == 3 || t.prim == 4);
    for (const ScreenVertex& v : t.v) {
      EXPECT_GE(v.x, -3 * vp.width * kOne / 2 - 1);
      EXPECT_LE(v.x, 5 * vp.width * kOne / 2 + 1);
    }
  }
  // A NaN normal only affects shading.
  m.triangles = {{0, 1, 2}};
  m.normals[0] = glm::vec3(nan);
  EXPECT_EQ(setup_triangles(s, vp).size(), 1u);
  // A NaN camera drops everything without crashing.
  s.camera.eye = glm::vec3(nan);
  EXPECT_TRUE(setup_triangles(s, vp).empty());
}

TEST(Geometry, PrimIdsFollowSceneOrder) {
  const Viewport vp = Viewport{64, 64};
  Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  s.objects[0].mesh.triangles = {{0, 1, 2}, {0, 0, 1}, {0, 2, 1}};  // middle one zero-area
  s.objects.push_back(s.objects[0]);
  s.objects[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10));  // behind eye
  s.objects.push_back(s.objects[0]);
  const std::vector<ScreenTriangle> tris = setup_triangles(s, vp);
  ASSERT_EQ(tris.size(), 4u);
  EXPECT_EQ(tris[0].prim, 0u);
  EXPECT_EQ(tris[1].prim, 2u);
  EXPECT_EQ(tris[2].prim, 6u);
  EXPECT_EQ(tris[3].prim, 8u);
  EXPECT_TRUE(tris[0].front);
  EXPECT_FALSE(tris[1].front);
}

TEST(Geometry, InvalidInputsRejected) {
  const Scene s = one_triangle({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
  EXPECT_THROW(setup_triangles(s, Viewport{0, 64}), std::invalid_argument);
  EXPECT_THROW(setup_triangles(s, Viewport{64, kMaxFrameSize + 1}), std::invalid_argument);
  EXPECT_THROW(setup_triangles(s, Viewport{64, 64, 7}), std::invalid_argument);
  Scene bad = s;
  bad.objects[0].mesh.triangles = {{0, 1, 3}};
  EXPECT_THROW(setup_triangles(bad, Viewport{64, 64}), std::invalid_argument);
  bad = s;
  bad.objects[0].material = 4;
  EXPECT_THROW(setup_triangles(bad, Viewport{64, 64}), std::invalid_argument);
}

}  // namespace
}  // namespace zb
