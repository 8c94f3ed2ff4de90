// depth-peel-K (Everitt 2001) against values worked out in the test from the method's rules:
// the layers in front of the opaque surface, nearest first, accumulated front to back into a
// premultiplied colour (t = 255 - A: C += m(m(s, a), t), A += m(a, t), each saturating), the
// opaque surface under them, then the resolve over the background (C += m(bg, 255 - A)).
// Written with zbtest::m_spec, independently of the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "support/layers.h"
#include "pipeline/passes.h"
#include "rop/rop.h"
#include "io/trace.h"

namespace {

using zb::Rgba8;
using zbtest::Layer;
using zbtest::kBackground;
using zbtest::kOpaque;
using zbtest::m_spec;
using zbtest::make_layers;
using zbtest::sat;

// The method's rules on one pixel: the nearest `keep` layers in front of the opaque surface.
Rgba8 front_to_back(std::vector<Layer> layers, size_t keep) {
  std::sort(layers.begin(), layers.end(), [](auto& a, auto& b) { return a.z < b.z; });
  uint32_t c[4] = {0, 0, 0, 0};
  auto under = [&](Rgba8 s) {
    const uint32_t t = 255 - c[3];
    const uint32_t src[3] = {s.r, s.g, s.b};
    for (int i = 0; i < 3; ++i) c[i] = sat(c[i] + m_spec(m_spec(src[i], s.a), t));
    c[3] = sat(c[3] + m_spec(s.a, t));
  };
  size_t used = 0;
  for (const Layer& l : layers)
    if (l.z < kOpaque.z && used < keep) {
      under(l.color);
      ++used;
    }
  under(kOpaque.color);
  const uint32_t bg[4] = {kBackground.r, kBackground.g, kBackground.b, kBackground.a};
  const uint32_t a = c[3];
  for (int i = 0; i < 4; ++i) c[i] = sat(c[i] + m_spec(bg[i], 255 - a));
  return {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2]), uint8_t(c[3])};
}

Rgba8 run_peel(int k, const std::vector<Layer>& transparent) {
  std::vector<Layer> all{kOpaque};
  all.insert(all.end(), transparent.begin(), transparent.end());
  const zb::RasterizedScene rs = zbtest::layer_scene(all, kBackground);
  const zb::PassPlan* plan = zb::find_plan("depth-peel-" + std::to_string(k));
  EXPECT_NE(plan, nullptr);
  if (!plan) return {};
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, *plan, rop);
  const Rgba8 c = r.framebuffer.color_at(1, 2);
  for (Rgba8 p : r.framebuffer.color) EXPECT_EQ(p, c) << "layers cover the frame uniformly";
  return c;
}

// Submit orders of `layers`: every permutation up to 6 layers; beyond, 300 seeded shuffles
// plus nearest-first and farthest-first (8! = 40320 renders would dominate the unit tests).
std::vector<std::vector<Layer>> orders(std::vector<Layer> layers) {
  std::vector<std::vector<Layer>> out;
  auto by_z = [](const Layer& a, const Layer& b) { return a.z < b.z; };
  std::sort(layers.begin(), layers.end(), by_z);
  if (layers.size() <= 6) {
    do out.push_back(layers);
    while (std::next_permutation(layers.begin(), layers.end(), by_z));
    return out;
  }
  out.push_back(layers);
  out.emplace_back(layers.rbegin(), layers.rend());
  std::mt19937 rng(12345);
  for (int i = 0; i < 300; ++i) {
    std::shuffle(layers.begin(), layers.end(), rng);
    out.push_back(layers);
  }
  return out;
}

TEST(DepthPeel, PlansRegistered) {
  for (int k : {2, 4, 8}) {
    const zb::PassPlan* p = zb::find_plan("depth-peel-" + std::to_string(k));
    ASSERT_NE(p, nullptr) << k;
    EXPECT_EQ(p->passes.size(), size_t(3 * k + 2));  // 3 per peel, opaque depth and under
    ASSERT_EQ(p->final_ops.size(), 1u);
    EXPECT_EQ(p->final_ops[0].kind, zb::FrameOpKind::kResolveUnder);
  }
}

