// The layer unit of mlab-K (docs/datapath.md "8. Layers"): the same layers in any submit order
// while a pixel has at most K, the resolve equal to depth peeling's under-blend chain there,
// the merge of the two farthest beyond K, and the edges (alpha 0, no layer, saturation).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "rop/blend.h"
#include "rop/layers.h"

namespace {

using zb::Layer;
using zb::PixelLayers;
using zb::Rgba8;

struct Frag {
  uint32_t z;
  Rgba8 c;
};

PixelLayers insert_all(const std::vector<Frag>& fs, int k) {
  PixelLayers px;
  for (const Frag& f : fs) zb::insert_layer(px, k, zb::fragment_layer(f.z, f.c));
  return px;
}

// Depth peeling's chain, written from blend.h's under blend: the fragments nearest first (ties
// as layer_before orders them), each under-blended into an accumulation from (0, 0, 0, 0), then
// the resolve under over the opaque colour.
Rgba8 peel_chain(std::vector<Frag> fs, Rgba8 opaque) {
  std::sort(fs.begin(), fs.end(), [](const Frag& a, const Frag& b) {
    return zb::layer_before(zb::fragment_layer(a.z, a.c), zb::fragment_layer(b.z, b.c));
  });
  Rgba8 acc{0, 0, 0, 0};
  for (const Frag& f : fs) {
    if (f.c.a == 0) continue;
    acc = Rgba8{zb::blend_under(f.c.r, f.c.a, acc.r, acc.a), zb::blend_under(f.c.g, f.c.a, acc.g, acc.a),
                zb::blend_under(f.c.b, f.c.a, acc.b, acc.a), zb::blend_under_alpha(f.c.a, acc.a)};
  }
  return Rgba8{zb::resolve_under(acc.r, opaque.r, acc.a), zb::resolve_under(acc.g, opaque.g, acc.a),
               zb::resolve_under(acc.b, opaque.b, acc.a), zb::resolve_under(acc.a, opaque.a, acc.a)};
}

std::vector<Frag> random_frags(std::mt19937& rng, int n, bool distinct) {
  std::vector<Frag> fs;
  std::uniform_int_distribution<uint32_t> z(0, distinct ? 0xffffff : 3), c(0, 255);
  while (int(fs.size()) < n) {
    Frag f{z(rng), Rgba8{uint8_t(c(rng)), uint8_t(c(rng)), uint8_t(c(rng)), uint8_t(c(rng))}};
    if (distinct && std::any_of(fs.begin(), fs.end(), [&](const Frag& g) { return g.z == f.z; })) continue;
    fs.push_back(f);
  }
  return fs;
}

// At most K fragments: every submit order gives the same layers, bit for bit, equal depths
// included (the colour word orders them), and the resolve is depth peeling's chain.
TEST(Layers, OrderIndependentUpToKAndDepthPeelingsChain) {
  std::mt19937 rng(59);
  const Rgba8 opaque{40, 45, 62, 255};
  for (int k : {2, 4}) {
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<Frag> fs = random_frags(rng, 1 + trial % k, trial % 3 != 0);
      std::sort(fs.begin(), fs.end(), [](const Frag& a, const Frag& b) {
        return std::tie(a.z, a.c.r, a.c.g, a.c.b, a.c.a) < std::tie(b.z, b.c.r, b.c.g, b.c.b, b.c.a);
      });
      const PixelLayers first = insert_all(fs, k);
      do {
        const PixelLayers px = insert_all(fs, k);
        ASSERT_EQ(px.n, first.n);
        for (int i = 0; i < px.n; ++i) ASSERT_EQ(px.layer[size_t(i)], first.layer[size_t(i)]) << "k " << k;
      } while (std::next_permutation(fs.begin(), fs.end(), [](const Frag& a, const Frag& b) {
        return std::tie(a.z, a.c.r, a.c.g, a.c.b, a.c.a) < std::tie(b.z, b.c.r, b.c.g, b.c.b, b.c.a);
      }));
      ASSERT_EQ(zb::resolve_layers(first, opaque), peel_chain(fs, opaque)) << "k " << k << " trial " << trial;
    }
  }
}

// K + 1 layers: the nearest K - 1 kept as they were, the two farthest merged front over back,
// worked by hand: front p 100, A 128 (t = 127), back p 200, A 255: 100 + m(200, 127) = 100 + 100.
TEST(Layers, MergesTheTwoFarthest) {
  PixelLayers px;
  const Layer near{10, Rgba8{1, 2, 3, 4}}, mid{20, Rgba8{100, 100, 100, 128}}, far{30, Rgba8{200, 200, 200, 255}};
  EXPECT_EQ(zb::insert_layer(px, 2, far), 0);
  EXPECT_EQ(zb::insert_layer(px, 2, mid), 0);
  EXPECT_EQ(zb::insert_layer(px, 2, near), 0);  // three: mid and far merge behind it
  ASSERT_EQ(px.n, 2);
  EXPECT_EQ(px.layer[0], near);
  EXPECT_EQ(zb::mul_unorm8(200, 127), 100);
  EXPECT_EQ(zb::mul_unorm8(255, 127), 127);
  EXPECT_EQ(px.layer[1], (Layer{20, Rgba8{200, 200, 200, 255}}));  // 128 + 127
  // A fragment behind every layer merges into the last: its place is reported as k.
  PixelLayers q;
  zb::insert_layer(q, 2, near);
  zb::insert_layer(q, 2, mid);
  EXPECT_EQ(zb::insert_layer(q, 2, far), 2);
  EXPECT_EQ(q.layer[1], zb::merge_layers(mid, far));
  // Saturation: the sums stop at 255.
  const Layer m = zb::merge_layers(Layer{0, Rgba8{250, 0, 0, 10}}, Layer{1, Rgba8{255, 0, 0, 255}});
  EXPECT_EQ(m.p.r, 255);
  EXPECT_EQ(m.p.a, 255);
  EXPECT_EQ(m.z, 0u);
}

// Alpha 0 changes nothing; no layer resolves to the opaque colour; a full pixel stays at k.
TEST(Layers, Edges) {
  PixelLayers px;
  EXPECT_EQ(zb::insert_layer(px, 4, zb::fragment_layer(5, Rgba8{9, 9, 9, 0})), -1);
  EXPECT_EQ(px.n, 0);
  EXPECT_EQ(zb::resolve_layers(px, Rgba8{7, 8, 9, 255}), (Rgba8{7, 8, 9, 255}));
  std::mt19937 rng(7);
  for (const Frag& f : random_frags(rng, 20, true)) zb::insert_layer(px, 4, zb::fragment_layer(f.z, f.c));
  EXPECT_EQ(px.n, 4);
  for (int i = 0; i + 1 < px.n; ++i) EXPECT_TRUE(zb::layer_before(px.layer[size_t(i)], px.layer[size_t(i + 1)]));
  EXPECT_THROW(zb::insert_layer(px, 0, Layer{}), std::invalid_argument);
  EXPECT_THROW(zb::insert_layer(px, zb::kMaxLayers + 1, Layer{}), std::invalid_argument);
}

}  // namespace
