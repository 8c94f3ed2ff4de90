// hidden-line (US 5,359,704): the line rule, unique edges, the depth offset and the passes,
// against values worked out here; edges without gaps on faces tilted 0, 60, 85 and 89 degrees.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>

#include "geometry/edges.h"
#include "support/layers.h"
#include "raster/edge_lift.h"
#include "raster/lines.h"
#include "metrics/line_metrics.h"
#include "pipeline/passes.h"
#include "reference/line_reference.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"
#include "scene/meshes.h"

namespace {

using zb::Fragment;
using zb::Rgba8;
using zb::ScreenVertex;

constexpr int32_t kPx = zb::kSubpixelOne;

std::vector<Fragment> line(ScreenVertex a, ScreenVertex b, int w = 16, int h = 16) {
  std::vector<Fragment> out;
  zb::rasterize_line(a, b, {w, h, 24}, Rgba8{0, 0, 0, 255}, 7, out);
  return out;
}

struct Px {
  int x, y;
  uint32_t z;
};

void expect_pixels(const std::vector<Fragment>& got, const std::vector<Px>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].x, want[i].x) << i;
    EXPECT_EQ(got[i].y, want[i].y) << i;
    EXPECT_EQ(got[i].z, want[i].z) << i;
    EXPECT_EQ(got[i].prim, 7u);
  }
}

TEST(LineRule, XMajorCentreToCentre) {
  // (0.5, 0.5) -> (4.5, 2.5): one pixel per column 0..4; at column i the line is at
  // y = 0.5 + i/2, row floor(y): 0, 1, 1, 2, 2 (y = 1.0 and 2.0 lie on a row boundary and go
  // to the row below). Depth 0 -> 1000: 1000 i / 4 exactly.
  const ScreenVertex a{kPx / 2, kPx / 2, 0, 0}, b{4 * kPx + kPx / 2, 2 * kPx + kPx / 2, 1000, 0};
  const std::vector<Px> want{{0, 0, 0}, {1, 1, 250}, {2, 1, 500}, {3, 2, 750}, {4, 2, 1000}};
  expect_pixels(line(a, b), want);
  expect_pixels(line(b, a), want);  // direction-free
}

TEST(LineRule, YMajorClampedEndsAndRounding) {
  // (2.2, 0.8) -> (3.0, 3.9) in pixels: y-major (dy 3.1 > dx 0.8); rows 0..3 (the cells of
  // both ends). Row 0's centre 0.5 is before the start: evaluated at the start (x 2.2, z 0).
  // Rows 1, 2 at y = 1.5, 2.5; row 3's centre 3.5 is inside. In 1/256 units: start (563, 205),
  // end (768, 998), dM = 793, dm = 205. Row 1: s = 384 - 205 = 179,
  // x = (563*793 + 205*179) / 793 = 609.27 -> column 2; z = (0*614 + 100*179 + 396) / 793 = 23.
  // Row 2: s = 435, x = 675.45 -> column 2; z = (43500 + 396) / 793 = 55.35 -> 55.
  // Row 3: s = 691, x = 741.63 -> column 2; z = (69100 + 396) / 793 = 87.6 -> 87.
  const ScreenVertex a{563, 205, 0, 0}, b{768, 998, 100, 0};
  const std::vector<Px> want{{2, 0, 0}, {2, 1, 23}, {2, 2, 55}, {2, 3, 87}};
  expect_pixels(line(a, b), want);
  expect_pixels(line(b, a), want);
}

TEST(LineRule, ShortLineIsOneFragmentAndPointTakesNearerDepth) {
  expect_pixels(line({5 * kPx + 10, 3 * kPx + 10, 40, 0}, {5 * kPx + 90, 3 * kPx + 60, 60, 0}),
                {{5, 3, 60}});  // centre 5.5 is past the end (5.35): evaluated at the end, z1
  expect_pixels(line({5 * kPx + 10, 3 * kPx + 10, 40, 0}, {5 * kPx + 10, 3 * kPx + 10, 30, 0}),
                {{5, 3, 30}});
}