// Only the nearest opaque surface counts, whichever opaque primitive is submitted first: a
// second opaque layer behind kOpaque, submitted before it, must not show.
TEST(DepthPeel, NearestOpaqueWinsInAnySubmitOrder) {
  const Layer far_opaque{14000000, {200, 10, 10, 255}};
  const std::vector<Layer> layers = make_layers(2);
  const Rgba8 want = front_to_back(layers, 2);
  for (int k : {2, 4}) {
    std::vector<Layer> all{far_opaque, kOpaque};
    all.insert(all.end(), layers.begin(), layers.end());
    const zb::RasterizedScene rs = zbtest::layer_scene(all, kBackground);
    zb::GoldenRop rop;
    const zb::RenderResult r = zb::render(rs, *zb::find_plan("depth-peel-" + std::to_string(k)), rop);
    EXPECT_EQ(r.framebuffer.color_at(0, 0), want) << "k=" << k;
  }
}

// The anchor: exact for 1..K layers in every submit order.
TEST(DepthPeel, ExactUpToKLayers) {
  for (int k : {2, 4, 8})
    for (int n = 1; n <= k; ++n) {
      const std::vector<Layer> layers = make_layers(n);
      const Rgba8 want = front_to_back(layers, size_t(n));
      int order = 0;
      for (const auto& o : orders(layers)) {
        ASSERT_EQ(run_peel(k, o), want) << "K=" << k << " layers=" << n << " order " << order;
        ++order;
      }
    }
}

// K+1 layers: the farthest layer is missing (the result is the nearest K's composite).
TEST(DepthPeel, KPlusOneLayersMissesTheFarthest) {
  for (int k : {2, 4, 8}) {
    const std::vector<Layer> layers = make_layers(k + 1);
    const Rgba8 exact = front_to_back(layers, size_t(k + 1));
    const Rgba8 nearest_k = front_to_back(layers, size_t(k));
    ASSERT_NE(exact, nearest_k) << "the test layers must make the farthest one visible";
    for (const auto& o : {layers, std::vector<Layer>(layers.rbegin(), layers.rend())}) {
      const Rgba8 got = run_peel(k, o);
      EXPECT_NE(got, exact) << "K=" << k;
      EXPECT_EQ(got, nearest_k) << "K=" << k;
    }
  }
}

TEST(DepthPeel, LayersBehindOpaqueAndNoLayers) {
  EXPECT_EQ(run_peel(2, {}), kOpaque.color);
  const Layer behind{kOpaque.z + 1, {0, 255, 0, 128}};
  EXPECT_EQ(run_peel(2, {behind}), kOpaque.color);
  // No opaque surface: the layers resolve over the background.
  const std::vector<Layer> two = make_layers(2);
  const zb::RasterizedScene rs = zbtest::layer_scene(two, kBackground);
  zb::GoldenRop rop;
  const Rgba8 got = zb::render(rs, *zb::find_plan("depth-peel-2"), rop).framebuffer.color_at(0, 0);
  // Expected: the chain without the opaque surface, then the resolve.
  uint32_t c[4] = {0, 0, 0, 0};
  for (const Layer& l : two) {
    const uint32_t t = 255 - c[3];
    const uint32_t src[3] = {l.color.r, l.color.g, l.color.b};
    for (int i = 0; i < 3; ++i) c[i] = sat(c[i] + m_spec(m_spec(src[i], l.color.a), t));
    c[3] = sat(c[3] + m_spec(l.color.a, t));
  }
  const uint32_t bg[4] = {kBackground.r, kBackground.g, kBackground.b, kBackground.a};
  const uint32_t a = c[3];
  for (int i = 0; i < 4; ++i) c[i] = sat(c[i] + m_spec(bg[i], 255 - a));
  EXPECT_EQ(got, (Rgba8{uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2]), uint8_t(c[3])}));
}

// Ties (a known limit, docs/datapath.md "Depth peeling"): two layers at one depth both blend in
// the peel that finds that depth.
TEST(DepthPeel, EqualDepthLayersBothBlendInOnePeel) {
  const Layer a{2000000, {255, 0, 0, 100}}, b{2000000, {0, 0, 255, 100}};
  const Rgba8 got = run_peel(2, {a, b});
  EXPECT_EQ(got, front_to_back({a, b}, 2));
}

