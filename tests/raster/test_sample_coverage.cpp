// coverage-aa (US 5,123,085): the sample pattern, the coverage rasterizer, the four compositing
// cases and the seam. Expected values are derived here from the patent's rules and the
// documented roundings (docs/datapath.md "Coverage blend"), not from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <utility>

#include "raster/sample_coverage.h"
#include "rop/blend.h"
#include "pipeline/passes.h"
#include "raster/raster.h"
#include "pipeline/render.h"
#include "rop/rop.h"

namespace {

using zb::Fragment;
using zb::Rgba8;

constexpr int kSamplesList[] = {1, 2, 4, 8, 16};

// The documented rounding, with a division: (w*p + (N - w)*b + N/2) / N.
uint8_t mix(uint32_t w, uint32_t p, uint32_t b, uint32_t n) {
  return uint8_t((w * p + (n - w) * b + n / 2) / n);
}
Rgba8 mix(uint32_t w, Rgba8 p, Rgba8 b, uint32_t n) {
  return {mix(w, p.r, b.r, n), mix(w, p.g, b.g, n), mix(w, p.b, b.b, n), mix(w, p.a, b.a, n)};
}

Fragment frag(uint16_t x, uint16_t y, uint32_t z, Rgba8 c, uint8_t cov) {
  Fragment f;
  f.x = x;
  f.y = y;
  f.z = z;
  f.color = c;
  f.coverage = cov;
  return f;
}

zb::RopState coverage_state() {
  zb::RopState s;
  s.depth_test = true;
  s.depth_func = zb::DepthFunc::kLess;
  s.depth_write = true;
  s.blend = zb::BlendMode::kCoverage;
  return s;
}

TEST(CoveragePattern, NRooksOnTheSubpixelGrid) {
  for (int n : kSamplesList) {
    const std::vector<zb::SamplePos>& p = zb::sample_pattern(n);
    ASSERT_EQ(int(p.size()), n);
    const int pitch = 256 / n;
    std::set<int> cols, rows;
    for (int i = 0; i < n; ++i) {
      EXPECT_EQ(p[i].y, i * pitch + pitch / 2) << "n=" << n << " sample " << i;
      EXPECT_EQ(p[i].x % pitch, pitch / 2) << "n=" << n << " sample " << i;
      EXPECT_GE(p[i].x, 0);
      EXPECT_LT(p[i].x, 256);
      cols.insert(p[i].x);
      rows.insert(p[i].y);
    }
    EXPECT_EQ(int(cols.size()), n) << "one sample per column";
    EXPECT_EQ(int(rows.size()), n) << "one sample per row";
  }
  EXPECT_EQ(zb::sample_pattern(1)[0].x, 128);  // N = 1: the pixel centre
  EXPECT_EQ(zb::sample_pattern(1)[0].y, 128);
  EXPECT_THROW(zb::sample_pattern(3), std::invalid_argument);
  EXPECT_THROW(zb::sample_pattern(32), std::invalid_argument);
}

TEST(CoverageFixed, WidthsAndBlend) {
  EXPECT_EQ(zb::coverage_bits(1), 1);
  EXPECT_EQ(zb::coverage_bits(2), 2);
  EXPECT_EQ(zb::coverage_bits(4), 3);
  EXPECT_EQ(zb::coverage_bits(8), 4);
  EXPECT_EQ(zb::coverage_bits(16), 5);
  for (int n : kSamplesList)
    for (uint32_t w = 0; w <= uint32_t(n); ++w)
      for (uint32_t p = 0; p < 256; p += 3)
        for (uint32_t b = 0; b < 256; b += 5)
          ASSERT_EQ(zb::blend_coverage(uint8_t(p), uint8_t(b), w, n), mix(w, p, b, uint32_t(n)));
}

zb::ScreenTriangle tri(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2,
                       uint32_t z0, uint32_t z1, uint32_t z2, Rgba8 c = {200, 100, 50, 255}) {
  zb::ScreenTriangle t;
  t.v[0] = {x0, y0, z0, z0 / 16777215.0};
  t.v[1] = {x1, y1, z1, z1 / 16777215.0};
  t.v[2] = {x2, y2, z2, z2 / 16777215.0};
  t.color = c;
  return t;
}

// With one sample at the centre the coverage rasterizer is the rasterizer: same pixels, same
// depths, in the same order; the pattern goes through the same edge functions and fill rule.
TEST(CoverageRaster, OneSampleIsTheRasterizer) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> c(-2000, 24 * 256);
  std::uniform_int_distribution<uint32_t> z(0, 16777215);
  const zb::Viewport vp{20, 20, 24, 1};
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    zb::ScreenTriangle t = tri(c(rng), c(rng), c(rng), c(rng), c(rng), c(rng), z(rng), z(rng),
                               z(rng));
    if (i % 3 == 0) {  // snap to pixel corners and centres: exact ties on edges
      for (auto& v : t.v) v.x = v.x / 128 * 128, v.y = v.y / 128 * 128;
    }
    std::vector<Fragment> a, b;
    zb::rasterize(t, vp, a);
    zb::rasterize_coverage(t, vp, b);
    ASSERT_EQ(a.size(), b.size()) << "triangle " << i;
    for (size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(a[k].x, b[k].x);
      ASSERT_EQ(a[k].y, b[k].y);
      ASSERT_EQ(a[k].z, b[k].z);
      ASSERT_EQ(b[k].coverage, 1);
      ASSERT_EQ(a[k].coverage, 1);  // ordinary fragments carry the full count
    }
    compared += int(a.size());
  }
  EXPECT_GT(compared, 10000);
}

