// wboit (McGuire and Bavoil 2013) against values computed in the test from the paper's
// equations: equation 10's weight w = a * max(1e-2, 3e3 (1 - d)^3), here
// a * max(1, 2^W (1 - d)^3), and equation 6's composite
//   C = sum(C_i w_i) / sum(a_i w_i) * (1 - prod(1 - a_i)) + C0 * prod(1 - a_i),
// evaluated in double from the layers' colours, alphas and depths. The datapath's own integer
// rules are not called: where the test uses a datapath quantity (premultiplied colour in 8
// bits, 1 - d in 8 bits, 1 - a on 0..256) it says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "pipeline/passes.h"
#include "rop/rop.h"
#include "support/layers.h"

namespace {

using zb::Rgba8;
using zb::WboitFormat;
using zbtest::Layer;
using zbtest::kBackground;
using zbtest::kOpaque;
using zbtest::m_spec;

constexpr uint32_t kZmax = (1u << 24) - 1;

// The top 8 bits of 1 - d, as equation 10 sees the depth in the datapath.
double one_minus_d(uint32_t z) { return double((kZmax - z) >> 16) / 256.0; }

// Equation 10's depth factor over its floor: max(1, 2^W (1 - d)^3), floored to an integer.
double paper_depth_weight(uint32_t z, int w) {
  return std::max(1.0, std::floor(std::ldexp(std::pow(one_minus_d(z), 3), w)));
}

// How a test treats the premultiplied colour and 1 - a: as the datapath holds them, or exactly.
struct Quantities {
  bool premul_8bit = true;     // C_i = m(s, a) / 255 (else s a / 255^2)
  bool transmit_on_256 = true;  // 1 - a_i = t / 256, t = k + k / 128, k = 255 - a (else k / 255)
};

// Equation 6 over the opaque colour, every channel on 0..255; alpha's average is 1.
std::array<double, 4> paper_composite(const std::vector<Layer>& layers, Rgba8 opaque, int w,
                                      Quantities q) {
  double sum_c[3] = {0, 0, 0}, sum_a = 0, reveal = 1;
  for (const Layer& l : layers) {
    if (l.z >= kOpaque.z) continue;  // behind the opaque surface: the depth test
    const double a = l.color.a / 255.0;
    const double weight = a * paper_depth_weight(l.z, w);
    const uint32_t s[3] = {l.color.r, l.color.g, l.color.b};
    for (int c = 0; c < 3; ++c)
      sum_c[c] += (q.premul_8bit ? m_spec(s[c], l.color.a) / 255.0 : s[c] / 255.0 * a) * weight;
    sum_a += a * weight;
    const uint32_t k = 255u - l.color.a;
    reveal *= q.transmit_on_256 ? (k + k / 128) / 256.0 : k / 255.0;
  }
  const double c0[4] = {double(opaque.r), double(opaque.g), double(opaque.b), double(opaque.a)};
  std::array<double, 4> out{};
  for (int c = 0; c < 4; ++c) {
    const double avg = c == 3 ? 255.0 : (sum_a > 0 ? 255.0 * sum_c[c] / sum_a : 0.0);
    out[size_t(c)] = avg * (1 - reveal) + c0[c] * reveal;
  }
  return out;
}

zb::RenderResult run_wboit(const std::vector<Layer>& transparent, const WboitFormat& f) {
  std::vector<Layer> all{kOpaque};
  all.insert(all.end(), transparent.begin(), transparent.end());
  zb::RasterizedScene rs = zbtest::layer_scene(all, kBackground);
  rs.viewport.wboit = f;
  zb::GoldenRop rop;
  return zb::render(rs, *zb::find_plan("wboit"), rop);
}

Rgba8 wboit_color(const std::vector<Layer>& transparent, const WboitFormat& f) {
  const zb::RenderResult r = run_wboit(transparent, f);
  const Rgba8 c = r.framebuffer.color_at(1, 2);
  for (Rgba8 p : r.framebuffer.color) EXPECT_EQ(p, c) << "layers cover the frame uniformly";
  return c;
}

double max_channel_error(Rgba8 got, const std::array<double, 4>& want) {
  const double g[4] = {double(got.r), double(got.g), double(got.b), double(got.a)};
  double e = 0;
  for (int c = 0; c < 4; ++c) e = std::max(e, std::abs(g[c] - want[size_t(c)]));
  return e;
}

// n random layers at distinct depths in front of the opaque one, alpha in [lo, hi].
std::vector<Layer> random_layers(std::mt19937& rng, int n, int lo, int hi) {
  std::uniform_int_distribution<int> ch(0, 255), al(lo, hi);
  std::uniform_int_distribution<uint32_t> depth(0, kOpaque.z - 1);
  std::vector<Layer> out;
  while (int(out.size()) < n) {
    const uint32_t z = depth(rng);
    if (std::any_of(out.begin(), out.end(), [&](const Layer& l) { return l.z == z; })) continue;
    out.push_back({z, {uint8_t(ch(rng)), uint8_t(ch(rng)), uint8_t(ch(rng)), uint8_t(al(rng))}});
  }
  return out;
}

TEST(Wboit, PlanRegistered) {
  const zb::PassPlan* p = zb::find_plan("wboit");
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->passes.size(), 2u);
  EXPECT_EQ(p->passes[1].rop.blend, zb::BlendMode::kAccumulate);
  EXPECT_FALSE(p->passes[1].rop.depth_write);
  ASSERT_EQ(p->final_ops.size(), 1u);
  EXPECT_EQ(p->final_ops[0].kind, zb::FrameOpKind::kResolveWboit);
}