TEST(LineRule, ScissoredToTheViewport) {
  // From (-3.5, 1.5) to (20.5, 1.5) on a 16-wide frame: columns 0..15 only.
  const auto f = line({-3 * kPx - kPx / 2, kPx + kPx / 2, 0, 0}, {20 * kPx + kPx / 2, kPx + kPx / 2, 0, 0});
  ASSERT_EQ(f.size(), 16u);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(f[i].x, i);
}

TEST(LineRule, EveryLineIsEightConnectedAndCoversItsMajorSpan) {
  uint32_t seed = 12345;
  auto rnd = [&](int n) { seed = seed * 1664525u + 1013904223u; return int((seed >> 8) % uint32_t(n)); };
  for (int it = 0; it < 2000; ++it) {
    const ScreenVertex a{rnd(64 * kPx), rnd(64 * kPx), uint32_t(rnd(1 << 24)), 0};
    const ScreenVertex b{rnd(64 * kPx), rnd(64 * kPx), uint32_t(rnd(1 << 24)), 0};
    const auto f = line(a, b, 64, 64);
    const bool x_major = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
    const int lo = (x_major ? std::min(a.x, b.x) : std::min(a.y, b.y)) / kPx;
    const int hi = (x_major ? std::max(a.x, b.x) : std::max(a.y, b.y)) / kPx;
    ASSERT_EQ(f.size(), size_t(hi - lo + 1));
    for (size_t i = 0; i < f.size(); ++i) {
      EXPECT_EQ(x_major ? f[i].x : f[i].y, lo + int(i));
      EXPECT_GE(f[i].z, std::min(a.z, b.z));
      EXPECT_LE(f[i].z, std::max(a.z, b.z));
      if (i) {
        EXPECT_LE(std::abs(x_major ? f[i].y - f[i - 1].y : f[i].x - f[i - 1].x), 1);
      }
    }
  }
}

// --- unique edges --------------------------------------------------------------------------

TEST(Edges, UniquePerMeshEulerCounts) {
  EXPECT_EQ(zb::unique_edges(zb::make_quad(1, 1)).size(), 5u);   // 4 sides + the diagonal
  // A box: 12 sides + 6 face diagonals, though make_box gives each face its own vertices.
  EXPECT_EQ(zb::unique_edges(zb::make_box({1, 2, 3})).size(), 18u);
  // Closed sphere: E = 3F/2, F = 2 slices (stacks - 1).
  EXPECT_EQ(zb::unique_edges(zb::make_sphere(1, 32, 16)).size(), 3u * 32 * 15);
  const auto q = zb::unique_edges(zb::make_quad(1, 1));  // triangles (0 1 2), (0 2 3)
  const std::vector<std::pair<uint32_t, uint32_t>> want{{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 0}};
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(q[i].a, want[i].first);
    EXPECT_EQ(q[i].b, want[i].second);
  }
}

// --- depth offset and the passes on a hand-made scene ---------------------------------------

// One opaque face at constant depth 1000 over the whole 4x4 frame, and horizontal lines along
// row 1 (visible and hidden) with given depths and slopes.
zb::RasterizedScene edge_scene(const std::vector<std::pair<uint32_t, uint32_t>>& z_slope) {
  zb::RasterizedScene rs = zbtest::layer_scene({{1000, {10, 20, 30, 255}}}, {255, 255, 255, 255});
  std::vector<zb::ScreenLine> lines;
  int row = 0;
  for (auto [z, slope] : z_slope) {
    zb::ScreenLine l;
    l.v[0] = {kPx / 2, row * kPx + kPx / 2, z, 0};
    l.v[1] = {3 * kPx + kPx / 2, row * kPx + kPx / 2, z, 0};
    l.depth_slope = slope;
    l.prim = uint32_t(lines.size());
    lines.push_back(l);
    ++row;
  }
  zb::add_lines(rs, lines);
  return rs;
}

zb::RenderResult run(const zb::RasterizedScene& rs, const zb::PassPlan& plan) {
  zb::GoldenRop rop;
  return zb::render(rs, plan, rop);
}

zb::RenderResult run(const zb::RasterizedScene& rs, const char* method) {
  return run(rs, *zb::find_plan(method));
}