// Triangles sharing edges split every sample exactly: a fan of triangles around an interior
// vertex whose outer polygon contains the frame covers every sample of every pixel once.
TEST(CoverageRaster, SharedEdgesSplitEverySampleExactly) {
  std::mt19937 rng(5);
  for (int n : kSamplesList) {
    for (int trial = 0; trial < 40; ++trial) {
      const int w = 24, h = 20;
      const zb::Viewport vp{w, h, 24, n};
      std::uniform_int_distribution<int32_t> cx(256, (w - 1) * 256), cy(256, (h - 1) * 256);
      // Centre: on the sub-pixel grid, half the time on a sample row or pixel corner.
      int32_t ox = cx(rng), oy = cy(rng);
      if (trial % 2) ox = ox / 8 * 8, oy = oy / 8 * 8;
      const int32_t far = 64 * 256;
      const int32_t ring[][2] = {{-far, -far}, {ox + 37, -far}, {far, -far},  {far, oy - 11},
                                 {far, far},   {ox - 5, far},   {-far, far},  {-far, oy + 3}};
      std::map<std::pair<int, int>, int> sum;
      for (int k = 0; k < 8; ++k) {
        const int32_t* a = ring[k];
        const int32_t* b = ring[(k + 1) % 8];
        std::vector<Fragment> f;
        zb::rasterize_coverage(tri(ox, oy, a[0], a[1], b[0], b[1], 5, 5, 5), vp, f);
        for (const Fragment& fr : f) {
          ASSERT_GE(fr.coverage, 1);
          ASSERT_LE(fr.coverage, n);
          sum[{fr.x, fr.y}] += fr.coverage;
        }
      }
      ASSERT_EQ(int(sum.size()), w * h) << "n=" << n;
      for (const auto& [pix, s] : sum)
        ASSERT_EQ(s, n) << "n=" << n << " trial " << trial << " pixel " << pix.first << ","
                        << pix.second;
    }
  }
}

