// The banded renderer (frame_render.h) against the reference path, render(rasterize_scene(),
// plan, GoldenRop): every plane and every pass's statistics bit for bit, for every built-in
// scene and plan, serial and threaded, with bands that cut triangles. And the rasterizers' row
// scissor that makes it exact: the bands' fragments, concatenated, are the whole primitive's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "raster/sample_coverage.h"
#include "geometry/edges.h"
#include "pipeline/frame_render.h"
#include "raster/lines.h"
#include "pipeline/passes.h"
#include "raster/raster.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;

bool same_fragment(const Fragment& a, const Fragment& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.color == b.color && a.front == b.front &&
         a.facing == b.facing && a.coverage == b.coverage && a.prim == b.prim;
}

void expect_same_fragments(const std::vector<Fragment>& got, const std::vector<Fragment>& want,
                           const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (size_t i = 0; i < got.size(); ++i)
    ASSERT_TRUE(same_fragment(got[i], want[i]))
        << what << ": fragment " << i << " at " << want[i].x << "," << want[i].y;
}

ScreenVertex V(int64_t x, int64_t y, uint32_t z) {
  ScreenVertex v;
  v.x = static_cast<int32_t>(x);
  v.y = static_cast<int32_t>(y);
  v.z = z;
  v.z_exact = double(z) / double(depth_max(32));
  return v;
}

// Random triangles over a frame: small, medium, long slivers and huge ones (scissored), with
// mixed facing flags.
std::vector<ScreenTriangle> random_triangles(const Viewport& vp, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> dz(0, depth_max(vp.depth_bits));
  std::vector<ScreenTriangle> out;
  for (int n = 0; n < count; ++n) {
    const int64_t w = int64_t{vp.width} * kSubpixelOne, h = int64_t{vp.height} * kSubpixelOne;
    // Huge, small (the rasterizer's small-box path) and medium.
    const int64_t span = n % 5 == 0   ? (int64_t{1} << 23)
                         : n % 5 == 1 ? 7 * kSubpixelOne
                                      : 40 * kSubpixelOne;
    std::uniform_int_distribution<int64_t> cx(-w / 4, w + w / 4), cy(-h / 4, h + h / 4),
        d(-span, span);
    const int64_t x = cx(rng), y = cy(rng);
    ScreenTriangle t;
    t.v[0] = V(x + d(rng), y + d(rng), dz(rng));
    t.v[1] = V(x + d(rng), y + d(rng), dz(rng));
    if (n % 3 == 0)  // a sliver along v0 -> v1
      t.v[2] = V((t.v[0].x + t.v[1].x) / 2 + d(rng) / 64, (t.v[0].y + t.v[1].y) / 2, dz(rng));
    else
      t.v[2] = V(x + d(rng), y + d(rng), dz(rng));
    t.color = Rgba8{uint8_t(n), uint8_t(n * 7), uint8_t(n * 13), uint8_t(128 + n % 128)};
    t.front = n % 2 == 0;
    for (int k = 0; k < 3; ++k) t.facing[k] = ((n >> k) & 1) != 0;
    t.prim = static_cast<uint32_t>(n);
    out.push_back(t);
  }
  return out;
}

TEST(RowScissor, BandsConcatenatedAreTheWholeTriangle) {
  for (int bits : {16, 24, 32}) {
    const Viewport vp{61, 47, bits, 4};
    for (const ScreenTriangle& t : random_triangles(vp, 400, 77u + uint32_t(bits))) {
      std::vector<Fragment> whole, banded, cov_whole, cov_banded;
      std::vector<double> ze_whole, ze_banded, cz_whole, cz_banded;
      rasterize(t, vp, whole, &ze_whole);
      rasterize_coverage(t, vp, cov_whole, &cz_whole);
      for (int rows : {1, 5, 16}) {
        banded.clear();
        ze_banded.clear();
        cov_banded.clear();
        cz_banded.clear();
        for (int y = -rows; y < vp.height + rows; y += rows) {
          rasterize(t, vp, banded, &ze_banded, RowRange{y, y + rows});
          rasterize_coverage(t, vp, cov_banded, &cz_banded, RowRange{y, y + rows});
        }
        const std::string what = "prim " + std::to_string(t.prim) + ", bands of " +
                                 std::to_string(rows) + ", " + std::to_string(bits) + " bits";
        expect_same_fragments(banded, whole, what);
        expect_same_fragments(cov_banded, cov_whole, "coverage, " + what);
        ASSERT_EQ(ze_banded, ze_whole) << what;
        ASSERT_EQ(cz_banded, cz_whole) << what;
      }
    }
  }
}