TEST(HiddenLine, SlopeOffsetDecidesVisibleAndHidden) {
  ASSERT_EQ(zb::kEdgeSlopeOffset.units, 2u);
  ASSERT_EQ(zb::kEdgeSlopeOffset.slope_q8, 256u);
  // offset = 2 + ceil(256 * slope / 256) = 2 + slope. Row 0: z 1000, slope 0 -> 998 <= 1000:
  // visible. Row 1: z 1302, slope 300 -> 1000: visible (LEQUAL). Row 2: z 1303, slope 300 ->
  // 1001: hidden. Row 3: z 1, slope 5 -> saturates at 0: visible.
  const auto rs = edge_scene({{1000, 0}, {1302, 300}, {1303, 300}, {1, 5}});
  const auto r = run(rs, zb::make_hidden_line_plan(false, zb::kEdgeSlopeOffset));
  const Rgba8 white{255, 255, 255, 255};
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(r.framebuffer.color_at(x, 0), zb::kEdgeColor);
    EXPECT_EQ(r.framebuffer.color_at(x, 1), zb::kEdgeColor);
    EXPECT_EQ(r.framebuffer.color_at(x, 2), white) << "hidden edge removed; faces masked";
    EXPECT_EQ(r.framebuffer.color_at(x, 3), zb::kEdgeColor);
    for (int y = 0; y < 4; ++y) EXPECT_EQ(r.framebuffer.depth_at(x, y), 1000u) << "edges write no depth";
  }
  const auto d = run(rs, zb::make_hidden_line_plan(true, zb::kEdgeSlopeOffset));
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(d.framebuffer.color_at(x, 1), zb::kEdgeColor);
    EXPECT_EQ(d.framebuffer.color_at(x, 2), zb::kHiddenEdgeColor);
  }
  ASSERT_EQ(r.passes.size(), 2u);
  EXPECT_EQ(r.passes[0].color_writes, 0u);
  EXPECT_EQ(r.passes[1].fragments_in, 16u);
  EXPECT_EQ(r.passes[1].fragments_passed, 12u);
  // A clamp (Vulkan's depthBiasClamp) limits the whole offset: at most 150 units, row 1's
  // 1302 - 150 = 1152 fails.
  zb::DepthOffset clamped = zb::kEdgeSlopeOffset;
  clamped.clamp = 150;
  const auto c = run(rs, zb::make_hidden_line_plan(false, clamped));
  EXPECT_EQ(c.framebuffer.color_at(0, 0), zb::kEdgeColor);
  EXPECT_EQ(c.framebuffer.color_at(0, 1), white);
}

// The offset from the edge's own faces (the default: no units beyond them): a line fragment at
// z takes min(z, its faces' plane at the centre), then `units` less. The face here is the
// frame-wide layer at 1000.
TEST(HiddenLine, FacesOffsetLiftsEdgesToTheirOwnFaces) {
  ASSERT_TRUE(zb::kEdgeOffset.faces) << "the plans' default";
  zb::RasterizedScene rs = zbtest::layer_scene({{1000, {10, 20, 30, 255}}}, {255, 255, 255, 255});
  const zb::ScreenTriangle& layer = rs.triangles[0];
  // Row y's line at depth z, its one face the layer on `side` (0: no face).
  auto line_at = [&](int row, int32_t y, uint32_t z, int side) {
    zb::ScreenLine l;
    l.v[0] = {kPx / 2, y, z, 0};
    l.v[1] = {3 * kPx + kPx / 2, y, z, 0};
    l.prim = uint32_t(row);
    if (side != 0) {
      l.faces[0].prim = layer.prim;
      for (int k = 0; k < 3; ++k) l.faces[0].v[k] = layer.v[k];
      l.faces[0].side = side;
    }
    return l;
  };
  // Row 0: along the centres (y = 0.5), 40 behind its face: lifted to 1000, drawn (LEQUAL).
  // Row 1: the same depth without a face: 1040, hidden. Row 2: along y = 2.0 (its fragments'
  // centres below the line, side +1) with its face above (side -1): the face is not on the
  // centre's side, so no lift: hidden. Row 3: in front of its face (900): kept, visible.
  zb::add_lines(rs, {line_at(0, kPx / 2, 1040, -1), line_at(1, kPx + kPx / 2, 1040, 0),
                     line_at(2, 2 * kPx, 1040, -1), line_at(3, 3 * kPx + kPx / 2, 900, 1)});
  const zb::PassState& edges = zb::find_plan("hidden-line")->passes[1];
  const std::vector<Fragment> fed = zb::pass_fragments(rs, edges);
  ASSERT_EQ(fed.size(), 16u);
  ASSERT_EQ(zb::kEdgeOffset.units, 0u);
  const uint32_t want[4] = {1000, 1040, 1040, 900};
  for (const Fragment& f : fed) EXPECT_EQ(f.z, want[f.y]) << f.x << "," << f.y;
  const auto r = run(rs, "hidden-line");
  const Rgba8 white{255, 255, 255, 255};
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(r.framebuffer.color_at(x, 0), zb::kEdgeColor);
    EXPECT_EQ(r.framebuffer.color_at(x, 1), white);
    EXPECT_EQ(r.framebuffer.color_at(x, 2), white);
    EXPECT_EQ(r.framebuffer.color_at(x, 3), zb::kEdgeColor);
  }
  // Row 2's face on the centre's side: lifted. With 2 units more, 2 in front of it.
  zb::add_lines(rs, {line_at(2, 2 * kPx, 1040, 1)});
  for (const Fragment& f : zb::pass_fragments(rs, edges)) EXPECT_EQ(f.z, 1000u);
  zb::PassState two = edges;
  two.offset.units = 2;
  for (const Fragment& f : zb::pass_fragments(rs, two)) EXPECT_EQ(f.z, 998u);
}