// Depth at the pixel centre: the rasterizer's value where the centre is covered, and inside
// the vertex depth range everywhere.
TEST(CoverageRaster, DepthAtTheCentreClamped) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int32_t> c(0, 16 * 256);
  std::uniform_int_distribution<uint32_t> z(0, 16777215);
  const zb::Viewport vp{16, 16, 24, 16};
  int outside = 0, inside = 0;
  for (int i = 0; i < 500; ++i) {
    const zb::ScreenTriangle t =
        tri(c(rng), c(rng), c(rng), c(rng), c(rng), c(rng), z(rng), z(rng), z(rng));
    std::vector<Fragment> centre, cov;
    zb::rasterize(t, vp, centre);
    zb::rasterize_coverage(t, vp, cov);
    std::map<std::pair<int, int>, uint32_t> zc;
    for (const Fragment& f : centre) zc[{f.x, f.y}] = f.z;
    const uint32_t lo = std::min({t.v[0].z, t.v[1].z, t.v[2].z});
    const uint32_t hi = std::max({t.v[0].z, t.v[1].z, t.v[2].z});
    size_t found = 0;
    for (const Fragment& f : cov) {
      EXPECT_GE(f.z, lo);
      EXPECT_LE(f.z, hi);
      auto it = zc.find({f.x, f.y});
      if (it != zc.end()) {
        ++found;
        EXPECT_EQ(f.z, it->second);
      } else {
        ++outside;
      }
    }
    // A sliver may cover a centre and no sample, so not every centre pixel is here.
    EXPECT_LE(found, centre.size());
    inside += int(found);
  }
  EXPECT_GT(inside, 5000) << "pixels with a covered centre were compared";
  EXPECT_GT(outside, 1000) << "edge pixels whose centre is outside were exercised";
}

// The total coverage of a triangle is its area in samples, to within the edge pixels.
TEST(CoverageRaster, TotalCoverageIsTheArea) {
  const zb::Viewport vp{64, 64, 24, 16};
  // Right triangle with legs 40 and 30 pixels, vertices off the pixel grid: area 600 pixels.
  const zb::ScreenTriangle t = tri(3 * 256 + 77, 5 * 256 + 19, 43 * 256 + 77, 5 * 256 + 19,
                                   3 * 256 + 77, 35 * 256 + 19, 7, 7, 7);
  std::vector<Fragment> f;
  zb::rasterize_coverage(t, vp, f);
  int total = 0, full = 0;
  for (const Fragment& fr : f) {
    total += fr.coverage;
    full += fr.coverage == 16;
  }
  EXPECT_NEAR(total / 16.0, 600.0, 3.0);
  EXPECT_GT(full, 500);
}

// ---- The four cases of claim 1, by hand on single pixels (N = 16 unless said) ----

