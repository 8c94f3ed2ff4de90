// mlab-K (one pass, K layers a pixel) against values worked out in the test from the method's
// rules (docs/datapath.md "8. Layers"), written with zbtest::m_spec, independently of the code
// under test: the transparent layers in front of the opaque surface, nearest first, each
// p = m(s, a); beyond K, in nearest-first submit order the last layer takes every farther one
// under it, p = min(255, p + m(p_b, 255 - A)); then the front-to-back chain over the opaque
// colour, C = min(255, C + m(p, 255 - A)), then C = min(255, C + m(opaque, 255 - A)).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "io/trace.h"
#include "pipeline/passes.h"
#include "rop/rop.h"
#include "support/layers.h"

namespace {

using zb::Rgba8;
using zbtest::Layer;
using zbtest::kBackground;
using zbtest::kOpaque;
using zbtest::m_spec;
using zbtest::make_layers;
using zbtest::sat;

struct P4 {
  uint32_t c[4];
};
P4 premul(Rgba8 s) { return {{m_spec(s.r, s.a), m_spec(s.g, s.a), m_spec(s.b, s.a), s.a}}; }
// `b` under `f`: f + m(b, 255 - A_f), every channel.
P4 under(P4 f, P4 b) {
  P4 o;
  for (int i = 0; i < 4; ++i) o.c[i] = sat(f.c[i] + m_spec(b.c[i], 255 - f.c[3]));
  return o;
}

// The method's rules on one pixel, for layers submitted nearest first.
Rgba8 expected(std::vector<Layer> layers, size_t k) {
  std::sort(layers.begin(), layers.end(), [](auto& a, auto& b) { return a.z < b.z; });
  std::vector<P4> kept;
  for (const Layer& l : layers) {
    if (l.z >= kOpaque.z || l.color.a == 0) continue;
    if (kept.size() < k) kept.push_back(premul(l.color));
    else kept.back() = under(kept.back(), premul(l.color));
  }
  P4 acc{{0, 0, 0, 0}};
  for (const P4& p : kept) acc = under(acc, p);
  const P4 o{{kOpaque.color.r, kOpaque.color.g, kOpaque.color.b, kOpaque.color.a}};
  const P4 c = under(acc, o);
  return {uint8_t(c.c[0]), uint8_t(c.c[1]), uint8_t(c.c[2]), uint8_t(c.c[3])};
}

zb::Framebuffer run(const std::string& method, const std::vector<Layer>& transparent) {
  std::vector<Layer> all{kOpaque};
  all.insert(all.end(), transparent.begin(), transparent.end());
  const zb::RasterizedScene rs = zbtest::layer_scene(all, kBackground);
  const zb::PassPlan* plan = zb::find_plan(method);
  EXPECT_NE(plan, nullptr) << method;
  if (!plan) return {};
  zb::GoldenRop rop;
  return zb::render(rs, *plan, rop).framebuffer;
}

Rgba8 run_uniform(int k, const std::vector<Layer>& transparent) {
  const zb::Framebuffer fb = run("mlab-" + std::to_string(k), transparent);
  const Rgba8 c = fb.color_at(1, 2);
  for (Rgba8 p : fb.color) EXPECT_EQ(p, c) << "layers cover the frame uniformly";
  EXPECT_TRUE(fb.layers.empty()) << "the resolve empties the layers";
  return c;
}

TEST(Mlab, PlansRegistered) {
  for (int k : zb::kMlabLayers) {
    const zb::PassPlan* p = zb::find_plan("mlab-" + std::to_string(k));
    ASSERT_NE(p, nullptr) << k;
    ASSERT_EQ(p->passes.size(), 2u);
    EXPECT_EQ(p->passes[1].rop.blend, zb::BlendMode::kLayers);
    EXPECT_EQ(p->passes[1].rop.layers, k);
    EXPECT_FALSE(p->passes[1].rop.depth_write);
    ASSERT_EQ(p->final_ops.size(), 1u);
    EXPECT_EQ(p->final_ops[0].kind, zb::FrameOpKind::kResolveLayers);
  }
}

// Up to K layers: the rule's value in every submit order, and depth-peel-K's frame bit for bit.
TEST(Mlab, ExactAndOrderIndependentUpToKLayers) {
  for (int k : {2, 4})
    for (int n = 0; n <= k; ++n) {
      std::vector<Layer> layers = make_layers(n);
      layers.push_back({13000000, {255, 0, 0, 200}});  // behind the opaque surface
      const Rgba8 want = expected(layers, size_t(k));
      std::sort(layers.begin(), layers.end(), [](auto& a, auto& b) { return a.z < b.z; });
      int order = 0;
      do {
        ASSERT_EQ(run_uniform(k, layers), want) << "K=" << k << " n=" << n << " order " << order;
        ++order;
      } while (std::next_permutation(layers.begin(), layers.end(),
                                     [](auto& a, auto& b) { return a.z < b.z; }));
      if (n >= 1) {
        EXPECT_EQ(run("mlab-" + std::to_string(k), layers).color,
                  run("depth-peel-" + std::to_string(k), layers).color)
            << "K=" << k << " n=" << n;
      }
    }
}

// Equal depths: the colour word orders them, so either submit order gives the same frame.
TEST(Mlab, EqualDepthsOrderIndependent) {
  const std::vector<Layer> a{{3000000, {200, 10, 10, 120}}, {3000000, {10, 200, 10, 90}},
                             {3000000, {10, 10, 200, 120}}};
  const std::vector<Layer> b{a[2], a[0], a[1]};
  EXPECT_EQ(run_uniform(4, a), run_uniform(4, b));
  EXPECT_EQ(run_uniform(4, a), run_uniform(4, {a[1], a[2], a[0]}));
}

// Beyond K, submitted nearest first: the last layer takes the farther ones under it.
TEST(Mlab, BeyondKTheLastLayerMerges) {
  for (int k : {2, 4}) {
    const std::vector<Layer> layers = make_layers(k + 2);
    EXPECT_EQ(run_uniform(k, layers), expected(layers, size_t(k))) << "K=" << k;
    // and the colour is not depth-peel-K's, which drops the farther layers
    EXPECT_NE(run("mlab-" + std::to_string(k), layers).color,
              run("depth-peel-" + std::to_string(k), layers).color);
  }
}

// Alpha 0 inserts nothing; a layers pass's K and blend survive a trace.
TEST(Mlab, AlphaZeroAndTrace) {
  EXPECT_EQ(run_uniform(2, {{2000000, {255, 255, 255, 0}}}), expected({}, 2));
  const zb::RasterizedScene rs = zbtest::layer_scene({kOpaque, make_layers(3)[0]}, kBackground);
  const zb::Trace t = zb::make_trace(rs, *zb::find_plan("mlab-4"));
  const zb::Trace back = zb::parse_trace(zb::serialize_trace(t), "mem");
  ASSERT_EQ(back.passes.size(), 2u);
  EXPECT_EQ(back.passes[1].state.blend, zb::BlendMode::kLayers);
  EXPECT_EQ(back.passes[1].state.layers, 4);
  ASSERT_EQ(back.final_ops.size(), 1u);
  EXPECT_EQ(back.final_ops[0].kind, zb::FrameOpKind::kResolveLayers);
}

}  // namespace
