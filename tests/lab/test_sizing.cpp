// The scene analysis, the cost model and the sizing search (docs/sizing.md), on scenes whose
// answers are worked out by hand here: from the camera of scene_suite.cpp, from pixel centres
// and the top-left rule, and from the RTL driver's tile loop.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/scene_analysis.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene/failure_scenes.h"
#include "scene/scene_suite.h"
#include "sizing.h"
#include "sizing_cost.h"

namespace {

using namespace zb;

RasterizedScene raster(const Scene& s, int w, int h) {
  return rasterize_scene(s, Viewport{w, h, kDefaultDepthBits, kDefaultCoverageSamples});
}

// An axis-aligned opaque rectangle [0, w) x [0, h) in pixels, as two window triangles.
std::vector<ScreenTriangle> corner_rect(int w, int h) {
  auto v = [](int x, int y) {
    ScreenVertex s;
    s.x = x * kSubpixelOne;
    s.y = y * kSubpixelOne;
    s.z = 1000;
    s.z_exact = 1000.0 / depth_max(kDefaultDepthBits);
    return s;
  };
  ScreenTriangle a, b;
  a.v[0] = v(0, 0), a.v[1] = v(w, 0), a.v[2] = v(w, h);
  b.v[0] = v(0, 0), b.v[1] = v(w, h), b.v[2] = v(0, h);
  a.color = b.color = Rgba8{200, 10, 10, 255};
  a.prim = 0;
  b.prim = 1;
  return {a, b};
}

TEST(Analysis, LayersSceneHasThreeLayersOverItsBackdrop) {
  const SceneAnalysis a = analyse_scene(raster(layers_scene(3, 0.5f), 160, 120));
  EXPECT_EQ(a.max_layers, 3);
  EXPECT_EQ(a.max_depth_complexity, 4);  // three layers and the backdrop
  EXPECT_GT(a.share_over(2), 0.0);
  EXPECT_EQ(a.share_over(3), 0.0);
}

// two_layers_scene's camera: eye (0, 0, 10) looking down -z, fov 30 degrees, near 1, far 100.
// GL's window depth at eye distance d is f / (f - n) * (1 - n / d). Along the ray of a row with
// slope vy (direction (vx, vy, -1)), the red plane n.x = 0 with n = (0, sin 60, cos 60) (the quad's
// +z normal tilted -60 degrees about x) is at d = 5 / (0.5 - 0.866 vy), the blue plane n.x = sep
// at d = (5 - sep) / (0.5 - 0.866 vy). So the separation depends only on the row:
//   S(vy) = f n / (f - n) * (0.5 - sin60 vy) * sep / (5 (5 - sep)),
// smallest on the topmost row of the blue quad, below its top edge (object y = 2) at vy_top.
struct TwoLayers {
  static constexpr double kN = 1, kF = 100, kTanHalfFov = 0.26794919243112270;  // tan 15 deg
  double sep;
  int height;
  double sin60() const { return std::sqrt(3.0) / 2; }
  double separation(double vy) const {
    return kF * kN / (kF - kN) * (0.5 - sin60() * vy) * sep / (5 * (5 - sep));
  }
  double red_depth(double vy) const {
    return kF / (kF - kN) * (1 - kN * (0.5 - sin60() * vy) / 5);
  }
  double vy_top() const {  // the blue quad's top edge: tilt of (x, 2, sep)
    const double y = 0.5 * 2 + sin60() * sep, z = -sin60() * 2 + 0.5 * sep;
    return y / (10 - z);
  }
  double row() const { return 2 * kTanHalfFov / height; }  // vy from one pixel row to the next
};

TEST(Analysis, TwoLayersSeparationMatchesTheCamera) {
  int previous_bits = 0;
  for (const double sep : {0.1, 0.01, 0.001}) {
    const TwoLayers t{sep, 480};
    const SceneAnalysis a = analyse_scene(raster(two_layers_scene(float(sep)), 640, 480));
    // The topmost covered row lies within one row below the edge: S between S(vy_top) and
    // S(vy_top - row). Tolerance: vertices are rounded to 1/256 pixel, which moves each plane's
    // interpolated depth by at most its depth change per pixel (one row here: the tilt is
    // about x) times sqrt(2)/512 pixel, for both planes; plus 1e-7 for the float geometry.
    const double lo = t.separation(t.vy_top()), hi = t.separation(t.vy_top() - t.row());
    const double per_row = t.red_depth(t.vy_top() - t.row()) - t.red_depth(t.vy_top());
    const double tol = 2 * std::fabs(per_row) * std::sqrt(2.0) / 512 + 1e-7;
    SCOPED_TRACE(::testing::Message() << "sep " << sep << ": S in [" << lo << ", " << hi << "]");
    EXPECT_GE(a.min_separation, lo - tol);
    EXPECT_LE(a.min_separation, hi + tol);
    EXPECT_GT(a.separated_pixels, 0u);
    // Bits: the narrowest B with S (2^B - 1) > 2, at the ends of the range.
    EXPECT_GE(a.depth_bits_needed, depth_bits_to_resolve(hi + tol));
    EXPECT_LE(a.depth_bits_needed, depth_bits_to_resolve(lo - tol));
    EXPECT_GT(a.depth_bits_needed, previous_bits);
    previous_bits = a.depth_bits_needed;
  }
}

TEST(Analysis, DepthBitsToResolve) {
  EXPECT_EQ(depth_bits_to_resolve(2.01 / 255), 8);   // 2.01 units of 8 bits
  EXPECT_EQ(depth_bits_to_resolve(2.0 / 255), 9);    // exactly 2 units is not enough
  EXPECT_EQ(depth_bits_to_resolve(0.5), 8);          // never below kMinDepthBits
  EXPECT_EQ(depth_bits_to_resolve(3e-9), 30);        // 3e-9 * (2^30 - 1) = 3.2 > 2 > 1.6
  EXPECT_EQ(depth_bits_to_resolve(1e-12), kUnresolvable);
  EXPECT_EQ(depth_bits_to_resolve(0), kUnresolvable);
}

// A 40 x 20 rectangle in the top-left corner of a 128 x 96 frame: pixel centres 0.5 .. 39.5
// and 0.5 .. 19.5 are inside, so columns 0..39 and rows 0..19.
TEST(Analysis, TilesTouchedByACornerRectangle) {
  const SceneAnalysis a = analyse_scene(
      rasterize_triangles(corner_rect(40, 20), Viewport{128, 96}, Rgba8{0, 0, 0, 255}));
  ASSERT_EQ(a.tiles.size(), 3u);
  EXPECT_EQ(a.fragments, 800u);
  EXPECT_EQ(a.tiles[0].size, 16);
  EXPECT_EQ(a.tiles[0].touched, 3u * 2u);  // columns 0..39 in 3 tiles, rows 0..19 in 2
  EXPECT_EQ(a.tiles[0].total, 8u * 6u);
  EXPECT_EQ(a.tiles[1].touched, 2u * 1u);
  EXPECT_EQ(a.tiles[1].total, 4u * 3u);
  EXPECT_EQ(a.tiles[2].touched, 1u);
  EXPECT_EQ(a.tiles[2].total, 2u * 2u);
  // The two triangles share a diagonal: one connected surface, so no separation.
  EXPECT_EQ(a.separated_pixels, 0u);
  EXPECT_EQ(a.max_layers, 0);
  // Its edges lie on pixel boundaries, except the diagonal: colours meet at no pixel.
  EXPECT_EQ(a.aa_edge_pixels, 0u);
}

// The driver's loop per touched tile: one setup cycle (the new frame's planes are fast-cleared:
// nothing loads), the fragments, 15 to issue and drain (none waits here: each pixel once),
// then the colour and depth planes stored, a beat of 8 pixels a clock.
TEST(CostModel, CountsTheDriversTileLoop) {
  const RasterizedScene rs =
      rasterize_triangles(corner_rect(40, 20), Viewport{128, 96}, Rgba8{0, 0, 0, 255});
  GoldenRop golden;
  CostCounter counter(golden);
  render(rs, *find_plan("opaque"), counter);
  const MethodCost& c = counter.cost();
  EXPECT_EQ(c.passes, 1u);
  EXPECT_EQ(c.totals.fragments_in, 800u);
  EXPECT_EQ(c.at(16).tiles_loaded, 6u);
  EXPECT_EQ(c.at(16).stream_cycles, 800u + 6u * 15u);
  ASSERT_EQ(kRtlBeat, 8) << "the figures below are worked for 8 pixels a beat";
  EXPECT_EQ(c.at(16).tile_io_cycles, 6u * (1u + 16u * 2u));
  EXPECT_EQ(c.at(16).tile_beats, 6u * 16u * 2u);
  // A 64 x 64 tile clipped to the 128 x 96 frame's first tile: all 64 x 64 inside.
  EXPECT_EQ(c.at(64).tile_io_cycles, 1u + 64u * 8u);
  EXPECT_EQ(c.frame_op_pixels, 0u);
  // The pixel in bits: colour 32, depth and peel 24 each, coverage 5 (0..16), the
  // accumulation word 4 * 16 + 8.
  EXPECT_EQ(tile_pixel_bits(24, 16), 157u);
  // Bytes at 16x16 tiles: 6 tiles of 256 pixels of colour (32 bits) and depth (24) stored,
  // plus 800 depth reads and writes (24 bits) and 800 colour writes (32 bits).
  EXPECT_EQ(c.traffic_bytes(16, 24, 16), (6u * 256u * 56u + 800u * (24u + 24u + 32u)) / 8u);
  EXPECT_EQ(c.best_tile(24, 16), 16);  // 6 * 33 I/O cycles against 513 at 64
}

TEST(CostModel, MovesWholeTilesAndCountsTheFramesBytes) {
  const RasterizedScene rs =
      rasterize_triangles(corner_rect(40, 20), Viewport{40, 20}, Rgba8{0, 0, 0, 255});
  GoldenRop golden;
  CostCounter counter(golden);
  render(rs, *find_plan("opaque"), counter);
  // The port moves whole tiles (64 rows of 8 beats), though the frame is 40 x 20; at 16, six
  // tiles of 16 rows of 2 beats. The memory traffic counts the frame's pixels only.
  EXPECT_EQ(counter.cost().at(64).tile_io_cycles, 1u + 64u * 8u);
  EXPECT_EQ(counter.cost().at(16).tile_beats, 6u * 16u * 2u);
  EXPECT_EQ(counter.cost().at(16).plane_pixels[0], 40u * 20u);  // colour stored once
}

TEST(Sizing, ErrorBeyondTheRoundingFloor) {
  Framebuffer ref(3, 1, 24, Rgba8{100, 100, 100, 255}), img = ref, exact = ref;
  img.color[0] = Rgba8{105, 100, 98, 255};    // off by 5
  img.color[1] = Rgba8{100, 97, 100, 255};    // off by 3
  exact.color[0] = Rgba8{102, 100, 100, 255}; // the exact-order composite off by 2
  exact.color[1] = Rgba8{100, 100, 90, 255};  // off by 10: more than rounding
  exact.color[2] = Rgba8{101, 101, 101, 255}; // off by 1, where there is no layer
  const std::vector<uint16_t> allow = rounding_allowance(exact, ref, {3, 2, 0});
  EXPECT_EQ(allow, (std::vector<uint16_t>{2, 2, 0}));  // min(error, layers)
  EXPECT_EQ(error_beyond_rounding(img, ref, allow), 3);   // pixel 0: 5 - 2
  EXPECT_EQ(error_beyond_rounding(img, ref, {0, 0, 0}), 5);
  EXPECT_EQ(error_beyond_rounding(img, ref, {5, 3, 0}), 0);
  EXPECT_EQ(error_beyond_rounding(ref, ref, {0, 0, 0}), 0);
  EXPECT_THROW(error_beyond_rounding(img, ref, {0, 0}), std::invalid_argument);
}

// Opaque only, E = 0: every one-pass-per-material method draws the same pixels; unsorted,
// three-pass, back-front and facing-additive add transparent passes that draw nothing (no tile
// loaded, no cycle), so they tie with opaque on cycles and bytes and lose on passes; coverage-aa
// at 1 sample reads colour too (more bytes). So opaque. At sep 0.5 the smallest separation
// is about 1.01 * (0.5 - 0.866 * 0.11) * 0.5 / 22.5 = 0.0091, and 0.0091 * 255 > 2: 8 bits.
TEST(Sizing, OpaqueSceneAtZeroErrorPicksOpaque) {
  SizingOptions o;
  o.width = 160;
  o.height = 120;
  o.max_error = 0;
  const SizingResult r = size_model(two_layers_scene(0.5f), o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.choice.method, "opaque");
  EXPECT_EQ(r.choice.step, "verify");
  EXPECT_EQ(r.choice.beyond_rounding, 0);
  EXPECT_EQ(r.choice.error.max_abs, 0);
  EXPECT_EQ(r.choice.depth_bits, 8);
}

// sep 0.01: S ~ 1.01 * 0.42 * 0.01 / 24.95 = 1.7e-4, 0.7 units at 12 bits (the quads round
// to equal depths and the far one, drawn first, wins), 11 at 16 bits: 16.
TEST(Sizing, NearQuadsNeedSixteenBits) {
  SizingOptions o;
  o.width = 160;
  o.height = 120;
  o.max_error = 0;
  const SizingResult r = size_model(two_layers_scene(0.01f), o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.choice.method, "opaque");
  EXPECT_EQ(r.choice.depth_bits, 16);
}

// Three layers, E = 0: only a method that composites all three in order stays within the
// rounding: depth peeling with K >= 3, and mlab-K, whose merge folds a third layer into the
// second front over back as the chain would (one rounding more, within a unit a layer). mlab-2
// is the cheapest: one geometry pass for the transparent layers, not one a peel.
TEST(Sizing, TransparentSceneAtZeroErrorPicksOnePassLayers) {
  SizingOptions o;
  o.width = 160;
  o.height = 120;
  o.max_error = 0;
  const SizingResult r = size_model(layers_scene(3, 0.5f), o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.analysis.max_layers, 3);
  EXPECT_EQ(r.choice.method, "mlab-2");
  EXPECT_FALSE(uses_coverage(r.choice.method));
  uint64_t peel4 = 0, mlab2 = 0;
  for (const SizingTrial& t : r.trials) {
    if (t.step != "method") continue;
    if (t.method == "depth-peel-2" || t.method == "unsorted") {
      EXPECT_FALSE(t.meets) << t.method;
    }
    if (t.method == "depth-peel-4" || t.method == "mlab-2" || t.method == "mlab-4") {
      EXPECT_TRUE(t.meets) << t.method;
    }
    if (t.method == "depth-peel-4") peel4 = t.cycles();
    if (t.method == "mlab-2") mlab2 = t.cycles();
  }
  EXPECT_LT(4 * mlab2, peel4);
}

// Twelve layers of alpha 0.1: depth-peel-8 misses four, which still show through the eight in
// front by 0.9^8 = 43%, and the patents' methods blend out of order. wboit's depth weights
// (nearer weighs more) come close to the exact weights a (1 - a)^k of low-alpha layers, and
// mlab-4 keeps the nearest three exact and folds the other nine into the fourth front over
// back: the two methods within E = 0, whose floor allows a unit per layer (12 here). mlab-4 is
// the cheaper: the cycles of wboit, and its layers never cross the tile port.
TEST(Sizing, WboitAndMlab4MeetTwelveLowAlphaLayers) {
  SizingOptions o;
  o.width = 64;
  o.height = 48;
  o.max_error = 0;
  const SizingResult r = size_model(layers_scene(12, 0.1f), o);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.choice.method, "mlab-4");
  for (const SizingTrial& t : r.trials)
    if (t.step == "method") {
      EXPECT_EQ(t.meets, t.method == "wboit" || t.method == "mlab-4") << t.method;
    }
}

// particles: 40 and more layers of many alphas in random order. Nothing meets E = 0 (the
// floor is the exact-order composite's own error), and the best achievable is reported.
TEST(Sizing, NothingMeetsTheBoundOnParticles) {
  SizingOptions o;
  o.width = 64;
  o.height = 48;
  o.max_error = 0;
  const SizingResult r = size_model(particles_scene(), o);
  EXPECT_FALSE(r.found);
  EXPECT_GT(r.choice.beyond_rounding, 0);
  for (const SizingTrial& t : r.trials) {
    EXPECT_EQ(t.step, "method");
    EXPECT_GE(t.beyond_rounding, r.choice.beyond_rounding);
  }
}

TEST(Sizing, RejectsBadCandidates) {
  SizingOptions o;
  o.depth_bits = {24, 16};
  EXPECT_THROW(size_model(two_layers_scene(0.5f), o), std::invalid_argument);
  o = SizingOptions{};
  o.coverage_samples = {3};
  EXPECT_THROW(size_model(two_layers_scene(0.5f), o), std::invalid_argument);
  o = SizingOptions{};
  o.max_error = 256;
  EXPECT_THROW(size_model(two_layers_scene(0.5f), o), std::invalid_argument);
}

}  // namespace