TEST(CoverageBlend, FourCasesByHand) {
  const Rgba8 bg{255, 255, 255, 255}, p1{40, 80, 160, 255}, p2{200, 10, 0, 128},
              p3{7, 77, 177, 255};
  zb::GoldenRop rop;
  rop.begin_frame(4, 1, 24, bg, 16);
  rop.begin_pass(coverage_state());
  const zb::Framebuffer& fb = rop.framebuffer();

  // Nearer than the cleared pixel (depth ZMAX, coverage 0): first blend by k = 5.
  rop.process(frag(0, 0, 1000, p1, 5));
  const Rgba8 c1 = mix(5, p1, bg, 16);
  EXPECT_EQ(fb.color_at(0, 0), c1);
  EXPECT_EQ(c1, (Rgba8{(5 * 40 + 11 * 255 + 8) / 16, (5 * 80 + 11 * 255 + 8) / 16,
                       (5 * 160 + 11 * 255 + 8) / 16, 255}));
  EXPECT_EQ(fb.depth_at(0, 0), 1000u);
  EXPECT_EQ(fb.coverage_at(0, 0), 5);

  // Farther (2000 > 1000): second blend, the background keeps its 5 samples; depth kept;
  // coverage combined 5 + 7.
  rop.process(frag(0, 0, 2000, p2, 7));
  const Rgba8 c2 = mix(16 - 5, p2, c1, 16);
  EXPECT_EQ(fb.color_at(0, 0), c2);
  EXPECT_EQ(fb.depth_at(0, 0), 1000u);
  EXPECT_EQ(fb.coverage_at(0, 0), 12);

  // Equal depth, combined 12 + 4 = 16 full: the polygon's colour, full coverage.
  rop.process(frag(0, 0, 1000, p3, 4));
  EXPECT_EQ(fb.color_at(0, 0), p3);
  EXPECT_EQ(fb.depth_at(0, 0), 1000u);
  EXPECT_EQ(fb.coverage_at(0, 0), 16);

  // Equal depth, not full: first blend by k, coverage combined.
  rop.process(frag(1, 0, 500, p1, 3));
  rop.process(frag(1, 0, 500, p2, 6));
  const Rgba8 c3 = mix(6, p2, mix(3, p1, bg, 16), 16);
  EXPECT_EQ(fb.color_at(1, 0), c3);
  EXPECT_EQ(fb.depth_at(1, 0), 500u);
  EXPECT_EQ(fb.coverage_at(1, 0), 9);
  // Nearer again, 12 more samples: coverage min(16, 21) = 16; depth moves.
  rop.process(frag(1, 0, 400, p3, 12));
  EXPECT_EQ(fb.color_at(1, 0), mix(12, p3, c3, 16));
  EXPECT_EQ(fb.depth_at(1, 0), 400u);
  EXPECT_EQ(fb.coverage_at(1, 0), 16);
  // Farther behind a full pixel: nothing shows (weight 16 - 16 = 0).
  const Rgba8 before = fb.color_at(1, 0);
  rop.process(frag(1, 0, 900, p1, 16));
  EXPECT_EQ(fb.color_at(1, 0), before);
  EXPECT_EQ(fb.coverage_at(1, 0), 16);

  // Equal and more than full (11 + 9 > 16): still the polygon colour, coverage 16.
  rop.process(frag(2, 0, 300, p1, 11));
  rop.process(frag(2, 0, 300, p2, 9));
  EXPECT_EQ(fb.color_at(2, 0), p2);
  EXPECT_EQ(fb.coverage_at(2, 0), 16);

  // Coverage 0 (never sent by the rasterizer, defined anyway): nearer moves depth only.
  rop.process(frag(3, 0, 100, p1, 0));
  EXPECT_EQ(fb.color_at(3, 0), bg);
  EXPECT_EQ(fb.depth_at(3, 0), 100u);
  EXPECT_EQ(fb.coverage_at(3, 0), 0);

  const zb::PassStats st = rop.end_pass();
  EXPECT_EQ(st.fragments_in, 10u);
  EXPECT_EQ(st.fragments_passed, 10u);  // every fragment is composited
  EXPECT_EQ(st.depth_reads, 10u);
  EXPECT_EQ(st.depth_writes, 5u);       // the nearer cases: 1000, 500, 400, 300, 100
  EXPECT_EQ(st.color_writes, 10u);
}

TEST(CoverageBlend, StateBitsAndOtherSampleCounts) {
  const Rgba8 bg{0, 0, 0, 0}, p{255, 128, 64, 255};
  for (int n : {1, 4}) {
    zb::GoldenRop rop;
    rop.begin_frame(3, 1, 16, bg, n);
    zb::RopState s = coverage_state();
    s.depth_func = zb::DepthFunc::kNever;  // not used in coverage mode
    s.depth_write = false;                 // depth kept; colour and coverage still composite
    s.color_mask = zb::kMaskR | zb::kMaskA;
    rop.begin_pass(s);
    rop.process(frag(0, 0, 10, p, uint8_t(n > 1 ? 1 : 1)));
    const zb::Framebuffer& fb = rop.framebuffer();
    EXPECT_EQ(fb.depth_at(0, 0), zb::depth_max(16));
    EXPECT_EQ(fb.coverage_at(0, 0), 1);
    EXPECT_EQ(fb.color_at(0, 0), (Rgba8{mix(1, 255, 0, n), 0, 0, mix(1, 255, 0, n)}));
    EXPECT_THROW(rop.process(frag(1, 0, 10, p, uint8_t(n + 1))), std::invalid_argument);
    rop.end_pass();
  }
  zb::GoldenRop rop;
  EXPECT_THROW(rop.begin_frame(1, 1, 24, bg, 3), std::invalid_argument);
  EXPECT_THROW(rop.begin_frame(1, 1, 24, bg, 32), std::invalid_argument);
}

