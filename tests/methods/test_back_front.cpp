// back-front (US 5,923,333) against pixels worked out in the test from the patent's claim:
// (a) opaque primitives with z-buffer writes; (b) z-writes off, front-facing transparent
// primitives culled, back-facing ones blended where in front of the opaque depth; (c) the same
// with the back-facing ones culled. Exact for one convex object, wrong for the torus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "support/layers.h"
#include "metrics/metrics.h"
#include "pipeline/passes.h"
#include "reference/reference.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"

namespace {

using zb::Rgba8;
using zbtest::over;

const Rgba8 kBackground{255, 255, 255, 255};

struct Face {
  uint32_t z;
  Rgba8 color;
  bool front;
};

// Full-frame triangles at constant depth with the given winding flag, in submit order.
zb::RasterizedScene faces_scene(const std::vector<Face>& faces) {
  std::vector<zbtest::Layer> layers;
  for (const Face& f : faces) layers.push_back({f.z, f.color});
  zb::RasterizedScene rs = zbtest::layer_scene(layers, kBackground);
  for (size_t i = 0; i < faces.size(); ++i) {
    rs.triangles[i].front = faces[i].front;
    for (size_t k = rs.first_fragment[i]; k < rs.first_fragment[i + 1]; ++k)
      rs.fragments[k].front = faces[i].front;
  }
  return rs;
}

// The claim applied to one pixel: opaque with LESS and z-write, then every back-facing
// transparent face in submit order, then every front-facing one, each blended when nearer
// than the stored (opaque) depth.
Rgba8 claim(const std::vector<Face>& faces) {
  Rgba8 c = kBackground;
  uint32_t depth = zb::depth_max(zb::kDefaultDepthBits);
  for (const Face& f : faces)
    if (f.color.a == 255 && f.z < depth) { c = f.color; depth = f.z; }   // (a)
  for (bool front : {false, true})                                       // (b), (c)
    for (const Face& f : faces)
      if (f.color.a < 255 && f.front == front && f.z < depth) c = over(f.color, c);
  return c;
}

Rgba8 run(const std::vector<Face>& faces) {
  const zb::RasterizedScene rs = faces_scene(faces);
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("back-front"), rop);
  for (Rgba8 p : r.framebuffer.color) EXPECT_EQ(p, r.framebuffer.color_at(0, 0));
  return r.framebuffer.color_at(0, 0);
}

const Face kOpaque{9000000, {40, 60, 200, 255}, true};
const Face kFrontNear{1000000, {230, 30, 30, 128}, true};
const Face kBackFar{5000000, {30, 200, 40, 90}, false};

TEST(BackFront, BackFacesBeforeFrontFacesWhateverTheSubmitOrder) {
  // Submitted front face first: the plan still blends the back face first.
  const Rgba8 want = over(kFrontNear.color, over(kBackFar.color, kOpaque.color));
  EXPECT_EQ(run({kOpaque, kFrontNear, kBackFar}), want);
  EXPECT_EQ(run({kFrontNear, kBackFar, kOpaque}), want);
  EXPECT_EQ(claim({kFrontNear, kBackFar, kOpaque}), want);
  EXPECT_NE(want, over(kBackFar.color, over(kFrontNear.color, kOpaque.color)));
}

TEST(BackFront, FacesBehindOpaqueAreCulledByDepth) {
  const Face behind_back{9500000, {0, 0, 0, 200}, false};
  const Face behind_front{9000001, {0, 255, 0, 200}, true};
  EXPECT_EQ(run({behind_back, kOpaque, behind_front}), kOpaque.color);
}

TEST(BackFront, TwoBackFacesBlendInSubmitOrder) {
  // The method does not sort within a pass: two back faces blend in submit order.
  const Face back_near{2000000, {250, 220, 10, 200}, false};
  const std::vector<Face> faces{kOpaque, back_near, kBackFar, kFrontNear};
  const Rgba8 want = over(kFrontNear.color, over(kBackFar.color, over(back_near.color, kOpaque.color)));
  EXPECT_EQ(claim(faces), want);
  EXPECT_EQ(run(faces), want);
}

TEST(BackFront, PassCountersCullByWinding) {
  const zb::RasterizedScene rs = faces_scene({kOpaque, kFrontNear, kBackFar});
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("back-front"), rop);
  const uint64_t px = zbtest::kSize * zbtest::kSize;
  ASSERT_EQ(r.passes.size(), 3u);
  EXPECT_EQ(r.passes[1].fragments_in, px);  // only the back face
  EXPECT_EQ(r.passes[2].fragments_in, px);  // only the front face
  EXPECT_EQ(r.passes[1].depth_writes + r.passes[2].depth_writes, 0u);
}

// --- exact for a convex object, wrong for the torus ------------------------------------------