TEST(DepthPeel, PeelTestIsStrict) {
  zb::GoldenRop rop;
  rop.begin_frame(2, 1, 24, Rgba8{0, 0, 0, 0});
  rop.begin_pass(zb::RopState{true, zb::DepthFunc::kLess, true, zb::BlendMode::kReplace, 15, false});
  zb::Fragment f;
  f.x = 0;
  f.z = 500;
  f.color = {1, 2, 3, 4};
  rop.draw(&f, 1);
  rop.end_pass();
  rop.frame_op({zb::FrameOpKind::kCopyDepthToPeel, {}, 0, false});
  rop.frame_op({zb::FrameOpKind::kClearDepth, {}, zb::FrameOp::kFar, false});
  EXPECT_EQ(rop.framebuffer().peel_at(0, 0), 500u);
  EXPECT_EQ(rop.framebuffer().depth_at(0, 0), zb::depth_max(24));
  zb::RopState peel{true, zb::DepthFunc::kLess, true, zb::BlendMode::kReplace, 15, true};
  rop.begin_pass(peel);
  zb::Fragment g[3] = {f, f, f};
  g[1].z = 501;
  g[2].z = 499;
  rop.draw(g, 3);
  const zb::PassStats s = rop.end_pass();
  EXPECT_EQ(s.fragments_passed, 1u);  // only z = 501 lies behind the peel plane
  EXPECT_EQ(rop.framebuffer().depth_at(0, 0), 501u);
}

TEST(DepthPeel, UnderBlendRule) {
  // Exhaustive over (s, a) for a few destinations, against the rule written here.
  for (uint32_t da : {0u, 1u, 100u, 254u, 255u})
    for (uint32_t d : {0u, 7u, 200u, 255u})
      for (uint32_t s = 0; s < 256; ++s)
        for (uint32_t a = 0; a < 256; ++a) {
          const Rgba8 got = zb::blend(zb::BlendMode::kUnder, Rgba8{uint8_t(s), 0, 0, uint8_t(a)},
                                      Rgba8{uint8_t(d), 0, 0, uint8_t(da)});
          ASSERT_EQ(got.r, sat(d + m_spec(m_spec(s, a), 255 - da)));
          ASSERT_EQ(got.a, sat(da + m_spec(a, 255 - da)));
        }
}

TEST(DepthPeel, StatePacksPeelAndUnder) {
  zb::RopState s{true, zb::DepthFunc::kEqual, false, zb::BlendMode::kUnder, 0xa, true};
  zb::RopState back;
  ASSERT_TRUE(zb::unpack_state(zb::pack_state(s), back));
  EXPECT_EQ(back.blend, zb::BlendMode::kUnder);
  EXPECT_TRUE(back.peel_test);
  EXPECT_EQ(back.color_mask, 0xa);
  EXPECT_EQ(back.depth_func, zb::DepthFunc::kEqual);
  EXPECT_EQ(zb::pack_state(back), zb::pack_state(s));
  EXPECT_FALSE(zb::unpack_state(uint16_t(7u << 5), back)) << "blend code 7 is invalid";
}

TEST(DepthPeel, TraceKeepsFrameOps) {
  const zb::RasterizedScene rs = zbtest::layer_scene({kOpaque, make_layers(3)[0]}, kBackground);
  const zb::PassPlan& plan = *zb::find_plan("depth-peel-2");
  const zb::Trace t = zb::make_trace(rs, plan);
  const zb::Trace back = zb::parse_trace(zb::serialize_trace(t), "mem");
  ASSERT_EQ(back.final_ops.size(), 1u);
  EXPECT_EQ(back.final_ops[0].value, kBackground);
  zb::GoldenRop a, b;
  zb::render(rs, plan, a);
  zb::replay_trace(back, b);
  EXPECT_EQ(a.framebuffer().color, b.framebuffer().color);
  EXPECT_EQ(a.framebuffer().peel, b.framebuffer().peel);
}

}  // namespace