TEST(RowScissor, BandsConcatenatedAreTheWholeLine) {
  const Viewport vp{53, 41, 24};
  std::mt19937 rng(5u);
  std::uniform_int_distribution<int64_t> x(-20 * kSubpixelOne, 73 * kSubpixelOne),
      y(-20 * kSubpixelOne, 61 * kSubpixelOne);
  std::uniform_int_distribution<uint32_t> z(0, depth_max(24));
  for (int n = 0; n < 2000; ++n) {
    const ScreenVertex a = V(x(rng), y(rng), z(rng));
    const ScreenVertex b = n % 4 == 0 ? V(a.x + 100, a.y - 30, z(rng)) : V(x(rng), y(rng), z(rng));
    std::vector<Fragment> whole, banded;
    rasterize_line(a, b, vp, Rgba8{0, 0, 0, 255}, uint32_t(n), whole);
    for (int rows : {1, 3, 8}) {
      banded.clear();
      for (int r = 0; r < vp.height; r += rows)
        rasterize_line(a, b, vp, Rgba8{0, 0, 0, 255}, uint32_t(n), banded, RowRange{r, r + rows});
      // Band by band the fragments come row-major; the whole line is in major order. Same set,
      // and the same order within each band's rows.
      std::vector<Fragment> sorted_whole = whole;
      std::stable_sort(
          sorted_whole.begin(), sorted_whole.end(),
          [&](const Fragment& p, const Fragment& q) { return p.y / rows < q.y / rows; });
      expect_same_fragments(banded, sorted_whole, "line " + std::to_string(n));
    }
  }
}

// The incremental depth along a span against the closed formula, on long spans with steep
// depth slopes and 32-bit depth (128-bit products).
TEST(RowScissor, SpanDepthIsTheClosedFormula) {
  const Viewport vp{300, 40, 32};
  for (const ScreenTriangle& t : random_triangles(vp, 600, 9u)) {
    std::vector<Fragment> out;
    rasterize(t, vp, out);
    // Oriented to positive area here, independently of the rasterizer's own setup.
    ScreenVertex v[3] = {t.v[0], t.v[1], t.v[2]};
    i128 area = (i128(v[1].x) - v[0].x) * (i128(v[2].y) - v[0].y) -
                (i128(v[2].x) - v[0].x) * (i128(v[1].y) - v[0].y);
    if (area == 0) {
      ASSERT_TRUE(out.empty());
      continue;
    }
    if (area < 0) {
      std::swap(v[1], v[2]);
      area = -area;
    }
    for (const Fragment& f : out) {
      const i128 px = i128(f.x) * kSubpixelOne + kSubpixelOne / 2;
      const i128 py = i128(f.y) * kSubpixelOne + kSubpixelOne / 2;
      i128 w[3];
      for (int k = 0; k < 3; ++k) {
        const ScreenVertex& a = v[(k + 1) % 3];
        const ScreenVertex& b = v[(k + 2) % 3];
        w[k] = i128(b.x - a.x) * (py - a.y) - i128(b.y - a.y) * (px - a.x);
      }
      const i128 num = w[0] * v[0].z + w[1] * v[1].z + w[2] * v[2].z + area / 2;
      ASSERT_EQ(f.z, static_cast<uint32_t>(num / area)) << "prim " << t.prim;
    }
  }
}

void expect_same_frame(const RenderResult& got, const RenderResult& want, const std::string& what) {
  const Framebuffer& g = got.framebuffer;
  const Framebuffer& w = want.framebuffer;
  ASSERT_EQ(g.width, w.width) << what;
  ASSERT_EQ(g.height, w.height) << what;
  ASSERT_EQ(g.depth_bits, w.depth_bits) << what;
  ASSERT_EQ(g.coverage_samples, w.coverage_samples) << what;
  ASSERT_TRUE(g.color == w.color) << what << ": colour";
  ASSERT_TRUE(g.depth == w.depth) << what << ": depth";
  ASSERT_TRUE(g.coverage == w.coverage) << what << ": coverage";
  ASSERT_TRUE(g.peel == w.peel) << what << ": peel";
  ASSERT_EQ(got.passes.size(), want.passes.size()) << what;
  for (size_t i = 0; i < want.passes.size(); ++i) {
    const PassStats& a = got.passes[i];
    const PassStats& b = want.passes[i];
    const std::string pass = what + ", pass " + std::to_string(i);
    EXPECT_EQ(a.fragments_in, b.fragments_in) << pass;
    EXPECT_EQ(a.fragments_passed, b.fragments_passed) << pass;
    EXPECT_EQ(a.color_reads, b.color_reads) << pass;
    EXPECT_EQ(a.color_writes, b.color_writes) << pass;
    EXPECT_EQ(a.depth_reads, b.depth_reads) << pass;
    EXPECT_EQ(a.depth_writes, b.depth_writes) << pass;
    EXPECT_EQ(a.cycles, b.cycles) << pass;
  }
}

