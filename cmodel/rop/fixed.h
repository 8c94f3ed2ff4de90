// The datapath's number formats (docs/datapath.md, "Numerics"): RGBA8, sub-pixel coordinates,
// depth widths and coverage sample counts. Their arithmetic is in blend.h.
#pragma once

#include <cstdint>

namespace zb {

struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 0;
  friend bool operator==(Rgba8 x, Rgba8 y) {
    return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
  }
  friend bool operator!=(Rgba8 x, Rgba8 y) { return !(x == y); }
};

// Sub-pixel precision of window coordinates: 8 fractional bits.
constexpr int kSubpixelBits = 8;
constexpr int32_t kSubpixelOne = 1 << kSubpixelBits;

constexpr int kMinDepthBits = 8;
constexpr int kMaxDepthBits = 32;
constexpr int kDefaultDepthBits = 24;

// Largest depth value of a `bits`-wide unorm depth buffer (window depth 1.0).
constexpr uint32_t depth_max(int bits) {
  return bits >= 32 ? 0xffffffffu : (uint32_t{1} << bits) - 1u;
}

// Coverage anti-aliasing (US 5,123,085; docs/datapath.md "Coverage blend", raster.md
// "Coverage"). N samples per pixel, a power of two from 1 to 16; the coverage plane stores a
// count 0..N in coverage_bits(N) = ceil(log2(N + 1)) bits.
constexpr int kMaxCoverageSamples = 16;
constexpr int kDefaultCoverageSamples = 16;

constexpr bool valid_coverage_samples(int n) {
  return n >= 1 && n <= kMaxCoverageSamples && (n & (n - 1)) == 0;
}

// log2(N) for a valid N.
constexpr int coverage_log2(int n) {
  int l = 0;
  while ((1 << l) < n) ++l;
  return l;
}

// ceil(log2(N + 1)): bits of a count 0..N.
constexpr int coverage_bits(int n) { return coverage_log2(n + 1); }

// Weighted blended OIT (docs/datapath.md "7. Accumulate blend"): the widths of the
// accumulation and revealage planes and the weight's range, the RTL's ACC_BITS, REV_BITS and
// WEIGHT_BITS. One accumulation channel is acc_bits wide (unsigned, saturating); revealage is
// a rev_bits unorm (all ones = 1.0); the depth weight F runs from 1 to 2^weight_bits - 1.
// The defaults are the knees of docs/sweeps.md "wboit": 12-bit channels saturate, wider ones
// gain nothing; weight ranges beyond 2^4 weigh the layers no better.
struct WboitFormat {
  int acc_bits = 16;
  int rev_bits = 8;
  int weight_bits = 4;
  friend bool operator==(const WboitFormat& x, const WboitFormat& y) {
    return x.acc_bits == y.acc_bits && x.rev_bits == y.rev_bits &&
           x.weight_bits == y.weight_bits;
  }
  friend bool operator!=(const WboitFormat& x, const WboitFormat& y) { return !(x == y); }
};
constexpr int kMinAccBits = 8, kMaxAccBits = 32;
constexpr int kMinRevBits = 8, kMaxRevBits = 16;
constexpr int kMinWeightBits = 0, kMaxWeightBits = 16;

constexpr bool valid_wboit_format(const WboitFormat& f) {
  return f.acc_bits >= kMinAccBits && f.acc_bits <= kMaxAccBits && f.rev_bits >= kMinRevBits &&
         f.rev_bits <= kMaxRevBits && f.weight_bits >= kMinWeightBits &&
         f.weight_bits <= kMaxWeightBits;
}

}  // namespace zb