// Equation 10's factor for every 8-bit 1 - d and every weight range.
TEST(Wboit, DepthWeightIsEquationTen) {
  for (int w : {0, 1, 4, 8, 12, 16})
    for (uint32_t u = 0; u < 256; ++u) {
      const uint32_t z = kZmax - (u << 16) - 0x1234;  // low bits must not matter
      ASSERT_EQ(double(zb::wboit_depth_weight(z, 24, w)), paper_depth_weight(z, w))
          << "W=" << w << " u=" << u;
    }
  // Nearer weighs more, and W = 0 weighs every depth alike (the weighted average).
  EXPECT_GT(zb::wboit_depth_weight(0, 24, 8), zb::wboit_depth_weight(kZmax / 2, 24, 8));
  EXPECT_EQ(zb::wboit_depth_weight(0, 24, 0), zb::wboit_depth_weight(kZmax / 2, 24, 0));
}

// With the widest planes (A = 32: no term shift; R = 16) the only differences from equation 6,
// given the datapath's premultiplied colour and 1 - a, are the revealage's rounding at each
// layer (half a unit of 2^-16) and the resolve's two roundings: within one unit.
TEST(Wboit, WidePlanesMatchEquationSix) {
  std::mt19937 rng(7);
  const WboitFormat wide{32, 16, 8};
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 8;
    const std::vector<Layer> layers = random_layers(rng, n, 1, 254);
    const Rgba8 got = wboit_color(layers, wide);
    const auto want = paper_composite(layers, kOpaque.color, wide.weight_bits, Quantities{});
    ASSERT_LE(max_channel_error(got, want), 1.0) << "trial " << trial << " layers " << n;
  }
}

// The paper's equation with exact premultiplication and 1 - a = k / 255, on the default
// planes. The 8-bit premultiplied colour is off by up to half a unit, which the average
// divides by alpha (up to 1 unit for alphas from 128); 1 - a on 0..256 by up to 0.5 / 256 a
// layer; and the term shift (S = 8) drops up to a unit of every term. Together within 5
// units.
TEST(Wboit, DefaultPlanesNearEquationSix) {
  std::mt19937 rng(11);
  const WboitFormat def{};
  double worst = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 6;
    const std::vector<Layer> layers = random_layers(rng, n, 128, 254);
    const Rgba8 got = wboit_color(layers, def);
    const auto want = paper_composite(layers, kOpaque.color, def.weight_bits, {false, false});
    worst = std::max(worst, max_channel_error(got, want));
  }
  EXPECT_LE(worst, 5.0);
  EXPECT_GT(worst, 0.5) << "the default planes round: some pixel must show it";
}

// Addition commutes and saturates alike in every order, so the accumulation is the same bit
// for bit in every submit order; the revealage rounds at each layer and may differ by a unit
// per layer after the first.
TEST(Wboit, OrderIndependent) {
  std::mt19937 rng(3);
  for (int n = 2; n <= 5; ++n) {
    std::vector<Layer> layers = random_layers(rng, n, 20, 240);
    std::sort(layers.begin(), layers.end(), [](auto& a, auto& b) { return a.z < b.z; });
    const zb::RenderResult first = run_wboit(layers, {});
    uint32_t lo = first.framebuffer.reveal_at(0), hi = lo;
    do {
      const zb::RenderResult r = run_wboit(layers, {});
      ASSERT_EQ(r.framebuffer.accum_at(0), first.framebuffer.accum_at(0)) << n << " layers";
      lo = std::min(lo, r.framebuffer.reveal_at(0));
      hi = std::max(hi, r.framebuffer.reveal_at(0));
    } while (std::next_permutation(layers.begin(), layers.end(),
                                   [](auto& a, auto& b) { return a.z < b.z; }));
    EXPECT_LE(hi - lo, uint32_t(n - 1)) << n << " layers";
  }
}