// Every built-in scene, every plan: threads 1, 2 and 3, bands of 7 rows (cutting most
// triangles) and the default.
void check_scene(const Scene& scene, const Viewport& vp) {
  const RasterizedScene rs = rasterize_scene(scene, vp);
  FrameGeometry geometry = make_frame_geometry(scene, vp, true, 2);
  for (const PassPlan& plan : pass_plans()) {
    GoldenRop golden;
    const RenderResult want = render(rs, plan, golden);
    for (const FrameRenderOptions& o :
         {FrameRenderOptions{1, 7}, FrameRenderOptions{2, 7}, FrameRenderOptions{3, 0},
          FrameRenderOptions{3, 7}}) {
      const std::string what = scene.name + " " + plan.name + ", threads " +
                               std::to_string(o.threads) + ", bands " +
                               std::to_string(o.band_rows);
      expect_same_frame(render_frame(geometry, plan, o), want, what);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  // From the scene itself, as zblend render calls it.
  const PassPlan& plan = *find_plan("three-pass");
  GoldenRop golden;
  expect_same_frame(render_frame(scene, vp, plan, FrameRenderOptions{2, 0}),
                    render(rs, plan, golden), scene.name + " from the scene");
}

TEST(FrameRender, EveryBuiltinSceneAndPlanBitExact) {
  for (const SceneInfo& info : builtin_scenes()) {
    SCOPED_TRACE(info.name);
    check_scene(*builtin_scene(info.name), Viewport{203, 157, kDefaultDepthBits});
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(FrameRender, OtherDepthWidthsAndSampleCounts) {
  for (const char* name : {"cad", "sphere-torus"}) {
    SCOPED_TRACE(name);
    check_scene(*builtin_scene(name), Viewport{97, 131, 32, 4});
    if (::testing::Test::HasFatalFailure()) return;
    check_scene(*builtin_scene(name), Viewport{131, 64, 16, 1});
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(FrameRender, BandsBeyondTheRedrawCache) {
  // Wide bands over large transparent quads: a band's triangles drawn again by later passes
  // outgrow the per-thread cache, so some are replayed and some rasterized again.
  const Scene scene = *builtin_scene("quads");
  const Viewport vp{3000, 600, kDefaultDepthBits};
  const RasterizedScene rs = rasterize_scene(scene, vp);
  const FrameGeometry geometry = make_frame_geometry(scene, vp, false, 1);
  for (const char* name : {"three-pass", "depth-peel-2", "facing-additive"}) {
    const PassPlan& plan = *find_plan(name);
    GoldenRop golden;
    const RenderResult want = render(rs, plan, golden);
    expect_same_frame(render_frame(geometry, plan, FrameRenderOptions{2, 200}), want, name);
  }
}

TEST(FrameRender, ParallelSetupIsTheSerialOne) {
  // Enough triangles for the split, across several objects, so parts cut objects.
  Scene scene = *builtin_scene("sphere-torus");
  while (scene.triangle_count() < 20000) {
    const size_t n = scene.objects.size();
    for (size_t i = 0; i < n; ++i) scene.objects.push_back(scene.objects[i]);
  }
  // One object whose vertices have normals only up to some index: its part keeps the whole
  // arrays (which vertices have one depends on the index).
  scene.objects[1].mesh.normals.resize(scene.objects[1].mesh.normals.size() / 2);
  const Viewport vp{203, 157, kDefaultDepthBits};
  const std::vector<ScreenTriangle> want = setup_triangles(scene, vp);
  for (int threads : {2, 3, 5}) {
    const std::vector<ScreenTriangle> got = setup_triangles_parallel(scene, vp, threads);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
      const ScreenTriangle &a = got[i], &b = want[i];
      ASSERT_EQ(a.prim, b.prim) << i;
      ASSERT_TRUE(a.color == b.color && a.front == b.front && a.transparent == b.transparent) << i;
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(a.v[k].x, b.v[k].x) << i;
        ASSERT_EQ(a.v[k].y, b.v[k].y) << i;
        ASSERT_EQ(a.v[k].z, b.v[k].z) << i;
        ASSERT_EQ(a.v[k].z_exact, b.v[k].z_exact) << i;
        ASSERT_EQ(a.facing[k], b.facing[k]) << i;
      }
    }
  }
  // A bad scene fails with the serial setup's own message.
  scene.objects.back().mesh.triangles.back().x = 1u << 30;
  std::string want_error, got_error;
  try {
    setup_triangles(scene, vp);
  } catch (const std::invalid_argument& e) {
    want_error = e.what();
  }
  try {
    setup_triangles_parallel(scene, vp, 3);
  } catch (const std::invalid_argument& e) {
    got_error = e.what();
  }
  EXPECT_FALSE(want_error.empty());
  EXPECT_EQ(got_error, want_error);
}

TEST(FrameRender, RejectsWhatTheGoldenModelRejects) {
  FrameGeometry g;
  g.viewport = Viewport{16, 16, 24, 3};
  EXPECT_THROW(render_frame(g, *find_plan("opaque")), std::invalid_argument);
  g.viewport = Viewport{0, 16, 24, 16};
  EXPECT_THROW(render_frame(g, *find_plan("opaque")), std::invalid_argument);
}

}  // namespace
}  // namespace zb
