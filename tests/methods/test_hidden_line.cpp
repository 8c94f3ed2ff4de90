// hidden-line (US 5,359,704): the line rule, unique edges, the depth offset and the passes,
// against values worked out here; edges without gaps on faces tilted 0, 60, 85 and 89 degrees.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>

#include "geometry/edges.h"
#include "support/layers.h"
#include "raster/lines.h"
#include "pipeline/passes.h"
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

zb::RenderResult run(const zb::RasterizedScene& rs, const char* method) {
  zb::GoldenRop rop;
  return zb::render(rs, *zb::find_plan(method), rop);
}

TEST(HiddenLine, OffsetDecidesVisibleAndHidden) {
  ASSERT_EQ(zb::kEdgeOffset.units, 2u);
  ASSERT_EQ(zb::kEdgeOffset.slope_q8, 256u);
  // offset = 2 + ceil(256 * slope / 256) = 2 + slope. Row 0: z 1000, slope 0 -> 998 <= 1000:
  // visible. Row 1: z 1302, slope 300 -> 1000: visible (LEQUAL). Row 2: z 1303, slope 300 ->
  // 1001: hidden. Row 3: z 1, slope 5 -> saturates at 0: visible.
  const auto rs = edge_scene({{1000, 0}, {1302, 300}, {1303, 300}, {1, 5}});
  const auto r = run(rs, "hidden-line");
  const Rgba8 white{255, 255, 255, 255};
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(r.framebuffer.color_at(x, 0), zb::kEdgeColor);
    EXPECT_EQ(r.framebuffer.color_at(x, 1), zb::kEdgeColor);
    EXPECT_EQ(r.framebuffer.color_at(x, 2), white) << "hidden edge removed; faces masked";
    EXPECT_EQ(r.framebuffer.color_at(x, 3), zb::kEdgeColor);
    for (int y = 0; y < 4; ++y) EXPECT_EQ(r.framebuffer.depth_at(x, y), 1000u) << "edges write no depth";
  }
  const auto d = run(rs, "hidden-line-dim");
  for (int x = 0; x < 4; ++x) {
    EXPECT_EQ(d.framebuffer.color_at(x, 1), zb::kEdgeColor);
    EXPECT_EQ(d.framebuffer.color_at(x, 2), zb::kHiddenEdgeColor);
  }
  ASSERT_EQ(r.passes.size(), 2u);
  EXPECT_EQ(r.passes[0].color_writes, 0u);
  EXPECT_EQ(r.passes[1].fragments_in, 16u);
  EXPECT_EQ(r.passes[1].fragments_passed, 12u);
}

TEST(HiddenLine, SharedEdgeDrawnOnce) {
  // A quad facing the camera: two triangles sharing the diagonal; 5 unique edges.
  zb::Scene s;
  s.materials.push_back({"m", {100, 100, 100, 255}});
  s.objects.push_back({"quad", zb::make_quad(1.0f, 1.0f), 0, glm::mat4(1.0f)});
  s.camera.eye = {0, 0, 4};
  s.camera.near = 1;
  s.camera.far = 10;
  const zb::RasterizedScene rs = zb::rasterize_scene(s, {64, 48, 24});
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
