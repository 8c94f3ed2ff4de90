// The blend unit's unorm8 arithmetic (docs/datapath.md, "Numerics", "Under blend", "Coverage
// blend"), one channel at a time; zb_blend.sv and zb_mul8.sv compute the same.
#pragma once

#include <array>
#include <cstdint>

#include "arithmetic.h"
#include "fixed.h"

namespace zb {

// m(x, y) ~ x*y/255: t = x*y, (t + (t >> 8) + 0x80) >> 8, llvmpipe's unorm8 multiply. It is
// x*y/255 rounded to nearest for all but 24 of the 65536 pairs, where the fraction is just
// over one half and it rounds down (tests/rop/test_blend.cpp counts them).
constexpr uint8_t mul_unorm8(uint8_t x, uint8_t y) {
  return static_cast<uint8_t>(divide(Divide::kZblend, uint32_t{x} * y));
}

// Alpha blend of one channel: min(255, m(s, a) + m(d, 255 - a)), zblend's rule of arithmetic.h.
constexpr uint8_t blend_alpha(uint8_t s, uint8_t a, uint8_t d) {
  return blend_alpha(Arithmetic{}, s, a, d);
}

// Additive blend of one channel: min(255, d + m(s, a)).
constexpr uint8_t blend_additive(uint8_t s, uint8_t a, uint8_t d) {
  return blend_additive(Arithmetic{}, s, a, d);
}

// Under blend (front-to-back accumulation, depth peeling; docs/datapath.md "Under blend"):
// the destination is premultiplied, t = 255 - A_d is its remaining transmittance.
// Colour channel: min(255, d + m(m(s, a), t)); alpha channel: min(255, A_d + m(a, t)).
constexpr uint8_t blend_under(uint8_t s, uint8_t a, uint8_t d, uint8_t dst_alpha) {
  const uint32_t v = uint32_t{d} + mul_unorm8(mul_unorm8(s, a), static_cast<uint8_t>(255 - dst_alpha));
  return static_cast<uint8_t>(v > 255u ? 255u : v);
}
constexpr uint8_t blend_under_alpha(uint8_t a, uint8_t dst_alpha) {
  const uint32_t v = uint32_t{dst_alpha} + mul_unorm8(a, static_cast<uint8_t>(255 - dst_alpha));
  return static_cast<uint8_t>(v > 255u ? 255u : v);
}

// Resolve of a front-to-back accumulation over the background, every channel:
// min(255, c + m(bg, 255 - A)).
constexpr uint8_t resolve_under(uint8_t c, uint8_t bg, uint8_t acc_alpha) {
  const uint32_t v = uint32_t{c} + mul_unorm8(bg, static_cast<uint8_t>(255 - acc_alpha));
  return static_cast<uint8_t>(v > 255u ? 255u : v);
}

// Coverage-weighted blend of one channel, w of the N samples from the polygon colour p, the
// rest from the stored colour d: (w*p + (N - w)*d + N/2) >> log2(N). 0 <= w <= N; the sum is
// below 256 N, so the result is at most 255 with no saturation.
constexpr uint8_t blend_coverage(uint8_t p, uint8_t d, uint32_t w, int n) {
  const uint32_t nn = uint32_t(n);
  return static_cast<uint8_t>((w * p + (nn - w) * d + nn / 2) >> coverage_log2(n));
}

// Weighted blended OIT (docs/datapath.md "7. Accumulate blend"), the paper's equation 10,
// w = a * max(1e-2, 3e3 * (1 - d)^3), in fixed point: the depth weight
// F = max(1, u^3 >> (24 - W)), u the top 8 bits of ZMAX - z (1 - d), so F runs from 1 to
// 2^W - 1 (the paper's range is 3e5, W = 18).
constexpr uint32_t wboit_depth_u(uint32_t z, int depth_bits) {
  return ((depth_max(depth_bits) - z) >> (depth_bits - 8)) & 0xffu;
}
constexpr uint32_t wboit_depth_weight(uint32_t z, int depth_bits, int weight_bits) {
  const uint32_t u = wboit_depth_u(z, depth_bits);
  const uint32_t f = (u * u * u) >> (24 - weight_bits);
  return f == 0 ? 1u : f;
}

// The accumulation term's right shift: a full-weight term (p = a = 255, F = 2^W) keeps 4 bits
// of headroom below 2^A, 16 such layers before a channel saturates.
constexpr int wboit_term_shift(const WboitFormat& f) {
  const int s = f.weight_bits + 20 - f.acc_bits;
  return s > 0 ? s : 0;
}

// One channel's term, p * w >> S, w = a * F the weight: p = m(s, a) for R, G, B, p = a for A.
constexpr uint32_t wboit_term(uint8_t p, uint32_t weight, int shift) {
  return static_cast<uint32_t>((uint64_t{p} * weight) >> shift);
}

// acc + term, saturated at 2^A - 1.
constexpr uint32_t wboit_accumulate(uint32_t acc, uint32_t term, int acc_bits) {
  const uint64_t top = (uint64_t{1} << acc_bits) - 1u;
  const uint64_t v = uint64_t{acc} + term;
  return static_cast<uint32_t>(v > top ? top : v);
}

// Revealage's 1.0, its clear value.
constexpr uint32_t wboit_reveal_one(int rev_bits) { return (uint32_t{1} << rev_bits) - 1u; }

// Revealage times 1 - a: (r * t + 128) >> 8 with t = k + (k >> 7), k = 255 - a, which maps
// 0..255 onto 0..256 (a = 0 keeps r exactly, a = 255 makes it 0).
constexpr uint32_t wboit_transmit(uint8_t a) {
  const uint32_t k = 255u - a;
  return k + (k >> 7);
}
constexpr uint32_t wboit_reveal(uint32_t r, uint8_t a) { return (r * wboit_transmit(a) + 128u) >> 8; }

// The resolve of one colour channel (frame operation 4): the weighted average
// avg = min(255, (acc * 255 + acc_a / 2) / acc_a) (0 when acc_a = 0; the alpha channel's avg
// is 255) over the opaque colour c by the revealage r of 1.0 = one:
// (avg * (one - r) + c * r + one / 2) / one. The blend keeps acc <= acc_a, so the min binds
// only on a word it never makes; it keeps both divisions at 8 quotient bits (docs/datapath.md).
constexpr uint8_t resolve_wboit_channel(uint32_t acc, uint32_t acc_a, uint8_t c, uint32_t r,
                                        uint32_t one) {
  const uint64_t q = acc_a == 0 ? 0 : (uint64_t{acc} * 255u + acc_a / 2) / acc_a;
  const uint64_t avg = q < 255 ? q : 255;
  return static_cast<uint8_t>((avg * (one - r) + uint64_t{c} * r + one / 2) / one);
}

// The resolve of one pixel: each channel of `c` from the accumulation acc (R, G, B, A) and
// the revealage r of 1.0 = one.
constexpr Rgba8 resolve_wboit(Rgba8 c, const std::array<uint32_t, 4>& acc, uint32_t r,
                              uint32_t one) {
  return {resolve_wboit_channel(acc[0], acc[3], c.r, r, one),
          resolve_wboit_channel(acc[1], acc[3], c.g, r, one),
          resolve_wboit_channel(acc[2], acc[3], c.b, r, one),
          resolve_wboit_channel(acc[3], acc[3], c.a, r, one)};
}

}  // namespace zb