// own_face_depth by hand. Face F below y = 1 (pixels): (0, 1), (8, 1) at 1000, (0, 9) at 200,
// so 1000 - 100 (y - 1); face G above it: (0, 1), (8, 1) at 1000, (0, -7) at 200. The edge is
// their shared side, from (0.5, 1) to (7.5, 1). At pixel (3, 1) the centre (3.5, 1.5) lies
// below: F's plane there is 950 (weights 2097152, 1835008, 262144 of A = 4194304:
// (3932160000 + 52428800 + 2097152) / 4194304 = 950.5, floored). At (3, 0), above: G's, 950.
TEST(HiddenLine, OwnFaceDepthByHand) {
  auto v = [](double x, double y, uint32_t z) {
    return ScreenVertex{int32_t(x * kPx), int32_t(y * kPx), z, 0};
  };
  zb::ScreenLine l;
  l.v[0] = v(0.5, 1, 1000);
  l.v[1] = v(7.5, 1, 1000);
  const ScreenVertex f[3] = {v(0, 1, 1000), v(8, 1, 1000), v(0, 9, 200)};
  const ScreenVertex g[3] = {v(0, 1, 1000), v(8, 1, 1000), v(0, -7, 200)};
  for (int k = 0; k < 3; ++k) {
    l.faces[0].v[k] = f[k];
    l.faces[1].v[k] = g[k];
  }
  l.faces[0].prim = 10;
  l.faces[0].side = 1;
  l.faces[1].prim = 11;
  l.faces[1].side = -1;
  EXPECT_EQ(zb::line_side(l, 3 * kPx + kPx / 2, kPx + kPx / 2) > 0, true);
  EXPECT_EQ(zb::own_face_depth(l, 3, 1, 7777), 950u);
  EXPECT_EQ(zb::own_face_depth(l, 3, 0, 7777), 950u);
  EXPECT_EQ(zb::face_lift(l, 3, 1, 1000), 50u);
  EXPECT_EQ(zb::face_lift(l, 3, 1, 900), 0u);
  l.faces[1].prim = zb::kNoFace;  // no face above: nothing to lift to there
  EXPECT_EQ(zb::own_face_depth(l, 3, 0, 7777), 7777u);
}

// A unit quad facing the camera at 64x48: two triangles sharing the diagonal, 5 unique edges.
zb::RasterizedScene facing_quad() {
  zb::Scene s;
  s.materials.push_back({"m", {100, 100, 100, 255}});
  s.objects.push_back({"quad", zb::make_quad(1.0f, 1.0f), 0, glm::mat4(1.0f)});
  s.camera.eye = {0, 0, 4};
  s.camera.near = 1;
  s.camera.far = 10;
  return zb::rasterize_scene(s, {64, 48, 24});
}