// A non-coverage pass leaves the coverage plane alone.
TEST(CoverageBlend, OtherModesKeepTheCoveragePlane) {
  zb::GoldenRop rop;
  rop.begin_frame(1, 1, 24, {1, 2, 3, 4}, 16);
  rop.begin_pass(coverage_state());
  rop.process(frag(0, 0, 10, {9, 9, 9, 9}, 6));
  rop.end_pass();
  zb::RopState s;
  s.blend = zb::BlendMode::kAlpha;
  s.depth_func = zb::DepthFunc::kAlways;
  rop.begin_pass(s);
  rop.process(frag(0, 0, 5, {9, 9, 9, 9}, 16));
  rop.end_pass();
  EXPECT_EQ(rop.framebuffer().coverage_at(0, 0), 6);
}

// ---- The seam: two triangles sharing an edge, same colour, over a white background ----

struct SeamResult {
  int seam_pixels = 0;       // pixels both triangles cover partly
  int leaking = 0;           // of those, pixels not equal to the polygon colour
  double leak_sum = 0;       // background share summed over the seam pixels (in pixels)
  double leak_max = 0;       // largest background share of one pixel
};

// A quad over the whole 32 x 24 frame split along a slanted diagonal, T1 drawn first at depth
// z1, T2 at z2, with the coverage-aa plan. Every pixel is checked against the patent's rules:
// a seam pixel with a samples from T1 and N - a from T2 ends as
//   z1 == z2 (equal, combined a + N - a = N full): the polygon colour;
//   z2 > z1 (farther): second blend by the background's a: (a*C1 + (N-a)*p + N/2) / N;
//   z2 < z1 (nearer): first blend by N - a: ((N-a)*p + a*C1 + N/2) / N,
// with C1 = (a*p + (N-a)*white + N/2) / N. The share of white left is (v - p) / (255 - p).
SeamResult seam(uint32_t z1, uint32_t z2, int n) {
  const Rgba8 white{255, 255, 255, 255}, p{40, 90, 160, 255};
  const int w = 32, h = 24;
  const int32_t far = 100 * 256;
  // Seam from (-3.3, -40.1) to (35.7, 70.9) pixels: steep, crossing every row off the grid.
  const int32_t ax = -845, ay = -10266, cx = 9139, cy = 18150;
  std::vector<zb::ScreenTriangle> tris = {tri(ax, ay, far, -far, cx, cy, z1, z1, z1, p),
                                          tri(ax, ay, cx, cy, -far, far, z2, z2, z2, p)};
  tris[1].prim = 1;
  const zb::RasterizedScene rs = zb::rasterize_triangles(tris, {w, h, 24, n}, white);
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("coverage-aa"), rop);
  std::vector<Fragment> f1;
  zb::rasterize_coverage(tris[0], rs.viewport, f1);
  std::map<std::pair<int, int>, int> a;
  for (const Fragment& f : f1) a[{f.x, f.y}] = f.coverage;
  SeamResult out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int k = a.count({x, y}) ? a[{x, y}] : 0;
      const Rgba8 c1 = mix(uint32_t(k), p, white, uint32_t(n));
      Rgba8 want = p;
      if (k > 0 && k < n) {
        if (z2 > z1) want = mix(uint32_t(k), c1, p, uint32_t(n));
        if (z2 < z1) want = mix(uint32_t(n - k), p, c1, uint32_t(n));
      } else if (k == n) {
        want = c1;  // T1 alone, full: the polygon colour
      }
      const Rgba8 got = r.framebuffer.color_at(x, y);
      EXPECT_EQ(got, want) << "pixel " << x << "," << y << " a=" << k;
      EXPECT_EQ(r.framebuffer.coverage_at(x, y), n) << "pixel " << x << "," << y;
      if (k > 0 && k < n) {
        ++out.seam_pixels;
        out.leaking += got != p;
        const double share = (got.r - p.r) / double(255 - p.r);
        out.leak_sum += share;
        out.leak_max = std::max(out.leak_max, share);
      }
    }
  return out;
}