// A full-weight layer (p = a = 254, z = 0: u = 255, F = 255^3 >> 16 = 253) keeps 4 bits of
// headroom: 16 layers fit in a 16-bit channel, the 17th saturates it.
TEST(Wboit, SixteenFullWeightLayersFit) {
  const WboitFormat def{16, 8, 8};
  const Layer full{0, {254, 254, 254, 254}};
  const uint32_t term = uint32_t((254ull * 254 * 253) >> 12);  // S = 8 + 20 - 16
  const zb::RenderResult r16 = run_wboit(std::vector<Layer>(16, full), def);
  EXPECT_EQ(r16.framebuffer.accum_at(0)[3], 16 * term);
  EXPECT_LT(r16.framebuffer.accum_at(0)[3], 0xffffu);
  const zb::RenderResult r17 = run_wboit(std::vector<Layer>(17, full), def);
  EXPECT_EQ(r17.framebuffer.accum_at(0)[3], 0xffffu);
}

// The resolve worked by hand: acc = (100, 50, 0, 200), r = 128 of 255 over (10, 20, 30, 255).
// avg = (25600 / 200, 12850 / 200, 100 / 200) = (128, 64, 0), alpha 255;
// c = (avg (255 - 128) + c0 128 + 127) / 255 = (17663, 10815, 3967, 65152) / 255.
TEST(Wboit, ResolveByHand) {
  zb::Framebuffer fb(2, 1, 24, Rgba8{10, 20, 30, 255});
  fb.touch_accum();
  fb.accum[0] = {100, 50, 0, 200};
  fb.reveal[0] = 128;
  zb::apply_frame_op(fb, zb::FrameOp{zb::FrameOpKind::kResolveWboit, Rgba8{}, 0, false});
  EXPECT_EQ(fb.color[0], (Rgba8{69, 42, 15, 255}));
  EXPECT_EQ(fb.color[1], (Rgba8{10, 20, 30, 255})) << "no transparent fragment: kept";
}

// A word the blend never makes (acc above acc_A, from a hostile tile load): avg saturates at
// 255 (datapath.md), where the unclamped quotient 382 would wrap to 126 in 8 bits.
TEST(Wboit, ResolveSaturatesAHostileAverage) {
  EXPECT_EQ(zb::resolve_wboit_channel(300, 200, 0, 0, 255), 255);
  EXPECT_EQ(zb::resolve_wboit_channel(300, 200, 0, 255, 255), 0) << "r = one keeps C0";
  EXPECT_EQ(zb::resolve_wboit_channel(199, 200, 0, 0, 255), 254) << "below acc_A: no clamp";
}

// Alpha 0 adds nothing and keeps the revealage exactly; alpha 255 zeroes it.
TEST(Wboit, RevealageEnds) {
  for (uint32_t r : {0u, 1u, 128u, 255u, 65535u}) {
    EXPECT_EQ(zb::wboit_reveal(r, 0), r);
    EXPECT_EQ(zb::wboit_reveal(r, 255), 0u);
  }
}

// Layers behind the opaque surface are depth-tested away: the pixel is the opaque colour.
TEST(Wboit, BehindOpaqueIsHidden) {
  const std::vector<Layer> behind{{kOpaque.z + 1000, {255, 0, 0, 200}}};
  EXPECT_EQ(wboit_color(behind, {}), kOpaque.color);
}

// The method's known failure: two high-alpha layers are averaged by weight, not composited in
// order. A red layer over a blue one, both alpha 0.9 and close in depth (their weights nearly
// equal), must look mostly red; wboit mixes them, so the far colour shows far more than the
// 10 % it should.
TEST(Wboit, HighAlphaLayersLoseTheirOrder) {
  const Layer near_red{5000000, {255, 0, 0, 230}};
  const Layer far_blue{5100000, {0, 0, 255, 230}};
  const Rgba8 got = wboit_color({near_red, far_blue}, {});
  const Rgba8 exact = zbtest::over(near_red.color, zbtest::over(far_blue.color, kOpaque.color));
  EXPECT_GT(exact.r, 200);
  EXPECT_LT(exact.b, 40);
  EXPECT_GT(got.b, exact.b + 40) << "the far layer shows through the near one";
}

}  // namespace

// The accumulation planes (20 B a pixel) exist only once something accumulates: a frame that
// never does reads them as cleared, and a resolve over them keeps its colours.
TEST(Wboit, PlanesOnlyOnceAccumulated) {
  zb::Framebuffer fb(2, 1, 24, Rgba8{10, 20, 30, 40});
  EXPECT_TRUE(fb.accum.empty() && fb.reveal.empty());
  EXPECT_EQ(fb.accum_at(1), (std::array<uint32_t, 4>{}));
  EXPECT_EQ(fb.reveal_at(1), 255u);
  zb::apply_frame_op(fb, zb::FrameOp{zb::FrameOpKind::kResolveWboit, Rgba8{}, 0, false});
  EXPECT_EQ(fb.color[1], (Rgba8{10, 20, 30, 40}));
  EXPECT_TRUE(fb.accum.empty()) << "a resolve allocates nothing";
  const zb::RenderResult r = run_wboit({Layer{100, {200, 100, 50, 128}}}, {});
  EXPECT_EQ(r.framebuffer.accum.size(), r.framebuffer.color.size());
  EXPECT_NE(r.framebuffer.reveal_at(0), 255u);
}
