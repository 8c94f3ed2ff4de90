// The lab's scene suite: every scene has the property it is built for, measured from its
// rasterized fragments (or, for the seam, from the images), never from the builder's own numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "scene/failure_scenes.h"
#include "pipeline/passes.h"
#include "reference/reference.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene/scene_suite.h"
#include "scene/builtin_scenes.h"
#include "scene/meshes.h"

namespace zb {
namespace {

constexpr int kW = 320, kH = 240;

RasterizedScene raster(const std::string& name, int w = kW, int h = kH) {
  const std::optional<Scene> s = builtin_scene(name);
  EXPECT_TRUE(s.has_value()) << name;
  return rasterize_scene(*s, Viewport{w, h, kDefaultDepthBits});
}

// The object each source triangle (Fragment::prim) comes from, by the scene's object order.
std::vector<size_t> object_of_prim(const Scene& s) {
  std::vector<size_t> out;
  for (size_t o = 0; o < s.objects.size(); ++o)
    out.insert(out.end(), s.objects[o].mesh.triangles.size(), o);
  return out;
}

size_t object_index(const Scene& s, const std::string& name) {
  for (size_t o = 0; o < s.objects.size(); ++o)
    if (s.objects[o].name == name) return o;
  ADD_FAILURE() << "no object " << name;
  return s.objects.size();
}

// Per pixel, the indices of its fragments in submit order; and the triangle of each fragment.
struct PixelFragments {
  std::vector<std::vector<size_t>> at;
  std::vector<size_t> triangle;
};

PixelFragments by_pixel(const RasterizedScene& rs) {
  PixelFragments p;
  p.at.resize(size_t(rs.viewport.width) * rs.viewport.height);
  p.triangle.resize(rs.fragments.size());
  for (size_t t = 0; t + 1 < rs.first_fragment.size(); ++t)
    for (size_t i = rs.first_fragment[t]; i < rs.first_fragment[t + 1]; ++i) p.triangle[i] = t;
  for (size_t i = 0; i < rs.fragments.size(); ++i) {
    const Fragment& f = rs.fragments[i];
    p.at[size_t(f.y) * rs.viewport.width + f.x].push_back(i);
  }
  return p;
}

int channel_diff(Rgba8 a, Rgba8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// --- the suite --------------------------------------------------------------------------------

TEST(SceneSuite, FamiliesInOrderEveryNameResolves) {
  const std::vector<std::string> families = {"shells",    "layers",    "interpenetrating",
                                             "non-convex", "coplanar", "particles",
                                             "seam",      "hidden-line"};
  std::vector<std::string> seen;
  std::set<std::string> names;
  for (const SuiteScene& e : scene_suite()) {
    SCOPED_TRACE(e.name);
    if (seen.empty() || seen.back() != e.family) seen.push_back(e.family);
    EXPECT_TRUE(names.insert(e.name).second) << "listed twice";
    EXPECT_FALSE(e.description.empty());
    EXPECT_EQ(e.description.find('\n'), std::string::npos);
    EXPECT_LE(e.description.size(), 200u) << "one line";
    const std::optional<Scene> a = suite_scene(e.name), b = builtin_scene(e.name);
    ASSERT_TRUE(a.has_value());
    ASSERT_TRUE(b.has_value());
    EXPECT_EQ(a->triangle_count(), b->triangle_count());
    EXPECT_GT(a->triangle_count(), 0u);
  }
  EXPECT_EQ(seen, families) << "each family once, in this order";
  for (const char* n : {"cad", "crossing-quads", "glass-torus", "coplanar", "particles", "seam",
                        "parts"})
    EXPECT_EQ(names.count(n), 1u) << n;
}

TEST(SceneSuite, LayersSampleAndNamesRoundTrip) {
  std::vector<std::string> layers;
  for (const SuiteScene& e : scene_suite())
    if (e.family == "layers") layers.push_back(e.name);
  std::vector<std::string> expected;
  for (const char* n : {"1", "2", "4", "8", "16"})
    for (const char* p : {"10", "50", "90"})
      expected.push_back(std::string("layers-") + n + "-a" + p);
  EXPECT_EQ(layers, expected);
  // Every layer count and alpha percent resolves, under its own name.
  for (int n = 1; n <= 16; ++n)
    for (int p = 1; p <= 99; ++p) {
      const std::string name = "layers-" + std::to_string(n) + "-a" + std::to_string(p);
      const std::optional<Scene> s = suite_scene(name);
      ASSERT_TRUE(s.has_value()) << name;
      EXPECT_EQ(s->name, name);
      EXPECT_EQ(layers_scene_name(n, float(p) / 100.0f), name);
    }
}

TEST(SceneSuite, UnknownAndMalformedNamesGiveNothing) {
  for (const char* n : {"layers-0-a50", "layers-17-a50", "layers-4-a0", "layers-4-a100",
                        "layers-4-a50x", "layers-04-a50", "layers-4-a050", "layers-+4-a50",
                        "layers- 4-a50", "layers-4-a-50", "layers-4", "layers-4-a", "layers",
                        "", "no-such-scene", "Seam", "seam ", "quads"}) {
    EXPECT_FALSE(suite_scene(n).has_value()) << "'" << n << "'";
  }
  // quads is a built-in, not a suite scene; unknown names reach neither.
  EXPECT_TRUE(builtin_scene("quads").has_value());
  EXPECT_FALSE(builtin_scene("layers-17-a50").has_value());
  EXPECT_FALSE(builtin_scene("particles-2").has_value());
}

TEST(SceneSuite, ScenesAreDeterministic) {
  for (const SuiteScene& e : scene_suite()) {
    const Scene a = *suite_scene(e.name), b = *suite_scene(e.name);
    ASSERT_EQ(a.objects.size(), b.objects.size()) << e.name;
    for (size_t i = 0; i < a.objects.size(); ++i) {
      EXPECT_EQ(a.objects[i].mesh.positions, b.objects[i].mesh.positions) << e.name;
      EXPECT_EQ(a.objects[i].transform, b.objects[i].transform) << e.name;
    }
  }
}

// --- mesh builders ----------------------------------------------------------------------------

// Every directed edge once and its reverse once (vertices welded by exact position).
bool closed_and_consistent(const Mesh& m) {
  std::map<std::tuple<float, float, float>, size_t> weld;
  std::vector<size_t> id;
  for (const glm::vec3& p : m.positions)
    id.push_back(weld.emplace(std::make_tuple(p.x, p.y, p.z), weld.size()).first->second);
  std::map<std::pair<size_t, size_t>, int> edges;
  for (const glm::uvec3& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{id[t[k]], id[t[(k + 1) % 3]]}];
  for (const auto& [e, n] : edges) {
    const auto r = edges.find({e.second, e.first});
    if (n != 1 || r == edges.end() || r->second != 1) return false;
  }
  return true;
}

double volume(const Mesh& m) {
  double v = 0;
  for (const glm::uvec3& t : m.triangles)
    v += glm::dot(glm::dvec3(m.positions[t.x]),
                  glm::cross(glm::dvec3(m.positions[t.y]), glm::dvec3(m.positions[t.z]))) / 6;
  return v;
}

TEST(SceneSuiteMesh, TetrahedronIsRegularClosedAndOutward) {
  const Mesh m = make_tetrahedron(0.5f);
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_TRUE(closed_and_consistent(m));
  // A regular tetrahedron of circumradius r has edge r sqrt(8/3) and volume edge^3 / (6 sqrt 2).
  const double edge = 0.5 * std::sqrt(8.0 / 3.0);
  EXPECT_NEAR(volume(m), edge * edge * edge / (6 * std::sqrt(2.0)), 1e-6);
  for (const glm::vec3& p : m.positions) EXPECT_NEAR(glm::length(p), 0.5f, 1e-6f);
  for (size_t i = 0; i < m.positions.size(); ++i)  // flat normals point away from the centre
    EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.0f);
}

TEST(SceneSuiteMesh, GridBoxIsClosedAndItsCellsAreBitEqual) {
  const glm::vec3 half{2.0f, 1.0f, 0.25f};
  const Mesh box = make_grid_box(half, 3);
  EXPECT_EQ(box.triangles.size(), 6u * 9u * 2u);
  EXPECT_TRUE(closed_and_consistent(box));
  EXPECT_NEAR(volume(box), 8.0 * 2.0 * 1.0 * 0.25, 1e-5);
  // The centre cell of face +z: x and y in [-1/3, 1/3] of the half extents, z = +half.z; its
  // triangles are among the box's, corner for corner.
  const Mesh cell = make_box_face_cells(half, 3, 1, 2, 1, 2);
  ASSERT_EQ(cell.triangles.size(), 2u);
  std::set<std::tuple<float, float, float, float, float, float, float, float, float>> tris;
  auto key = [](const Mesh& m, const glm::uvec3& t) {
    const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    return std::make_tuple(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z);
  };
  for (const glm::uvec3& t : box.triangles) tris.insert(key(box, t));
  for (const glm::uvec3& t : cell.triangles) EXPECT_EQ(tris.count(key(cell, t)), 1u);
  for (const glm::vec3& p : cell.positions) {
    EXPECT_EQ(p.z, 0.25f);
    EXPECT_NEAR(std::fabs(p.x), 2.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(std::fabs(p.y), 1.0f / 3.0f, 1e-6f);
  }
  EXPECT_THROW(make_grid_box(half, 0), std::invalid_argument);
  EXPECT_THROW(make_box_face_cells(half, 3, 2, 2, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_box_face_cells(half, 3, 0, 4, 0, 1), std::invalid_argument);
  EXPECT_THROW(make_tetrahedron(0.0f), std::invalid_argument);
}

// --- each family's property -------------------------------------------------------------------

// layers-N-aP: inside the rectangle every pixel has exactly N transparent fragments, submitted
// near to far, each of alpha round(P/100 * 255).
TEST(SceneSuiteLayers, EveryPixelOfTheRectangleSeesNLayersNearToFar) {
  for (const auto& [n, p] : {std::pair{1, 10}, {4, 50}, {16, 90}, {7, 33}}) {
    const std::string name = "layers-" + std::to_string(n) + "-a" + std::to_string(p);
    SCOPED_TRACE(name);
    const RasterizedScene rs = raster(name);
    const PixelFragments px = by_pixel(rs);
    const auto alpha = static_cast<uint8_t>(std::lround(p / 100.0 * 255.0));
    int x0 = kW, y0 = kH, x1 = -1, y1 = -1;
    for (size_t i = 0; i < rs.fragments.size(); ++i) {
      if (!rs.triangles[px.triangle[i]].transparent) continue;
      const Fragment& f = rs.fragments[i];
      x0 = std::min<int>(x0, f.x), x1 = std::max<int>(x1, f.x);
      y0 = std::min<int>(y0, f.y), y1 = std::max<int>(y1, f.y);
    }
    ASSERT_GT(x1 - x0, kW / 3);
    ASSERT_GT(y1 - y0, kH / 3);
    int checked = 0;
    for (int y = y0 + 1; y < y1; ++y)
      for (int x = x0 + 1; x < x1; ++x) {
        std::vector<const Fragment*> layers;
        for (size_t i : px.at[size_t(y) * kW + x])
          if (rs.triangles[px.triangle[i]].transparent) layers.push_back(&rs.fragments[i]);
        ASSERT_EQ(layers.size(), size_t(n)) << "pixel " << x << "," << y;
        for (size_t k = 0; k < layers.size(); ++k) {
          EXPECT_EQ(layers[k]->color.a, alpha);
          if (k > 0) {
            EXPECT_GT(layers[k]->z, layers[k - 1]->z) << "near to far";
          }
        }
        ++checked;
      }
    EXPECT_GT(checked, kW * kH / 8);
  }
}

// interpenetrating: for every pair of the three quads, each is nearer at some pixels.
TEST(SceneSuiteInterpenetrating, EveryPairSwapsDepthOrder) {
  const Scene s = *builtin_scene("crossing-quads");
  const RasterizedScene rs = rasterize_scene(s, Viewport{kW, kH, kDefaultDepthBits});
  const PixelFragments px = by_pixel(rs);
  const std::vector<size_t> obj = object_of_prim(s);
  std::vector<size_t> quads;
  for (size_t o = 0; o < s.objects.size(); ++o)
    if (s.materials[s.objects[o].material].transparent()) quads.push_back(o);
  ASSERT_EQ(quads.size(), 3u);
  for (size_t a = 0; a < quads.size(); ++a)
    for (size_t b = a + 1; b < quads.size(); ++b) {
      int a_nearer = 0, b_nearer = 0;
      for (const std::vector<size_t>& frags : px.at) {
        const Fragment *fa = nullptr, *fb = nullptr;
        for (size_t i : frags) {
          const size_t o = obj[rs.fragments[i].prim];
          if (o == quads[a]) fa = &rs.fragments[i];
          if (o == quads[b]) fb = &rs.fragments[i];
        }
        if (!fa || !fb) continue;
        if (fa->z < fb->z) ++a_nearer;
        if (fb->z < fa->z) ++b_nearer;
      }
      EXPECT_GT(a_nearer, 500) << s.objects[quads[a]].name << " over " << s.objects[quads[b]].name;
      EXPECT_GT(b_nearer, 500) << s.objects[quads[b]].name << " over " << s.objects[quads[a]].name;
    }
}

// non-convex: one torus, 4 transparent layers at many pixels, where a front face lies behind a
// back face (back-front draws every back face before every front face).
TEST(SceneSuiteNonConvex, TorusIsFourDeepWithFrontFacesBehindBackFaces) {
  const Scene s = *builtin_scene("glass-torus");
  const RasterizedScene rs = rasterize_scene(s, Viewport{kW, kH, kDefaultDepthBits});
  const PixelFragments px = by_pixel(rs);
  const std::vector<size_t> obj = object_of_prim(s);
  std::set<size_t> transparent_objects;
  int four_deep = 0, front_behind_back = 0;
  for (const std::vector<size_t>& frags : px.at) {
    std::vector<size_t> layers;
    for (size_t i : frags)
      if (rs.triangles[px.triangle[i]].transparent) {
        layers.push_back(i);
        transparent_objects.insert(obj[rs.fragments[i].prim]);
      }
    int front = 0;
    for (size_t i : layers) front += rs.triangles[px.triangle[i]].front;
    if (layers.size() < 4 || front < 2) continue;
    ++four_deep;
    std::sort(layers.begin(), layers.end(),
              [&](size_t a, size_t b) { return rs.z_exact[a] < rs.z_exact[b]; });
    bool back_seen = false;
    for (size_t i : layers) {
      const bool is_front = rs.triangles[px.triangle[i]].front;
      if (is_front && back_seen) {
        ++front_behind_back;
        break;
      }
      back_seen = back_seen || !is_front;
    }
  }
  EXPECT_EQ(transparent_objects.size(), 1u) << "one object overlaps itself";
  EXPECT_GT(four_deep, 1000);
  EXPECT_GT(front_behind_back, 1000);
}

// coplanar: pixels with two fragments at exactly equal depth from different primitives with
// different colours: an opaque pair, a transparent pair, and a transparent decal on an opaque
// wall submitted before it.
TEST(SceneSuiteCoplanar, EqualDepthsFromDifferentPrimitivesAndColours) {
  const Scene s = *builtin_scene("coplanar");
  const RasterizedScene rs = rasterize_scene(s, Viewport{kW, kH, kDefaultDepthBits});
  const PixelFragments px = by_pixel(rs);
  int opaque_pairs = 0, glass_pairs = 0, decal_first = 0;
  for (const std::vector<size_t>& frags : px.at) {
    bool op = false, gl = false, dc = false;
    for (size_t a = 0; a < frags.size(); ++a)
      for (size_t b = a + 1; b < frags.size(); ++b) {
        const Fragment &fa = rs.fragments[frags[a]], &fb = rs.fragments[frags[b]];
        if (fa.prim == fb.prim || fa.z != fb.z || rs.z_exact[frags[a]] != rs.z_exact[frags[b]] ||
            fa.color == fb.color)
          continue;
        const bool ta = fa.color.a < 255, tb = fb.color.a < 255;  // a submitted before b
        op = op || (!ta && !tb);
        gl = gl || (ta && tb);
        dc = dc || (ta && !tb);
      }
    opaque_pairs += op, glass_pairs += gl, decal_first += dc;
  }
  EXPECT_GT(opaque_pairs, 1000);
  EXPECT_GT(glass_pairs, 1000);
  EXPECT_GT(decal_first, 1000);
}

// particles: at least 40 transparent layers at the centre of the frame, and their submit order
// is not their depth order.
TEST(SceneSuiteParticles, FortyLayersAtTheCentreInNoDepthOrder) {
  for (const auto& [w, h] : {std::pair{kW, kH}, {96, 72}, {640, 480}}) {
    const RasterizedScene rs = raster("particles", w, h);
    const PixelFragments px = by_pixel(rs);
    std::vector<uint32_t> z;
    for (size_t i : px.at[size_t(h / 2) * w + w / 2])
      if (rs.triangles[px.triangle[i]].transparent) z.push_back(rs.fragments[i].z);
    EXPECT_GE(z.size(), 40u) << w << "x" << h;
    EXPECT_FALSE(std::is_sorted(z.begin(), z.end()));
    EXPECT_FALSE(std::is_sorted(z.rbegin(), z.rend()));
  }
}

// seam: inside the sphere, away from its outline, coverage-aa differs from the reference by
// more than 16/255, and is darker there than every facet around the pixel: the black backdrop
// leaks in. `opaque` matches the reference exactly at the same pixels.
TEST(SceneSuiteSeam, CoverageAaLeaksTheBackdropWhereOpaqueIsExact) {
  const Scene s = *builtin_scene("seam");
  const RasterizedScene rs = rasterize_scene(s, Viewport{kW, kH, kDefaultDepthBits});
  const PixelFragments px = by_pixel(rs);
  const std::vector<size_t> obj = object_of_prim(s);
  const size_t sphere = object_index(s, "sphere");
  auto on_sphere = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= kW || y >= kH) return false;
    for (size_t i : px.at[size_t(y) * kW + x])
      if (obj[rs.fragments[i].prim] == sphere) return true;
    return false;
  };
  // Interior: the pixel's 5 x 5 neighbourhood is all on the sphere.
  auto interior = [&](int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        if (!on_sphere(x + dx, y + dy)) return false;
    return true;
  };
  // Per channel, the darkest sphere facet among the pixel's 3 x 3 neighbourhood.
  auto darkest_facet = [&](int x, int y) {
    Rgba8 d{255, 255, 255, 255};
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (size_t i : px.at[size_t(y + dy) * kW + x + dx]) {
          if (obj[rs.fragments[i].prim] != sphere) continue;
          const Rgba8 c = rs.fragments[i].color;
          d = {std::min(d.r, c.r), std::min(d.g, c.g), std::min(d.b, c.b), 255};
        }
    return d;
  };
  const Framebuffer ref = render_reference(rs);
  GoldenRop rop_aa, rop_opaque;
  const Framebuffer aa = render(rs, *find_plan("coverage-aa"), rop_aa).framebuffer;
  const Framebuffer opaque = render(rs, *find_plan("opaque"), rop_opaque).framebuffer;
  int inside = 0, wrong = 0, leaks = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (!interior(x, y)) continue;
      ++inside;
      const size_t p = ref.index(x, y);
      EXPECT_EQ(opaque.color[p], ref.color[p]) << "opaque at " << x << "," << y;
      if (channel_diff(aa.color[p], ref.color[p]) <= 16) continue;
      ++wrong;
      const Rgba8 a = aa.color[p], d = darkest_facet(x, y);
      leaks += a.r + 16 < d.r || a.g + 16 < d.g || a.b + 16 < d.b;
    }
  EXPECT_GT(inside, 5000);
  EXPECT_GT(wrong, inside / 10) << "coverage-aa fails inside the object";
  EXPECT_GT(leaks, wrong * 3 / 4) << "mostly the backdrop showing through";
}

// hidden-line: the plates' large faces range from facing the eye to 89 degrees away, so the
// steepest one's depth slope per pixel is many times the others'.
TEST(SceneSuiteHiddenLine, PlatesFromFlatToNearlyEdgeOn) {
  const Scene s = *builtin_scene("parts");
  const RasterizedScene rs = rasterize_scene(s, Viewport{kW, kH, kDefaultDepthBits});
  const std::vector<size_t> obj = object_of_prim(s);
  std::vector<size_t> first_prim(s.objects.size() + 1, 0);
  for (size_t o = 0; o < s.objects.size(); ++o)
    first_prim[o + 1] = first_prim[o] + s.objects[o].mesh.triangles.size();
  // Largest |dz/dx| + |dz/dy| (window depth units per pixel) over the triangles of a plate's
  // large front face (object-space normal +z).
  auto slope = [&](const std::string& plate) {
    const size_t o = object_index(s, plate);
    double best = 0;
    for (const ScreenTriangle& t : rs.triangles) {
      if (obj[t.prim] != o) continue;
      const Mesh& m = s.objects[o].mesh;
      if (m.normals[m.triangles[t.prim - first_prim[o]].x].z < 0.99f) continue;
      const double x1 = t.v[1].x - t.v[0].x, y1 = t.v[1].y - t.v[0].y;
      const double x2 = t.v[2].x - t.v[0].x, y2 = t.v[2].y - t.v[0].y;
      const double z1 = double(t.v[1].z) - t.v[0].z, z2 = double(t.v[2].z) - t.v[0].z;
      const double det = x1 * y2 - x2 * y1;
      const double dzdx = (z1 * y2 - z2 * y1) / det * kSubpixelOne;
      const double dzdy = (x1 * z2 - x2 * z1) / det * kSubpixelOne;
      best = std::max(best, std::fabs(dzdx) + std::fabs(dzdy));
    }
    EXPECT_GT(best, 0.0) << plate << " front face not drawn";
    return best;
  };
  const double s0 = slope("plate_0"), s60 = slope("plate_60"), s85 = slope("plate_85"),
               s89 = slope("plate_89");
  EXPECT_LT(s0, s60);
  EXPECT_LT(s60, s85);
  EXPECT_LT(s85, s89);
  // tan 89 / tan 60 is 33; perspective changes it a little, not tenfold.
  EXPECT_GT(s89, 10 * s60);
}

}  // namespace
}  // namespace zb
