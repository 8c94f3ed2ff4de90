// The sweeps' known shapes (docs/sweeps.md), against values computed here by hand: camera
// geometry, popping on hand-made frames, closed forms of blending, a z-fighting bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pipeline/passes.h"
#include "scene/scene_suite.h"
#include "scene/builtin_scenes.h"
#include "scene/meshes.h"
#include "sweeps.h"

namespace {

using namespace zb;
using namespace zb::lab;

constexpr Viewport kSmall{96, 72};

Framebuffer frame(std::vector<Rgba8> colors) {
  Framebuffer fb(static_cast<int>(colors.size()), 1, kDefaultDepthBits, Rgba8{0, 0, 0, 255});
  fb.color = std::move(colors);
  return fb;
}

const MethodRow& row_at(const std::vector<MethodRow>& rows, const std::string& method, double x) {
  for (const MethodRow& r : rows)
    if (r.method == method && std::abs(r.x - x) < 1e-9) return r;
  throw std::runtime_error("no row for " + method);
}

// --- orbit ---

TEST(OrbitCamera, TurnsAboutUpKeepingDistanceAndHeight) {
  Scene s;
  s.camera.eye = {3.0f, 2.0f, 4.0f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.objects.push_back(Object{"box", make_box({1.0f, 1.0f, 1.0f}), 0, glm::mat4(1.0f)});
  s.materials.push_back(Material{"m", Rgba8{200, 200, 200, 255}});

  const Camera c0 = orbit_camera(s, 0.0f);
  EXPECT_EQ(c0.eye, s.camera.eye);
  // Half a turn about +y: (x, z) -> (-x, -z).
  const Camera c180 = orbit_camera(s, 180.0f);
  EXPECT_NEAR(c180.eye.x, -3.0f, 1e-5f);
  EXPECT_NEAR(c180.eye.y, 2.0f, 1e-5f);
  EXPECT_NEAR(c180.eye.z, -4.0f, 1e-5f);
  // A quarter turn: the same height and distance, the horizontal offset at right angles.
  const Camera c90 = orbit_camera(s, 90.0f);
  EXPECT_NEAR(c90.eye.y, 2.0f, 1e-5f);
  EXPECT_NEAR(glm::length(c90.eye), std::sqrt(29.0f), 1e-5f);
  EXPECT_NEAR(c90.eye.x * 3.0f + c90.eye.z * 4.0f, 0.0f, 1e-5f);
  // Near and far hold the box's corners (sqrt 3 from the centre) from every angle, and do
  // not change with the angle.
  EXPECT_LE(c0.near, std::sqrt(29.0f) - std::sqrt(3.0f));
  EXPECT_GE(c0.far, std::sqrt(29.0f) + std::sqrt(3.0f));
  EXPECT_EQ(orbit_camera(s, 137.0f).near, c0.near);
  EXPECT_EQ(orbit_camera(s, 137.0f).far, c0.far);
}

TEST(Popping, CountsChangesBeyondTheReferencesByTheThreshold) {
  // Pixel 0: red moves 40 where the reference moves 20: 40 > 20 + 16, pops.
  // Pixel 1: red moves 30 where the reference moves 20: 30 <= 36, does not.
  // Pixel 2: the reference moves 100, the method not at all: does not.
  // Pixel 3: green moves 17 where the reference stands still: pops.
  const Rgba8 black{0, 0, 0, 255}, grey{50, 50, 50, 255}, dark{9, 9, 9, 255};
  const Framebuffer m0 = frame({black, black, grey, dark});
  const Framebuffer m1 = frame({{40, 0, 0, 255}, {30, 0, 0, 255}, grey, {9, 26, 9, 255}});
  const Framebuffer r0 = frame({black, black, black, dark});
  const Framebuffer r1 = frame({{20, 0, 0, 255}, {20, 0, 0, 255}, {100, 0, 0, 255}, dark});
  EXPECT_DOUBLE_EQ(popping_share(m0, m1, r0, r1, 16), 0.5);
  EXPECT_DOUBLE_EQ(popping_share(m0, m1, r0, r1, 9), 0.75);  // pixel 1 too: 30 > 29
  EXPECT_DOUBLE_EQ(popping_share(r0, r1, r0, r1, 0), 0.0);   // never against itself
}

double mean_of(const std::vector<OrbitRow>& rows, const std::string& method) {
  for (const auto& [m, v] : mean_popping(rows))
    if (m == method) return v;
  return -1;
}

TEST(OrbitSweep, ReferenceAndOpaqueOnOpaqueGeometryNeverPop) {
  OrbitOptions o;
  o.steps = 12;
  o.viewport = kSmall;
  o.methods = {kReferenceMethod, "opaque"};
  const std::vector<OrbitRow> rows = orbit_sweep(opaque_only(*builtin_scene("parts")), o);
  ASSERT_EQ(rows.size(), 24u);
  for (const OrbitRow& r : rows) {
    EXPECT_EQ(r.popping, 0.0) << r.method << " at " << r.angle_deg;
    if (r.method == kReferenceMethod) { EXPECT_EQ(r.error.max_abs, 0); }
  }
  EXPECT_EQ(rows[2].angle_deg, 30.0);  // step 1 of 12
}

TEST(OrbitSweep, UnsortedPopsOnCad) {
  OrbitOptions o;
  o.steps = 24;
  o.viewport = kSmall;
  o.methods = {kReferenceMethod, "unsorted"};
  const std::vector<OrbitRow> rows = orbit_sweep(*builtin_scene("cad"), o);
  EXPECT_EQ(mean_of(rows, kReferenceMethod), 0.0);
  EXPECT_GT(mean_of(rows, "unsorted"), 0.0);
}

// --- depth ---

// two_layers_scene: near 1, far 100, eye 10 from the quads' centre, tilted 60 degrees. The
// near quad (half height 2) spans eye depths 10 -+ 2 sin 60. A ray meets the two parallel
// planes 1 / cos 60 = 2 separations apart, and window depth changes by f n / ((f - n) z^2)
// per unit of eye depth: the gap in depth units at separation s is
// 2 s f n / ((f - n) z^2) * (2^bits - 1). Where it is below one unit everywhere, rounding ties
// most pixels (and a tie keeps the far quad, drawn first); where it is above two units
// everywhere (one for the rounding of each vertex depth), none.
double separation_for_gap(double gap_units, double z, int bits) {
  const double n = 1, f = 100;
  return gap_units * (f - n) * z * z / (2 * f * n * double(depth_max(bits)));
}

TEST(DepthSweep, OnsetFallsWithDepthBitsAsTheDepthGapPredicts) {
  DepthOptions o;
  o.viewport = {120, 90};
  const std::vector<DepthRow> rows = depth_sweep(o);
  const double reach = 2 * std::sin(glm::radians(60.0));
  const double z_near = 10 - reach, z_far = 10 + reach;

  for (const DepthRow& r : rows) {
    EXPECT_GT(r.near_pixels, 500u);
    if (r.separation == 1.0) { EXPECT_EQ(r.far_shown, 0u) << r.method << " " << r.depth_bits; }
    if (r.method == kReferenceMethod && r.separation >= 1e-3) { EXPECT_EQ(r.far_shown, 0u); }
    // The widest buffer resolves everything the exact sort does.
    if (r.depth_bits == 32) { EXPECT_EQ(r.error_vs_reference, 0.0) << r.separation; }
  }
  std::vector<double> onset;
  for (const int bits : o.depth_bits) onset.push_back(onset_separation(rows, "opaque", bits));
  for (size_t i = 0; i < 3; ++i) {  // 8, 12, 16 bits: the formula's bracket, grid step included
    const int bits = o.depth_bits[i];
    EXPECT_GE(onset[i], separation_for_gap(1, z_near, bits) / 1.5) << bits;
    EXPECT_LE(onset[i], separation_for_gap(2, z_far, bits) * 1.5) << bits;
  }
  // From 20 bits on, the snapping of vertices to 1/256 pixel (they keep their depths) moves
  // each plane by up to half a subpixel times its depth slope, about 2e-6 of window depth at
  // this size: 2 units of 20 bits, more than the gap. It decides which quad wins as much as
  // the buffer does, so only the order is checked there.
  EXPECT_GT(onset[0], onset[1]);
  EXPECT_GT(onset[1], onset[2]);
  EXPECT_GT(onset[2], onset[3]);
  EXPECT_GE(onset[3], onset[4]);
  EXPECT_GE(onset[4], onset[5]);
}

// --- layers and alpha ---

TEST(LayersSweep, ReferenceExactUnsortedExactForOneLayerOnly) {
  LayersOptions o;
  o.viewport = kSmall;
  o.methods = {kReferenceMethod, "unsorted"};
  const std::vector<MethodRow> rows = layers_sweep(o);
  ASSERT_EQ(rows.size(), 32u);
  for (int n = 1; n <= 16; ++n) {
    EXPECT_EQ(row_at(rows, kReferenceMethod, n).error.max_abs, 0) << n;
    const int unsorted = row_at(rows, "unsorted", n).error.max_abs;
    // One blend rounds twice by at most half a unit; N blends stay within N units.
    if (n == 1) {
      EXPECT_LE(unsorted, 1);
    } else {
      EXPECT_GT(unsorted, n + 1) << n;
    }
  }
}

TEST(AlphaSweep, ReferenceExactAtEveryAlpha) {
  AlphaOptions o;
  o.viewport = kSmall;
  o.methods = {kReferenceMethod, "depth-peel-4"};
  const std::vector<MethodRow> rows = alpha_sweep(o);
  ASSERT_EQ(rows.size(), 38u);
  for (const MethodRow& r : rows) {
    if (r.method == kReferenceMethod) {
      EXPECT_EQ(r.error.max_abs, 0) << r.x;
    } else {
      EXPECT_LE(r.error.max_abs, 2) << r.x;  // four layers: depth-peel-4 is exact
    }
  }
}

// depth-peel-K's error stays at the blend rounding up to K layers and jumps past it. At alpha
// 0.5 only 2^-8 of the light gets past 8 layers, so a ninth would not show: depth-peel-8 is
// checked at alpha 0.15, where 0.85^8 = 27% of it is left.
TEST(LayersSweep, DepthPeelExactUpToItsLayers) {
  for (const auto& [k, alpha] : {std::pair{2, 0.5f}, {4, 0.5f}, {8, 0.15f}}) {
    LayersOptions o;
    o.viewport = kSmall;
    o.alpha = alpha;
    o.max_layers = k + 1;
    const std::string m = "depth-peel-" + std::to_string(k);
    o.methods = {m};
    const std::vector<MethodRow> rows = layers_sweep(o);
    int within = 0;
    for (int n = 1; n <= k; ++n) within = std::max(within, row_at(rows, m, n).error.max_abs);
    EXPECT_LE(within, 2) << m;
    EXPECT_GT(row_at(rows, m, k + 1).error.max_abs, within + 2) << m;
  }
}

// --- pixels of layers_scene, composited here by hand ---

// What the back-end receives at one pixel of a layers scene: the backdrop (the one opaque
// fragment) and the layers in submit order, which the scene makes near to far.
struct PixelStack {
  Rgba8 backdrop;
  std::vector<Rgba8> layers;
};

PixelStack stack_at(const RasterizedScene& rs, int x, int y) {
  PixelStack p;
  for (const Fragment& f : rs.fragments) {
    if (f.x != x || f.y != y) continue;
    if (f.color.a == 255) p.backdrop = f.color;
    else p.layers.push_back(f.color);
  }
  return p;
}

// `layers` (near to far) over `backdrop`, channel c, in double: c = a s + (1 - a) c from the
// farthest up.
double over(const std::vector<Rgba8>& layers, Rgba8 backdrop, int c) {
  auto ch = [c](Rgba8 v) { return double(c == 0 ? v.r : c == 1 ? v.g : v.b); };
  double out = ch(backdrop);
  for (auto it = layers.rbegin(); it != layers.rend(); ++it) {
    const double a = it->a / 255.0;
    out = a * ch(*it) + (1 - a) * out;
  }
  return out;
}

int channel(Rgba8 v, int c) { return c == 0 ? v.r : c == 1 ? v.g : v.b; }

// Left of centre over the light backdrop, right of centre over the dark one; both inside the
// layers' rectangle (the middle half of the frame).
const int kPixelX[2] = {kSmall.width * 35 / 100, kSmall.width * 65 / 100};
const int kPixelY = kSmall.height / 2;

TEST(LayersPixels, ThreePassBlendsOneLayerTwice) {
  for (const float alpha : {0.3f, 0.5f, 0.8f}) {
    const RasterizedScene rs = rasterize_scene(layers_scene(1, alpha), kSmall);
    const Framebuffer three = render_method(rs, "three-pass");
    const Framebuffer ref = render_method(rs, kReferenceMethod);
    for (const int x : kPixelX) {
      const PixelStack p = stack_at(rs, x, kPixelY);
      ASSERT_EQ(p.layers.size(), 1u);
      const double a = p.layers[0].a / 255.0;
      for (int c = 0; c < 3; ++c) {
        const double s = channel(p.layers[0], c), b = channel(p.backdrop, c);
        const double once = s * a + b * (1 - a);
        const double twice = s * a * (2 - a) + b * (1 - a) * (1 - a);
        // The reference rounds once: half a unit. Three-pass blends twice in 8 bits, each
        // blend rounding its two products by half a unit: at most 1 + (1 - a) < 2.
        EXPECT_NEAR(channel(ref.color_at(x, kPixelY), c), once, 0.5) << alpha << " " << x;
        EXPECT_NEAR(channel(three.color_at(x, kPixelY), c), twice, 2.0) << alpha << " " << x;
      }
    }
  }
}

TEST(LayersPixels, DepthPeelCompositesTheNearestKLayers) {
  for (const auto& [k, alpha] : {std::pair{2, 0.5f}, {4, 0.5f}, {8, 0.15f}}) {
    const std::string m = "depth-peel-" + std::to_string(k);
    for (int n = 1; n <= k + 1; ++n) {
      const RasterizedScene rs = rasterize_scene(layers_scene(n, alpha), kSmall);
      const Framebuffer image = render_method(rs, m);
      double missing = 0;  // what the layers past K would add
      for (const int x : kPixelX) {
        const PixelStack p = stack_at(rs, x, kPixelY);
        ASSERT_EQ(p.layers.size(), size_t(n));
        const std::vector<Rgba8> peeled(p.layers.begin(), p.layers.begin() + std::min(n, k));
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(channel(image.color_at(x, kPixelY), c), over(peeled, p.backdrop, c), 2.5)
              << m << " " << n << " layers at x " << x;
          const double all = over(p.layers, p.backdrop, c);
          missing = std::max(missing, std::abs(all - over(peeled, p.backdrop, c)));
        }
      }
      if (n == k + 1) {
        EXPECT_GT(missing, 5.0) << m;  // the check can tell K from K + 1
      }
    }
  }
}

TEST(LayersPixels, UnsortedPutsTheFarLayersOnTop) {
  for (int n = 1; n <= 4; ++n) {
    const RasterizedScene rs = rasterize_scene(layers_scene(n, 0.5f), kSmall);
    const Framebuffer image = render_method(rs, "unsorted");
    for (const int x : kPixelX) {
      const PixelStack p = stack_at(rs, x, kPixelY);
      // Submitted near to far and blended in that order: the farthest ends up on top.
      const std::vector<Rgba8> reversed(p.layers.rbegin(), p.layers.rend());
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(channel(image.color_at(x, kPixelY), c), over(reversed, p.backdrop, c), n)
            << n << " layers at x " << x;
    }
  }
}

// --- coverage samples ---

TEST(SamplesSweep, AntiAliasingHelpsWithoutSeamsAndSeamsLeakMore) {
  SamplesOptions o;
  o.viewport = kSmall;
  o.supersample = 4;
  const std::vector<MethodRow> rows = samples_sweep(*builtin_scene("parts"), o);
  auto rmse = [&](const std::string& scene, const std::string& m, int n) {
    for (const MethodRow& r : rows)
      if (r.scene == scene && r.method == m && r.x == n) return r.error.rmse;
    return -1.0;
  };
  const std::string tri = separate_triangles_scene().name;
  for (const std::string& scene : {std::string("parts"), tri}) {
    // One sample is the pixel centre: coverage-aa draws what opaque draws.
    EXPECT_DOUBLE_EQ(rmse(scene, "coverage-aa", 1), rmse(scene, "opaque", 1)) << scene;
    EXPECT_DOUBLE_EQ(rmse(scene, "opaque", 16), rmse(scene, "opaque", 1)) << scene;
  }
  // Edges only: every doubling of the samples lowers the error.
  for (const int n : {2, 4, 8, 16})
    EXPECT_LT(rmse(tri, "coverage-aa", n), rmse(tri, "coverage-aa", n / 2)) << n;
  EXPECT_LT(rmse(tri, "coverage-aa", 16), 0.5 * rmse(tri, "coverage-aa", 1));
  // Shared edges: the single coverage count lets the background through, more with more
  // samples.
  EXPECT_GT(rmse("parts", "coverage-aa", 16), rmse("parts", "coverage-aa", 1));
}

// --- hidden-line offset ---

// A larger offset draws a superset of the edge fragments (every fragment's depth only falls),
// so along each knob the hidden edges drawn never fall and the visible ones missing never rise;
// steep faces need the slope term or their own faces; the old offset leaks on cad and the
// default does not; the default sits at its knob's knee.
TEST(OffsetSweep, MonotoneKnobsGapsAtSteepTiltsLeakOnCad) {
  OffsetOptions o;
  o.viewport = Viewport{160, 120};
  o.tilts = {0, 60, 85, 89, 89.9};
  o.scenes = {"cad"};
  const std::vector<OffsetRow> rows = offset_sweep(o);
  const std::vector<OffsetSetting> settings = offset_settings();
  ASSERT_EQ(rows.size(), settings.size() * 6);
  auto at = [&](const std::string& knob, double value, const std::string& scene, double tilt) {
    for (const OffsetRow& r : rows)
      if (r.knob == knob && r.value == value && r.scene == scene &&
          (scene != "tilt" || r.tilt == tilt))
        return r.error;
    ADD_FAILURE() << knob << " " << value << " " << scene << " " << tilt;
    return LineError{};
  };
  for (const OffsetRow& r : rows) {
    EXPECT_GT(r.error.edge_pixels, 0u) << r.scene << " " << r.tilt;
    // The next value of the same knob on the same case.
    for (size_t i = 0; i + 1 < settings.size(); ++i) {
      if (settings[i].knob != r.knob || settings[i].value != r.value) continue;
      if (settings[i + 1].knob != r.knob) break;
      const LineError next = at(r.knob, settings[i + 1].value, r.scene, r.tilt);
      EXPECT_GE(next.hidden_drawn, r.error.hidden_drawn) << r.knob << " " << r.value << " " << r.scene << " " << r.tilt;
      EXPECT_LE(next.visible_missing, r.error.visible_missing) << r.knob << " " << r.value << " " << r.scene << " " << r.tilt;
    }
  }
  // Without the slope term the steep plates' edges sink into their faces.
  EXPECT_GT(at("slope", 0, "tilt", 89).visible_missing, at("slope", 1, "tilt", 89).visible_missing);
  EXPECT_GT(at("slope", 0, "tilt", 89).visible_missing_share(), 0.02);
  // The first polygon offset lifts cad's sphere silhouette through the box: the leak.
  EXPECT_GT(at("slope", 1, "cad", 0).hidden_drawn_share(), 0.01);
  EXPECT_LT(at("faces", kEdgeOffset.units, "cad", 0).hidden_drawn_share(), 0.002);
  // The default is the knee of its knob.
  ASSERT_TRUE(kEdgeOffset.faces);
  EXPECT_EQ(offset_knee(rows, "faces"), double(kEdgeOffset.units));
  for (const OffsetRow& r : rows)
    EXPECT_EQ(r.is_default, r.knob == "faces" && r.value == kEdgeOffset.units);
}

TEST(OffsetSweep, TiltedPlateSceneTurnsItsPlate) {
  // At 0 degrees the plate faces the eye; at 89.9 it is seen almost edge-on.
  const RasterizedScene flat = rasterize_scene(tilted_plate_scene(0), kSmall);
  const RasterizedScene steep = rasterize_scene(tilted_plate_scene(89.9f), kSmall);
  EXPECT_EQ(flat.lines.size(), steep.lines.size());
  EXPECT_GT(flat.fragments.size(), 2 * steep.fragments.size());
  const std::string csv = offset_csv({OffsetRow{"clamp", INFINITY, false, "cad", NAN, {}}});
  EXPECT_NE(csv.find("\nclamp,inf,0,cad,,"), std::string::npos) << csv;
}

// --- output ---

TEST(SweepOutput, CsvHasAHeaderAndARowEach) {
  std::vector<MethodRow> rows(3);
  rows[1].method = "opaque";
  const std::string csv = method_csv("layers", rows);
  EXPECT_EQ(csv.rfind("layers,scene,method,rmse,", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
}

TEST(SweepOutput, MarkdownShowsEachChartRun) {
  SweepResults r;
  LayersOptions o;
  o.viewport = kSmall;
  o.max_layers = 3;
  o.methods = {kReferenceMethod, "unsorted", "depth-peel-2"};
  r.layers = o;
  r.layers_rows = layers_sweep(o);
  const std::string md = sweeps_markdown(r);
  EXPECT_NE(md.find("![layers](layers.png)"), std::string::npos);
  EXPECT_EQ(md.find("orbit.png"), std::string::npos);  // not run, not shown
  EXPECT_NE(md.find("`depth-peel-2`"), std::string::npos) << md;
  EXPECT_NE(md.find("up to 2 layers"), std::string::npos) << md;
}

}  // namespace

namespace {

// wboit's weight range and accumulation width (docs/sweeps.md "wboit"): the defaults sit at
// the knees, depth weighting beats none, a 12-bit channel saturates at wide weight ranges, and
// the patents' methods win where the sweep's chart says.
class WboitSweep : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { rows_ = new std::vector<WboitRow>(wboit_sweep(WboitOptions{})); }
  static void TearDownTestSuite() { delete rows_; }
  static const std::vector<WboitRow>& rows() { return *rows_; }
  static double error(const std::string& scene, const std::string& method, int a = 0,
                      int w = -1) {
    for (const WboitRow& r : rows())
      if (r.scene == scene && r.method == method &&
          (method != "wboit" || (r.format.acc_bits == a && r.format.weight_bits == w)))
        return r.error.delta_e_mean;
    ADD_FAILURE() << scene << " " << method << " not in the sweep";
    return 0;
  }
  static std::vector<WboitRow>* rows_;
};
std::vector<WboitRow>* WboitSweep::rows_ = nullptr;

TEST_F(WboitSweep, DefaultWeightAtTheKnee) {
  const WboitFormat def;
  EXPECT_EQ(wboit_best_weight(rows(), def.acc_bits), def.weight_bits);
  // Wider channels gain less than 0.1 CIEDE2000 at the default weight range; 12 bits lose.
  const double at_default = wboit_mean_error(rows(), def.acc_bits, def.weight_bits);
  EXPECT_GT(at_default - wboit_mean_error(rows(), 32, def.weight_bits), -1e-9);
  EXPECT_LT(at_default - wboit_mean_error(rows(), 32, def.weight_bits), 0.1);
  EXPECT_GT(wboit_mean_error(rows(), 12, def.weight_bits), at_default + 0.5);
}

TEST_F(WboitSweep, DepthWeightingBeatsTheWeightedAverage) {
  const WboitFormat def;
  EXPECT_GT(wboit_mean_error(rows(), def.acc_bits, 0),
            wboit_mean_error(rows(), def.acc_bits, def.weight_bits) + 0.2);
}

TEST_F(WboitSweep, NarrowChannelsSaturateAtWideWeightRanges) {
  EXPECT_GT(wboit_mean_error(rows(), 12, 16), wboit_mean_error(rows(), 12, 2) + 0.4);
  EXPECT_LT(wboit_mean_error(rows(), 32, 16), wboit_mean_error(rows(), 12, 16) - 0.4);
}

// Four layers of alpha 0.9: three-pass keeps the nearest layer on top at less traffic than
// wboit, which averages them; on cad's shells and the particles wboit beats it.
TEST_F(WboitSweep, WhereThreePassWins) {
  const WboitFormat d;
  EXPECT_LT(error("layers-4-a90", "three-pass") * 3,
            error("layers-4-a90", "wboit", d.acc_bits, d.weight_bits));
  EXPECT_LT(error("cad", "wboit", d.acc_bits, d.weight_bits), error("cad", "three-pass"));
  EXPECT_LT(error("particles", "wboit", d.acc_bits, d.weight_bits),
            error("particles", "three-pass"));
}

}  // namespace