TEST(CoverageSeam, EqualDepthsDoNotLeak) {
  for (int n : {4, 16}) {
    const SeamResult s = seam(5000, 5000, n);
    EXPECT_GT(s.seam_pixels, 15) << "n=" << n;
    EXPECT_EQ(s.leaking, 0) << "n=" << n;
    EXPECT_EQ(s.leak_sum, 0.0);
  }
}

// Patent single-value coverage: with different depths each seam pixel keeps a share
// a (N - a) / N^2 of the background, up to 1/4 where the seam halves the pixel; summed over
// the seam that is the figure asserted here (rounding to 8 bits aside).
TEST(CoverageSeam, DifferentDepthsLeakTheBackground) {
  for (uint32_t z2 : {9000u, 1000u}) {  // T2 behind T1, then in front
    const int n = 16;
    const SeamResult s = seam(5000, z2, n);
    EXPECT_GT(s.seam_pixels, 15);
    EXPECT_EQ(s.leaking, s.seam_pixels) << "every partly covered seam pixel shows white";
    // Expected from the sample counts alone: sum of a(N - a)/N^2 over the seam.
    const Rgba8 white{255, 255, 255, 255};
    const int32_t far = 100 * 256;
    std::vector<Fragment> f1;
    zb::rasterize_coverage(tri(-845, -10266, far, -far, 9139, 18150, 5000, 5000, 5000, white),
                           {32, 24, 24, n}, f1);
    double expect = 0, expect_max = 0;
    for (const Fragment& f : f1)
      if (f.coverage < n) {
        const double share = double(f.coverage) * (n - f.coverage) / (n * n);
        expect += share;
        expect_max = std::max(expect_max, share);
      }
    EXPECT_NEAR(s.leak_sum, expect, 0.01 * s.seam_pixels);  // 8-bit rounding, < 1/215 each
    EXPECT_NEAR(s.leak_max, expect_max, 0.01);
    EXPECT_LE(s.leak_max, 0.25 + 0.01);
    std::printf("coverage seam, N=%d, z2 %s z1: %d seam pixels, leak %.3f pixels of "
                "background (mean %.3f, max %.3f)\n",
                n, z2 > 5000 ? ">" : "<", s.seam_pixels, s.leak_sum,
                s.leak_sum / s.seam_pixels, s.leak_max);
  }
}

// The plan: one pass over all primitives, coverage blend, depth write on.
TEST(CoveragePlan, OnePassCoverageBlend) {
  const zb::PassPlan* plan = zb::find_plan("coverage-aa");
  ASSERT_NE(plan, nullptr);
  ASSERT_EQ(plan->passes.size(), 1u);
  EXPECT_EQ(plan->passes[0].filter, zb::PrimFilter::kAll);
  EXPECT_EQ(plan->passes[0].rop.blend, zb::BlendMode::kCoverage);
  EXPECT_TRUE(plan->passes[0].rop.depth_write);
  EXPECT_TRUE(zb::is_coverage_pass(plan->passes[0].rop));
}

}  // namespace