// setup_lines hands each edge its own faces: a quad's diagonal has both triangles, one on each
// side; a side has one.
TEST(HiddenLine, EdgesCarryTheirOwnFaces) {
  const zb::RasterizedScene rs = facing_quad();
  ASSERT_EQ(rs.lines.size(), 5u);
  const zb::ScreenLine& diag = rs.lines[2];  // (2, 0), in triangles (0 1 2) and (0 2 3)
  EXPECT_EQ(diag.faces[0].prim, 0u);
  EXPECT_EQ(diag.faces[1].prim, 1u);
  EXPECT_EQ(diag.faces[0].side, -diag.faces[1].side);
  EXPECT_NE(diag.faces[0].side, 0);
  EXPECT_EQ(rs.lines[0].faces[0].prim, 0u);  // (0, 1): the first triangle only
  EXPECT_EQ(rs.lines[0].faces[1].prim, zb::kNoFace);
  EXPECT_EQ(rs.lines[3].faces[0].prim, 1u);  // (2, 3): the second
  const auto e = zb::unique_edges(zb::make_quad(1, 1));
  EXPECT_EQ(e[2].faces[0], 0u);
  EXPECT_EQ(e[2].faces[1], 1u);
}

TEST(HiddenLine, SharedEdgeDrawnOnce) {
  const zb::RasterizedScene rs = facing_quad();
  ASSERT_EQ(rs.lines.size(), 5u);
  size_t want = 0;
  for (const auto& l : rs.lines) {
    const bool x_major = std::abs(l.v[1].x - l.v[0].x) >= std::abs(l.v[1].y - l.v[0].y);
    const int lo = (x_major ? std::min(l.v[0].x, l.v[1].x) : std::min(l.v[0].y, l.v[1].y)) / kPx;
    const int hi = (x_major ? std::max(l.v[0].x, l.v[1].x) : std::max(l.v[0].y, l.v[1].y)) / kPx;
    want += size_t(hi - lo + 1);
  }
  const auto edges = zb::pass_fragments(rs, zb::find_plan("hidden-line")->passes[1]);
  EXPECT_EQ(edges.size(), want);
  // Away from the corners every pixel of the diagonal gets exactly one fragment.
  std::map<std::pair<int, int>, int> count;
  for (const Fragment& f : edges) ++count[{f.x, f.y}];
  const auto& diag = rs.lines[2];  // edge (2, 0): the diagonal, third in first-seen order
  const int cx = (diag.v[0].x + diag.v[1].x) / 2 / kPx;
  int on_diagonal = 0;
  for (const Fragment& f : edges)
    if (f.prim == diag.prim && std::abs(f.x - cx) < 5) {
      EXPECT_EQ((count[{f.x, f.y}]), 1) << f.x << "," << f.y;
      ++on_diagonal;
    }
  EXPECT_GE(on_diagonal, 9);
}

// --- faces tilted 0, 60, 85 and 89 degrees: no gaps ----------------------------------------

TEST(HiddenLine, NoGapsOnTiltedFaces) {
  const zb::Scene s = *zb::builtin_scene("parts");
  const char* plates[4] = {"plate_0", "plate_60", "plate_85", "plate_89"};
  for (int w : {320, 640, 1280}) {
    const zb::Viewport vp{w, w * 3 / 4, 24};
    const zb::RasterizedScene rs = zb::rasterize_scene(s, vp);
    const zb::RenderResult r = run(rs, "hidden-line");
    uint32_t edge_base = 0;
    for (const zb::Object& o : s.objects) {
      const auto edges = zb::unique_edges(o.mesh);
      for (int i = 0; i < 4; ++i) {
        if (o.name != plates[i]) continue;
        // The large face toward the eye is the box's +z face (local z = +0.06): its four sides
        // and diagonal are visible; every pixel the line rule gives them must be drawn.
        int checked = 0;
        for (size_t e = 0; e < edges.size(); ++e) {
          if (!(o.mesh.positions[edges[e].a].z > 0 && o.mesh.positions[edges[e].b].z > 0)) continue;
          const zb::ScreenLine* l = nullptr;
          for (const auto& cand : rs.lines)
            if (cand.prim == edge_base + e) l = &cand;
          ASSERT_NE(l, nullptr);
          std::vector<Fragment> px;
          zb::rasterize_line(l->v[0], l->v[1], vp, zb::kEdgeColor, 0, px);
          ASSERT_FALSE(px.empty());
          for (const Fragment& f : px)
            EXPECT_EQ(r.framebuffer.color_at(f.x, f.y), zb::kEdgeColor)
                << o.name << " at " << w << ": gap at (" << f.x << "," << f.y << ")";
          ++checked;
        }
        EXPECT_EQ(checked, 5) << o.name;
      }
      edge_base += uint32_t(edges.size());
    }
  }
}

