// The blend arithmetic against its formula evaluated independently, over every input.
#include <gtest/gtest.h>

#include <cmath>

#include "rop/blend.h"

namespace {

// docs/datapath.md's m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x*y, written with divisions.
uint32_t m_spec(uint32_t x, uint32_t y) {
  const uint32_t t = x * y;
  return (t + t / 256 + 128) / 256;
}

TEST(Blend, MulUnorm8MatchesFormulaForAllPairs) {
  int checked = 0;
  for (uint32_t x = 0; x < 256; ++x)
    for (uint32_t y = 0; y < 256; ++y, ++checked)
      ASSERT_EQ(zb::mul_unorm8(uint8_t(x), uint8_t(y)), m_spec(x, y)) << x << " * " << y;
  EXPECT_EQ(checked, 1 << 16);
}

// How m differs from x*y/255 rounded to nearest: in 24 pairs, by one, downwards, and never
// by more than half a unit plus 1/510 from the true quotient.
TEST(Blend, MulUnorm8AgainstExactRounding) {
  int differ = 0;
  for (uint32_t x = 0; x < 256; ++x)
    for (uint32_t y = 0; y < 256; ++y) {
      const uint32_t m = zb::mul_unorm8(uint8_t(x), uint8_t(y));
      const uint32_t rounded = (2 * x * y + 255) / 510;  // never a tie: 255 is odd
      if (m != rounded) {
        ++differ;
        EXPECT_EQ(m + 1, rounded) << x << " * " << y;
      }
      EXPECT_LE(std::fabs(double(m) - x * y / 255.0), 0.5 + 1.0 / 510 + 1e-12);
    }
  EXPECT_EQ(differ, 24);
  for (uint32_t x = 0; x < 256; ++x) {
    EXPECT_EQ(zb::mul_unorm8(uint8_t(x), 255), x);
    EXPECT_EQ(zb::mul_unorm8(uint8_t(x), 0), 0);
  }
}

TEST(Blend, AlphaBlendExhaustiveOverAllTriples) {
  uint32_t largest_sum = 0;
  for (uint32_t a = 0; a < 256; ++a)
    for (uint32_t s = 0; s < 256; ++s)
      for (uint32_t d = 0; d < 256; ++d) {
        const uint32_t sum = m_spec(s, a) + m_spec(d, 255 - a);
        largest_sum = std::max(largest_sum, sum);
        const uint8_t got = zb::blend_alpha(uint8_t(s), uint8_t(a), uint8_t(d));
        if (got != std::min(255u, sum))
          FAIL() << "s=" << s << " a=" << a << " d=" << d << " got " << int(got);
      }
  EXPECT_EQ(largest_sum, 255u) << "the clamp of the alpha blend never acts";
}

TEST(Blend, AdditiveBlendExhaustiveOverAllTriples) {
  int saturated = 0;
  for (uint32_t a = 0; a < 256; ++a)
    for (uint32_t s = 0; s < 256; ++s)
      for (uint32_t d = 0; d < 256; ++d) {
        const uint32_t sum = d + m_spec(s, a);
        saturated += sum > 255;
        const uint8_t got = zb::blend_additive(uint8_t(s), uint8_t(a), uint8_t(d));
        if (got != std::min(255u, sum))
          FAIL() << "s=" << s << " a=" << a << " d=" << d << " got " << int(got);
      }
  EXPECT_GT(saturated, 0);
}

TEST(Blend, AlphaEndpoints) {
  for (uint32_t s = 0; s < 256; ++s)
    for (uint32_t d = 0; d < 256; ++d) {
      EXPECT_EQ(zb::blend_alpha(uint8_t(s), 255, uint8_t(d)), s);
      EXPECT_EQ(zb::blend_alpha(uint8_t(s), 0, uint8_t(d)), d);
    }
}

TEST(Blend, DepthMax) {
  EXPECT_EQ(zb::depth_max(16), 0xffffu);
  EXPECT_EQ(zb::depth_max(24), 0xffffffu);
  EXPECT_EQ(zb::depth_max(32), 0xffffffffu);
}

}  // namespace
