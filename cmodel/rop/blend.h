// The blend unit's unorm8 arithmetic (docs/datapath.md, "Numerics", "Under blend", "Coverage
// blend"), one channel at a time; zb_blend.sv and zb_mul8.sv compute the same.
#pragma once

#include <cstdint>

#include "fixed.h"

namespace zb {

// m(x, y) ~ x*y/255: t = x*y, (t + (t >> 8) + 0x80) >> 8, llvmpipe's unorm8 multiply. It is
// x*y/255 rounded to nearest for all but 24 of the 65536 pairs, where the fraction is just
// over one half and it rounds down (tests/rop/test_blend.cpp counts them).
constexpr uint8_t mul_unorm8(uint8_t x, uint8_t y) {
  const uint32_t t = uint32_t{x} * y;
  return static_cast<uint8_t>((t + (t >> 8) + 0x80u) >> 8);
}

// Alpha blend of one channel: min(255, m(s, a) + m(d, 255 - a)).
constexpr uint8_t blend_alpha(uint8_t s, uint8_t a, uint8_t d) {
  const uint32_t v = uint32_t{mul_unorm8(s, a)} + mul_unorm8(d, static_cast<uint8_t>(255 - a));
  return static_cast<uint8_t>(v > 255u ? 255u : v);
}

// Additive blend of one channel: min(255, d + m(s, a)).
constexpr uint8_t blend_additive(uint8_t s, uint8_t a, uint8_t d) {
  const uint32_t v = uint32_t{d} + mul_unorm8(s, a);
  return static_cast<uint8_t>(v > 255u ? 255u : v);
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

}  // namespace zb