// The silhouette leak: on cad the sphere lies wholly inside the box, so every edge
// pixel of the sphere's is hidden by the box's front faces. The polygon offset lifted the
// sphere's silhouette edges (their faces seen edge-on, slopes without bound) through them; the
// plans' offset keeps them behind. Measured against the exact line reference at the README's
// 400x300.
TEST(HiddenLine, NoSilhouetteLeakOnCad) {
  const zb::Scene cad = *zb::builtin_scene("cad");
  const zb::RasterizedScene rs = zb::rasterize_scene(cad, {400, 300, 24});
  const zb::LineVisibility truth = zb::line_visibility(rs);
  // The inner shell's edges (the second object's), every pixel of which is hidden.
  const uint32_t box_edges = uint32_t(zb::unique_edges(cad.objects[0].mesh).size());
  const uint32_t sphere_edges = uint32_t(zb::unique_edges(cad.objects[1].mesh).size());
  std::vector<bool> sphere_px(size_t(400 * 300), false);
  for (const Fragment& f : rs.line_fragments)
    if (f.prim >= box_edges && f.prim < box_edges + sphere_edges)
      sphere_px[size_t(f.y) * 400 + f.x] = true;
  size_t sphere_hidden = 0;
  for (size_t p = 0; p < sphere_px.size(); ++p)
    sphere_hidden += sphere_px[p] && truth.pixels[p] == zb::EdgePixel::kHidden;
  ASSERT_GT(sphere_hidden, 1000u);
  auto leaked = [&](const zb::Framebuffer& fb) {
    size_t n = 0;
    for (size_t p = 0; p < sphere_px.size(); ++p)
      n += sphere_px[p] && truth.pixels[p] == zb::EdgePixel::kHidden && fb.color[p] == zb::kEdgeColor;
    return n;
  };
  const auto old = run(rs, zb::make_hidden_line_plan(false, zb::kEdgeSlopeOffset));
  const auto now = run(rs, "hidden-line");
  EXPECT_GT(leaked(old.framebuffer), 100u) << "the polygon offset's leak, as the README showed it";
  EXPECT_EQ(leaked(now.framebuffer), 0u) << "sphere edges drawn through the box's front";
  const zb::LineError e = zb::compare_lines(now.framebuffer, truth, zb::kEdgeColor);
  EXPECT_LT(e.hidden_drawn_share(), 0.002);
  EXPECT_LT(e.visible_missing_share(), 0.01);
  EXPECT_GT(zb::compare_lines(old.framebuffer, truth, zb::kEdgeColor).hidden_drawn_share(), 0.01);
}

TEST(HiddenLine, HiddenEdgesOfTheBackBlockAreGoneOrDimmed) {
  const zb::RasterizedScene rs = zb::rasterize_scene(*zb::builtin_scene("parts"), {640, 480, 24});
  const auto plain = run(rs, "hidden-line");
  const auto dim = run(rs, "hidden-line-dim");
  size_t hidden_px = 0, dimmed_px = 0;
  for (size_t i = 0; i < plain.framebuffer.color.size(); ++i) {
    EXPECT_NE(plain.framebuffer.color[i], zb::kHiddenEdgeColor);
    dimmed_px += dim.framebuffer.color[i] == zb::kHiddenEdgeColor;
    // Every pixel black in the plain image is black in the dim one (visible edges win).
    if (plain.framebuffer.color[i] == zb::kEdgeColor) {
      EXPECT_EQ(dim.framebuffer.color[i], zb::kEdgeColor);
    }
    hidden_px += plain.framebuffer.color[i] == Rgba8{255, 255, 255, 255} &&
                 dim.framebuffer.color[i] == zb::kHiddenEdgeColor;
  }
  EXPECT_EQ(hidden_px, dimmed_px);
  EXPECT_GT(dimmed_px, 500u);
}

}  // namespace
