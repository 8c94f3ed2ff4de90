// A DUT's declared blend arithmetic (docs/datapath.md "Declared arithmetic"): where the blend
// divides by its unit, how, and what stands for 1. zblend's own rule is the default and the only
// one the renderer uses; the conformance path (the checker, the C API, the DPI-C scoreboard)
// runs the golden model in the rule an outside ROP declares, as a reference model runs in the
// configuration a DUT declares. Each rule is a row of the table below, each division defined once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "fixed.h"

namespace zb {

// Where the blend rounds: each product divided and the quotients added, or the sum divided once.
enum class BlendRound : uint8_t { kEachProduct = 0, kSum = 1 };

// How a product (or the sum of two) of 8-bit values becomes 8 bits again.
enum class Divide : uint8_t {
  kZblend = 0,    // m(t) = (t + (t >> 8) + 0x80) >> 8 (zblend's, llvmpipe's)
  kRound255 = 1,  // t / 255 rounded half up, exactly: c = t + 0x80, (c + (c >> 8)) >> 8
  kFloor256 = 2,  // t >> 8
  kCeil256 = 3,   // (t + 0xff) >> 8
  kRound256 = 4,  // (t + 0x80) >> 8
};
constexpr unsigned kDivides = 5;

// What stands for 1 in the factors: 255 (1 - a = 255 - a) or 256 (1 - a = 256 - a).
enum class One : uint8_t { k255 = 0, k256 = 1 };

struct Arithmetic {
  BlendRound round = BlendRound::kEachProduct;
  Divide divide = Divide::kZblend;
  One one = One::k255;
  bool is_zblend() const {
    return round == BlendRound::kEachProduct && divide == Divide::kZblend && one == One::k255;
  }
  friend bool operator==(Arithmetic x, Arithmetic y) {
    return x.round == y.round && x.divide == y.divide && x.one == y.one;
  }
  friend bool operator!=(Arithmetic x, Arithmetic y) { return !(x == y); }
};

// The division of t (at most 256 * 255 * 2) under `d`; quotients above 255 are the callers' to
// saturate.
constexpr uint32_t divide(Divide d, uint32_t t) {
  switch (d) {
    case Divide::kZblend: return (t + (t >> 8) + 0x80u) >> 8;
    case Divide::kRound255: {
      const uint32_t c = t + 0x80u;
      return (c + (c >> 8)) >> 8;
    }
    case Divide::kFloor256: return t >> 8;
    case Divide::kCeil256: return (t + 0xffu) >> 8;
    case Divide::kRound256: return (t + 0x80u) >> 8;
  }
  return 0;
}

constexpr uint32_t one_value(One o) { return o == One::k256 ? 256u : 255u; }

constexpr uint8_t saturate8(uint32_t v) { return static_cast<uint8_t>(v > 255u ? 255u : v); }

// GL's (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) on one channel: s*a + d*(1 - a), under `r`.
// zblend's rule is blend_alpha (blend.h): min(255, m(s*a) + m(d*(255 - a))).
constexpr uint8_t blend_alpha(const Arithmetic& r, uint8_t s, uint8_t a, uint8_t d) {
  const uint32_t sa = uint32_t{s} * a, db = uint32_t{d} * (one_value(r.one) - a);
  return saturate8(r.round == BlendRound::kSum ? divide(r.divide, sa + db)
                                               : divide(r.divide, sa) + divide(r.divide, db));
}

// GL's (SRC_ALPHA, ONE) on one channel: s*a + d. Divided by product, the destination's factor
// ONE is exact (d + D(s*a)); on the sum, d is scaled by the rule's 1: D(s*a + d*one).
constexpr uint8_t blend_additive(const Arithmetic& r, uint8_t s, uint8_t a, uint8_t d) {
  const uint32_t sa = uint32_t{s} * a;
  return saturate8(r.round == BlendRound::kSum ? divide(r.divide, sa + uint32_t{d} * one_value(r.one))
                                               : d + divide(r.divide, sa));
}

// A rule's name: "<each|sum>-<zblend|round255|floor256|ceil256|round256>[-one256]", and
// "zblend" for the default (each-zblend). docs/datapath.md's table lists the names real ROPs
// use: sum-round255 (round(sum / 255)), sum-ceil256, sum-floor256.
std::string to_string(const Arithmetic& r);
// The rule named `name`, or nullopt.
std::optional<Arithmetic> parse_arithmetic(const std::string& name);
// Why `name` is no rule, one line with the names there are, for every program's error.
std::string arithmetic_error(const std::string& name);
// Every rule, in a fixed order (zblend first): 20 rules.
constexpr unsigned kArithmetics = 2 * kDivides * 2;
Arithmetic arithmetic_at(unsigned i);

}  // namespace zb