// The exact composite with the datapath's own integer blend: per pixel, the nearest opaque
// fragment (LESS, first in submit order on ties) over the background, then every transparent
// fragment nearer than it, back to front by unrounded depth.
zb::Framebuffer sorted_composite(const zb::RasterizedScene& rs) {
  const zb::Viewport& vp = rs.viewport;
  zb::Framebuffer fb(vp.width, vp.height, vp.depth_bits, rs.background);
  std::vector<std::vector<size_t>> at(fb.color.size());
  for (size_t i = 0; i < rs.fragments.size(); ++i)
    at[fb.index(rs.fragments[i].x, rs.fragments[i].y)].push_back(i);
  for (size_t p = 0; p < at.size(); ++p) {
    uint32_t depth = zb::depth_max(vp.depth_bits);
    Rgba8 c = rs.background;
    for (size_t i : at[p]) {
      const zb::Fragment& f = rs.fragments[i];
      if (f.color.a == 255 && f.z < depth) { depth = f.z; c = f.color; }
    }
    std::vector<size_t> layers;
    for (size_t i : at[p])
      if (rs.fragments[i].color.a < 255 && rs.fragments[i].z < depth) layers.push_back(i);
    std::stable_sort(layers.begin(), layers.end(),
                     [&](size_t a, size_t b) { return rs.z_exact[a] > rs.z_exact[b]; });
    for (size_t i : layers) c = over(rs.fragments[i].color, c);
    fb.color[p] = c;
  }
  return fb;
}

struct Diff {
  int max_abs = 0;
  size_t over2 = 0, over16 = 0;
};

Diff diff_rgb(const zb::Framebuffer& a, const zb::Framebuffer& b) {
  Diff d;
  for (size_t i = 0; i < a.color.size(); ++i) {
    const int w = std::max({std::abs(a.color[i].r - b.color[i].r), std::abs(a.color[i].g - b.color[i].g),
                            std::abs(a.color[i].b - b.color[i].b)});
    d.max_abs = std::max(d.max_abs, w);
    d.over2 += w > 2;
    d.over16 += w > 16;
  }
  return d;
}

constexpr int kW = 200, kH = 150;

zb::Framebuffer render_back_front(const zb::RasterizedScene& rs) {
  zb::GoldenRop rop;
  return zb::render(rs, *zb::find_plan("back-front"), rop).framebuffer;
}

TEST(BackFront, ExactForOneConvexObject) {
  // sphere-torus without the torus: one closed convex transparent sphere over the ground.
  zb::Scene s = *zb::builtin_scene("sphere-torus");
  s.objects.erase(std::remove_if(s.objects.begin(), s.objects.end(),
                                 [](const zb::Object& o) { return o.name == "torus"; }),
                  s.objects.end());
  ASSERT_EQ(s.objects.size(), 2u);
  const zb::RasterizedScene rs = zb::rasterize_scene(s, {kW, kH, 24});
  const zb::Framebuffer got = render_back_front(rs);
  // Equal, bit for bit, to the depth-sorted composite with the same integer blend.
  const Diff vs_sorted = diff_rgb(got, sorted_composite(rs));
  EXPECT_EQ(vs_sorted.max_abs, 0);
  // And within the blend's rounding of the float reference. Each layer's m(s, a) + m(d, 255-a)
  // is within 2 x 0.502 of a*s + (1-a)*d; an earlier layer's error is scaled by (1 - a) < 1,
  // so with at most two layers the integer result is within 1.004 + 1.004 < 2.01 of the exact
  // value, which the reference rounds to within 0.5: at most 2 apart as integers.
  const Diff vs_ref = diff_rgb(got, zb::render_reference(rs));
  EXPECT_LE(vs_ref.max_abs, 2);
}

TEST(BackFront, WrongForTheTorus) {
  const zb::RasterizedScene rs = zb::rasterize_scene(*zb::builtin_scene("sphere-torus"), {kW, kH, 24});
  const zb::Framebuffer got = render_back_front(rs);
  const Diff vs_sorted = diff_rgb(got, sorted_composite(rs));
  const Diff vs_ref = diff_rgb(got, zb::render_reference(rs));
  // The torus has up to four layers of itself per pixel: two back and two front faces, each
  // pair blended in submit order, not by depth. (Measured at 200x150: see the figures printed.)
  std::printf("back-front sphere-torus %dx%d: vs sorted max %d, >2 %zu, >16 %zu; "
              "vs reference max %d, >2 %zu, >16 %zu\n", kW, kH, vs_sorted.max_abs, vs_sorted.over2,
              vs_sorted.over16, vs_ref.max_abs, vs_ref.over2, vs_ref.over16);
  EXPECT_GE(vs_sorted.max_abs, 32);
  EXPECT_GE(vs_sorted.over16, 50u);
  EXPECT_GE(vs_ref.over16, 50u);
}

}  // namespace
