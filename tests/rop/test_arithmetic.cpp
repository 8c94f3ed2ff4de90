// The declared arithmetic's rules (rop/arithmetic.h, docs/datapath.md "Declared arithmetic"):
// every rule's alpha and additive blends over all 2^24 (s, d, a) triples against formulas written
// here from the rules' definitions in real numbers; the comparison shown failing on rules with
// one constant changed; zblend's rule equal to the renderer's blend; the names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdint>

#include "rop/arithmetic.h"
#include "rop/blend.h"

namespace {

using zb::Arithmetic;
using zb::BlendRound;
using zb::Divide;
using zb::One;

// The divisions as real-number statements: t/255 rounded half up, t/256 floored, ceiled,
// rounded half up; zblend's m has no other form than its definition, written with divisions.
uint32_t divide_spec(Divide d, uint32_t t) {
  const double q255 = t / 255.0, q256 = t / 256.0;
  switch (d) {
    case Divide::kZblend: return (t + t / 256 + 128) / 256;
    case Divide::kRound255: return uint32_t(std::floor(q255 + 0.5));
    case Divide::kFloor256: return uint32_t(std::floor(q256));
    case Divide::kCeil256: return uint32_t(std::ceil(q256));
    case Divide::kRound256: return uint32_t(std::floor(q256 + 0.5));
  }
  return 0;
}

uint32_t clamp255(uint32_t v) { return v < 255 ? v : 255; }

// s*a + d*(1 - a) and s*a + d, by the rule's place of rounding and its 1.
uint32_t alpha_spec(const Arithmetic& r, uint32_t s, uint32_t a, uint32_t d) {
  const uint32_t one = r.one == One::k256 ? 256 : 255;
  if (r.round == BlendRound::kSum) return clamp255(divide_spec(r.divide, s * a + d * (one - a)));
  return clamp255(divide_spec(r.divide, s * a) + divide_spec(r.divide, d * (one - a)));
}
uint32_t additive_spec(const Arithmetic& r, uint32_t s, uint32_t a, uint32_t d) {
  const uint32_t one = r.one == One::k256 ? 256 : 255;
  if (r.round == BlendRound::kSum) return clamp255(divide_spec(r.divide, s * a + d * one));
  return clamp255(d + divide_spec(r.divide, s * a));
}

// Triples where `impl` and `spec` differ, over all 2^24; the first in `first`.
struct Count {
  uint64_t differ = 0;
  uint32_t s = 0, a = 0, d = 0;
};
template <class Impl, class Spec>
Count compare_all(Impl impl, Spec spec) {
  Count c;
  for (uint32_t a = 0; a < 256; ++a)
    for (uint32_t s = 0; s < 256; ++s)
      for (uint32_t d = 0; d < 256; ++d)
        if (uint32_t(impl(uint8_t(s), uint8_t(a), uint8_t(d))) != spec(s, a, d) && c.differ++ == 0)
          c.s = s, c.a = a, c.d = d;
  return c;
}

TEST(Arithmetic, EveryRuleEqualsItsFormulaOverAllTriples) {
  for (unsigned i = 0; i < zb::kArithmetics; ++i) {
    const Arithmetic r = zb::arithmetic_at(i);
    const Count alpha = compare_all(
        [&](uint8_t s, uint8_t a, uint8_t d) { return zb::blend_alpha(r, s, a, d); },
        [&](uint32_t s, uint32_t a, uint32_t d) { return alpha_spec(r, s, a, d); });
    EXPECT_EQ(alpha.differ, 0u) << zb::to_string(r) << " alpha: first at s=" << alpha.s
                                << " a=" << alpha.a << " d=" << alpha.d;
    const Count add = compare_all(
        [&](uint8_t s, uint8_t a, uint8_t d) { return zb::blend_additive(r, s, a, d); },
        [&](uint32_t s, uint32_t a, uint32_t d) { return additive_spec(r, s, a, d); });
    EXPECT_EQ(add.differ, 0u) << zb::to_string(r) << " additive: first at s=" << add.s
                              << " a=" << add.a << " d=" << add.d;
  }
}

// The comparison catches a rule with one constant changed: each division's own constant moved
// by one, on the sum, against the formula of the rule it was.
TEST(Arithmetic, ComparisonFailsOnARuleChangedByOneConstant) {
  struct Mutant {
    Divide d;
    uint32_t (*div)(uint32_t);
  };
  const Mutant mutants[] = {
      {Divide::kZblend, [](uint32_t t) { return (t + (t >> 8) + 0x7fu) >> 8; }},
      {Divide::kRound255, [](uint32_t t) { const uint32_t c = t + 0x7fu; return (c + (c >> 8)) >> 8; }},
      {Divide::kFloor256, [](uint32_t t) { return t >> 9 << 1; }},
      {Divide::kCeil256, [](uint32_t t) { return (t + 0xfeu) >> 8; }},
      {Divide::kRound256, [](uint32_t t) { return (t + 0x81u) >> 8; }},
  };
  for (const Mutant& m : mutants) {
    const Arithmetic r{BlendRound::kSum, m.d, One::k255};
    const Count c = compare_all(
        [&](uint8_t s, uint8_t a, uint8_t d) {
          return clamp255(m.div(uint32_t{s} * a + uint32_t{d} * (255u - a)));
        },
        [&](uint32_t s, uint32_t a, uint32_t d) { return alpha_spec(r, s, a, d); });
    EXPECT_GT(c.differ, 0u) << zb::to_string(r) << ": a changed constant went unseen";
  }
}

// zblend's rule is the renderer's blend, bit for bit; the real ROPs' rules differ from it on
// the shares of the alpha blend's triples measured outside this project (24.56 %, 29.88 %,
// 84.8 %, each to its last printed digit).
TEST(Arithmetic, ZblendIsTheDefaultAndTheOthersDifferAsMeasured) {
  const Arithmetic z;
  EXPECT_TRUE(z.is_zblend());
  // The renderer's entry points (blend.h) against the default rule's formula, written here.
  const Count same = compare_all(
      [&](uint8_t s, uint8_t a, uint8_t d) { return zb::blend_alpha(s, a, d); },
      [&](uint32_t s, uint32_t a, uint32_t d) { return alpha_spec(z, s, a, d); });
  EXPECT_EQ(same.differ, 0u);
  const Count add = compare_all(
      [&](uint8_t s, uint8_t a, uint8_t d) { return zb::blend_additive(s, a, d); },
      [&](uint32_t s, uint32_t a, uint32_t d) { return additive_spec(z, s, a, d); });
  EXPECT_EQ(add.differ, 0u);
  struct Share {
    const char* name;
    double percent, digits;
    int most;  // the largest difference from zblend's, in units
  };
  for (const Share& sh : {Share{"sum-round255", 24.56, 0.005, 1}, Share{"sum-ceil256", 29.88, 0.005, 1},
                          Share{"sum-floor256", 84.8, 0.05, 2}}) {
    const Arithmetic r = *zb::parse_arithmetic(sh.name);
    int most = 0;
    const Count c = compare_all(
        [&](uint8_t s, uint8_t a, uint8_t d) { return zb::blend_alpha(r, s, a, d); },
        [&](uint32_t s, uint32_t a, uint32_t d) {
          const uint32_t z = zb::blend_alpha(uint8_t(s), uint8_t(a), uint8_t(d));
          const int diff = std::abs(int(zb::blend_alpha(r, uint8_t(s), uint8_t(a), uint8_t(d))) - int(z));
          most = std::max(most, diff);
          return z;
        });
    EXPECT_NEAR(100.0 * double(c.differ) / double(1u << 24), sh.percent, sh.digits) << sh.name;
    EXPECT_EQ(most, sh.most) << sh.name;
  }
}

TEST(Arithmetic, NamesRoundTripAndUnknownNamesAreRefused) {
  for (unsigned i = 0; i < zb::kArithmetics; ++i) {
    const Arithmetic r = zb::arithmetic_at(i);
    const auto back = zb::parse_arithmetic(zb::to_string(r));
    ASSERT_TRUE(back.has_value()) << zb::to_string(r);
    EXPECT_EQ(*back, r) << zb::to_string(r);
    for (unsigned j = 0; j < i; ++j) EXPECT_NE(zb::arithmetic_at(j), r);
  }
  EXPECT_EQ(zb::to_string(zb::arithmetic_at(0)), "zblend");
  EXPECT_EQ(zb::parse_arithmetic("each-zblend"), Arithmetic{});
  EXPECT_EQ(zb::to_string(*zb::parse_arithmetic("sum-ceil256")), "sum-ceil256");
  for (const char* bad : {"", "sum", "sum-round", "each-round255-one255", "Zblend", "sum-ceil256 "})
    EXPECT_FALSE(zb::parse_arithmetic(bad).has_value()) << bad;
}

}  // namespace
