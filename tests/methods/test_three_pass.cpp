// three-pass (US 7,834,879) against pixel values worked out in the test from the patent's
// pass rules: 1 opaque, z-test, z-write; 2 transparent, z-test, no z-write, blend;
// 3 transparent, z-test, z-write, blend.
#include <gtest/gtest.h>

#include <algorithm>

#include "support/layers.h"
#include "pipeline/passes.h"
#include "rop/rop.h"

namespace {

using zb::Rgba8;
using zbtest::Layer;
using zbtest::over;

const Rgba8 kBackground{255, 255, 255, 255};
const Layer kOpaque{9000000, {40, 60, 200, 255}};
const Layer kNear{1000000, {230, 30, 30, 128}};
const Layer kMid{3000000, {30, 200, 40, 90}};
const Layer kFar{6000000, {250, 220, 10, 200}};

// The patent's three passes applied to one pixel, with depth LESS, in submit order.
Rgba8 patent_rules(const Layer& opaque, const std::vector<Layer>& transparent) {
  Rgba8 color = kBackground;
  uint32_t depth = zb::depth_max(zb::kDefaultDepthBits);
  if (opaque.z < depth) { color = opaque.color; depth = opaque.z; }          // pass 1
  for (const Layer& l : transparent)                                         // pass 2
    if (l.z < depth) color = over(l.color, color);
  for (const Layer& l : transparent)                                         // pass 3
    if (l.z < depth) { color = over(l.color, color); depth = l.z; }
  return color;
}

Rgba8 run_three_pass(const std::vector<Layer>& transparent) {
  std::vector<Layer> all{kOpaque};
  all.insert(all.end(), transparent.begin(), transparent.end());
  const zb::RasterizedScene rs = zbtest::layer_scene(all, kBackground);
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("three-pass"), rop);
  const Rgba8 c = r.framebuffer.color_at(1, 2);
  for (Rgba8 p : r.framebuffer.color) EXPECT_EQ(p, c) << "layers cover the frame uniformly";
  return c;
}

TEST(ThreePass, OneLayerIsBlendedTwice) {
  const Rgba8 got = run_three_pass({kNear});
  EXPECT_EQ(got, over(kNear.color, over(kNear.color, kOpaque.color)));
  EXPECT_NE(got, over(kNear.color, kOpaque.color)) << "the single layer must count twice";
}

TEST(ThreePass, TwoLayersNearFirst) {
  // Pass 2 blends near then far; pass 3 blends near, whose depth write then hides far.
  const Rgba8 pass2 = over(kFar.color, over(kNear.color, kOpaque.color));
  EXPECT_EQ(run_three_pass({kNear, kFar}), over(kNear.color, pass2));
}

TEST(ThreePass, TwoLayersFarFirst) {
  // Pass 3 blends far, then near, which is nearer still: the nearest is blended last.
  const Rgba8 pass2 = over(kNear.color, over(kFar.color, kOpaque.color));
  EXPECT_EQ(run_three_pass({kFar, kNear}), over(kNear.color, over(kFar.color, pass2)));
}

TEST(ThreePass, ThreeLayersEverySubmitOrder) {
  std::vector<Layer> layers{kNear, kMid, kFar};
  std::sort(layers.begin(), layers.end(), [](auto& a, auto& b) { return a.z < b.z; });
  int orders = 0;
  do {
    EXPECT_EQ(run_three_pass(layers), patent_rules(kOpaque, layers)) << "order " << orders;
    ++orders;
  } while (std::next_permutation(layers.begin(), layers.end(),
                                 [](auto& a, auto& b) { return a.z < b.z; }));
  EXPECT_EQ(orders, 6);
}

TEST(ThreePass, LayerBehindOpaqueIsHidden) {
  const Layer behind{9500000, {0, 0, 0, 128}};
  const Layer hidden{kOpaque.z + 1, {0, 255, 0, 128}};
  EXPECT_EQ(run_three_pass({behind, hidden}), kOpaque.color);
}

TEST(Unsorted, BlendsOnceInSubmitOrder) {
  const zb::RasterizedScene rs = zbtest::layer_scene({kOpaque, kFar, kNear}, kBackground);
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("unsorted"), rop);
  EXPECT_EQ(r.framebuffer.color_at(0, 0), over(kNear.color, over(kFar.color, kOpaque.color)));
  ASSERT_EQ(r.passes.size(), 2u);
  EXPECT_EQ(r.passes[1].depth_writes, 0u);
}

TEST(ThreePass, PassCounters) {
  const zb::RasterizedScene rs = zbtest::layer_scene({kOpaque, kNear, kFar}, kBackground);
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *zb::find_plan("three-pass"), rop);
  const uint64_t px = zbtest::kSize * zbtest::kSize;
  ASSERT_EQ(r.passes.size(), 3u);
  EXPECT_EQ(r.passes[0].fragments_in, px);
  EXPECT_EQ(r.passes[1].fragments_in, 2 * px);
  EXPECT_EQ(r.passes[1].depth_writes, 0u);
  EXPECT_EQ(r.passes[1].color_reads, 2 * px);
  EXPECT_EQ(r.passes[2].fragments_passed, px);  // near passes; far then fails against near
  EXPECT_EQ(r.passes[2].depth_writes, px);
}

}  // namespace
