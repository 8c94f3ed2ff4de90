// The oracle's own pieces against cases worked by hand: GL's fill rule in both window-y
// directions, the frame comparison, and the exact-depth replay.
#include <gtest/gtest.h>

#include "exact_depth.h"
#include "frame_diff.h"
#include "gl_render.h"
#include "pipeline/render.h"
#include "rop/rop.h"

namespace zb::oracle {
namespace {

constexpr Rgba8 kWhite{255, 255, 255, 255};
constexpr Rgba8 kRed{255, 0, 0, 255};
constexpr Rgba8 kBlue{0, 0, 255, 255};

ClipTriangle triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, Rgba8 color, float z = 0) {
  ClipTriangle t;
  t.clip[0] = {a, z, 1};
  t.clip[1] = {b, z, 1};
  t.clip[2] = {c, z, 1};
  t.color = color;
  return t;
}

// Two triangles share a horizontal edge at y_ndc = -0.125: window y 4.5 of an 8-row frame, the
// centres of row 4. Red is above it in the picture, blue below.
std::vector<ClipTriangle> shared_edge() {
  return {triangle({-1, 1}, {-1, -0.125f}, {1, -0.125f}, kRed),
          triangle({-1, -0.125f}, {-1, -1}, {1, -0.125f}, kBlue)};
}

TEST(OracleGl, FillRuleMeetsTheGoldenModelWithWindowYDown) {
  GlContext gl(8, 8);
  const PassPlan& opaque = *find_plan("opaque");
  const Framebuffer down = render_gl(gl, shared_edge(), opaque, kWhite, WindowY::kDown);
  const Framebuffer up = render_gl(gl, shared_edge(), opaque, kWhite, WindowY::kUp);
  EXPECT_EQ(down.color_at(0, 3), kRed);
  EXPECT_EQ(down.color_at(0, 4), kBlue);  // the top-left rule, y down: the triangle below
  EXPECT_EQ(up.color_at(0, 4), kRed);     // GL's own frame, y up: the triangle above

  // The golden model on the same triangles.
  Scene scene;
  scene.materials = {Material{"m", kWhite}};
  const Viewport vp{8, 8};
  std::vector<ScreenTriangle> screen;
  for (const ClipTriangle& t : shared_edge()) {
    ScreenTriangle s;
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(clip_to_window(t.clip[k], vp, s.v[k]));
    s.color = t.color;
    screen.push_back(s);
  }
  GoldenRop golden;
  const Framebuffer g =
      render(rasterize_triangles(screen, vp, kWhite), opaque, golden).framebuffer;
  EXPECT_EQ(diff_frames(g, down).identical, 64u);
  EXPECT_EQ(diff_frames(g, up).identical, 56u);  // row 4 differs
}

TEST(OracleGl, CullingAndDepthFollowThePlan) {
  GlContext gl(4, 4);
  // A clockwise (back-facing) full-screen pair in front of a counter-clockwise one.
  const std::vector<ClipTriangle> tris = {
      triangle({-1, -1}, {3, -1}, {-1, 3}, kBlue, 0.5f),          // front, far
      triangle({-1, -1}, {-1, 3}, {3, -1}, kRed, -0.5f)};         // back, near
  EXPECT_EQ(render_gl(gl, tris, *find_plan("opaque"), kWhite).color_at(1, 1), kRed);
  PassPlan cull_back = *find_plan("opaque");
  cull_back.passes[0].cull = Cull::kBack;
  const Framebuffer f = render_gl(gl, tris, cull_back, kWhite);
  EXPECT_EQ(f.color_at(1, 1), kBlue);
  EXPECT_EQ(f.depth_at(1, 1), 0xbfffffu);  // 0.75 x (2^24 - 1) = 12582911.25, rounded
}

TEST(OracleGl, RefusesPlansItCannotDraw) {
  EXPECT_TRUE(unsupported_reason(*find_plan("three-pass")).empty());
  EXPECT_NE(unsupported_reason(*find_plan("coverage-aa")).find("blend 'coverage'"),
            std::string::npos);
  EXPECT_NE(unsupported_reason(*find_plan("hidden-line")).find("edges"), std::string::npos);
  EXPECT_FALSE(unsupported_reason(*find_plan("facing-additive")).empty());
  EXPECT_FALSE(unsupported_reason(*find_plan("depth-peel-2")).empty());
}

TEST(FrameDiff, CountsAndLocates) {
  Framebuffer a(3, 2, 24, kWhite), b(3, 2, 24, kWhite);
  b.color[b.index(2, 0)] = Rgba8{250, 255, 255, 255};
  b.color[b.index(1, 1)] = Rgba8{255, 255, 255, 0};
  b.depth[b.index(0, 1)] = 7;
  const FrameDiff d = diff_frames(a, b);
  EXPECT_EQ(d.pixels, 6u);
  EXPECT_EQ(d.identical, 4u);
  EXPECT_EQ(d.max_diff, 255);
  EXPECT_EQ(d.first_x, 2);
  EXPECT_EQ(d.first_y, 0);
  EXPECT_EQ(d.depth_identical, 5u);
  EXPECT_EQ(d.max_depth_diff, depth_max(24) - 7);
  const Framebuffer img = diff_image(a, b);
  EXPECT_EQ(img.color_at(2, 0).g, 0);    // red
  EXPECT_GT(img.color_at(0, 0).g, 191);  // grey
  EXPECT_THROW(diff_frames(a, Framebuffer(2, 2, 24, kWhite)), std::invalid_argument);
}

TEST(ExactDepth, OrdersByUnroundedDepth) {
  // Two one-pixel-covering triangles whose rounded depths tie but whose exact depths do not:
  // the replay keeps the exactly nearer one, the datapath (LESS on a tie) the first.
  const Viewport vp{1, 1};
  ScreenTriangle a, b;
  const ScreenVertex corners[3] = {{-256, -256, 100, 0}, {3 * 256, -256, 100, 0},
                                   {-256, 3 * 256, 100, 0}};
  for (int k = 0; k < 3; ++k) a.v[k] = b.v[k] = corners[k];
  a.color = kRed;
  b.color = kBlue;
  RasterizedScene rs = rasterize_triangles({a, b}, vp, kWhite);
  ASSERT_EQ(rs.fragments.size(), 2u);
  rs.z_exact = {100.4 / depth_max(24), 99.6 / depth_max(24)};
  const PassPlan& opaque = *find_plan("opaque");
  GoldenRop golden;
  EXPECT_EQ(render(rs, opaque, golden).framebuffer.color_at(0, 0), kRed);
  EXPECT_EQ(replay_exact_depth(rs, opaque, {0}), std::vector<Rgba8>{kBlue});
}

}  // namespace
}  // namespace zb::oracle
