// zb_rop's tile port and retire port as lanes: each bus holds BEAT values side by side from bit 0
// up (docs/rtl.md "Port timing"), packed and unpacked a 32-bit word at a time instead of a
// masked read-modify-write per field. Templates over the Verilated model's port types.
#pragma once

#include <cstdint>
#include <type_traits>

#include "rtl_params.h"
#include "tile_io.h"

namespace zb {
namespace lanes {

// Widths: the accumulation word {r, acc_A, acc_B, acc_G, acc_R} (acc_R lowest), and the word
// planes' lanes in kPlane* order (colour pack_rgba, depth, coverage count, peel depth).
constexpr unsigned kAcc = unsigned(kRtlWboit.acc_bits), kRev = unsigned(kRtlWboit.rev_bits);
constexpr unsigned kColor = 32, kDepth = kRtlDepthBits, kCov = coverage_bits(kRtlCoverageSamples);
constexpr unsigned kWord[kWordPlanes] = {kColor, kDepth, kCov, kDepth};

// Writes values of at most 32 bits each, one after another, into a port (an integer of at most
// 64 bits, or Verilator's array of 32-bit words); the rest of the port is written on destruction.
template <class Port>
class Writer {
 public:
  explicit Writer(Port& port) : port_(port) {}
  void put(uint32_t v, unsigned width) {
    acc_ |= uint64_t(v & mask(width)) << fill_;
    fill_ += width;
    if (fill_ >= 32) flush_word();
  }
  ~Writer() {
    if constexpr (std::is_integral_v<Port>) {  // at most 64 bits: next_ < 2 while fill_ > 0
      port_ = Port(fill_ > 0 ? word_ | acc_ << (32 * next_) : word_);
    } else {
      if (fill_ > 0) port_[next_] = uint32_t(acc_);
    }
  }

 private:
  static uint32_t mask(unsigned w) { return w >= 32 ? ~0u : (1u << w) - 1; }
  void flush_word() {
    if constexpr (std::is_integral_v<Port>) {
      word_ |= (acc_ & 0xffffffffu) << (32 * next_);
    } else {
      port_[next_] = uint32_t(acc_);
    }
    ++next_;
    acc_ >>= 32;
    fill_ -= 32;
  }
  Port& port_;
  uint64_t acc_ = 0, word_ = 0;
  unsigned fill_ = 0, next_ = 0;
};

template <class Port>
class Reader {
 public:
  explicit Reader(const Port& port) : port_(port) {}
  uint32_t get(unsigned width) {
    if (fill_ < width) {
      acc_ |= uint64_t(word(next_++)) << fill_;
      fill_ += 32;
    }
    const uint32_t v = uint32_t(acc_) & (width >= 32 ? ~0u : (1u << width) - 1);
    acc_ >>= width;
    fill_ -= width;
    return v;
  }

 private:
  uint32_t word(unsigned i) const {
    if constexpr (std::is_integral_v<Port>) {
      return i < 2 ? uint32_t(uint64_t(port_) >> (32 * i)) : 0;
    } else {
      return port_[i];
    }
  }
  const Port& port_;
  uint64_t acc_ = 0;
  unsigned fill_ = 0, next_ = 0;
};

template <class Port>
AccumWord get_accum(Reader<Port>& r) {
  AccumWord w;
  for (uint32_t& c : w.acc) c = r.get(kAcc);
  w.reveal = r.get(kRev);
  return w;
}
template <class Port>
void put_accum(Writer<Port>& p, const AccumWord& w) {
  for (uint32_t c : w.acc) p.put(c, kAcc);
  p.put(w.reveal, kRev);
}

// A pixel's layers word, written: kRtlLayers slots {z, A, R, G, B} from bit 0 up (B lowest).
template <class Port>
void put_layers(Writer<Port>& w, const PixelLayers& px) {
  for (int j = 0; j < kRtlLayers; ++j) {
    const Layer& l = px.layer[size_t(j)];
    w.put(l.p.b, 8);
    w.put(l.p.g, 8);
    w.put(l.p.r, 8);
    w.put(l.p.a, 8);
    w.put(l.z, kDepth);
  }
}

// A pixel's layers word: kRtlLayers slots {z, A, R, G, B} from bit 0 up (B lowest); n the
// slots up to the last occupied one (A != 0).
template <class Port>
PixelLayers get_layers(Reader<Port>& r) {
  PixelLayers px;
  for (int j = 0; j < kRtlLayers; ++j) {
    Layer& l = px.layer[size_t(j)];
    l.p.b = uint8_t(r.get(8));
    l.p.g = uint8_t(r.get(8));
    l.p.r = uint8_t(r.get(8));
    l.p.a = uint8_t(r.get(8));
    l.z = r.get(kDepth);
    if (l.p.a != 0) px.n = j + 1;
  }
  return px;
}

}  // namespace lanes

// The beat the tile port read at the last edge (colour, depth, coverage, peel, accumulation).
template <class Model>
BeatWords read_beat(const Model& t) {
  using lanes::Reader;
  BeatWords w{};
  Reader color(t.tile_rcolor_o), depth(t.tile_rdepth_o), cov(t.tile_rcov_o),
      peel(t.tile_rpeel_o), acc(t.tile_racc_o);
  for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
    w[0][l] = color.get(lanes::kColor);
    w[1][l] = depth.get(lanes::kDepth);
    w[2][l] = cov.get(lanes::kCov);
    w[3][l] = peel.get(lanes::kDepth);
    w.accum[l] = lanes::get_accum(acc);
  }
  return w;
}

// A beat onto the tile port's write lanes (colour, depth, coverage, peel, accumulation).
template <class Model>
void put_beat(Model& t, const BeatWords& w) {
  using lanes::Writer;
  Writer color(t.tile_wcolor_i), depth(t.tile_wdepth_i), cov(t.tile_wcov_i),
      peel(t.tile_wpeel_i), acc(t.tile_wacc_i);
  for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
    color.put(w[0][l], lanes::kColor);
    depth.put(w[1][l], lanes::kDepth);
    cov.put(w[2][l], lanes::kCov);
    peel.put(w[3][l], lanes::kDepth);
    lanes::put_accum(acc, w.accum[l]);
  }
}

// Random bits for every lane of `w`'s planes not in `keep` (kPlane* mask): lanes the RTL must
// not read.
template <class Bits>
void scramble(BeatWords& w, uint8_t keep, Bits&& bits) {
  for (size_t pl = 0; pl < kWordPlanes; ++pl)
    if (!(keep >> pl & 1))
      for (auto& v : w[pl]) v = bits(lanes::kWord[pl]);
  if (!(keep & kPlaneAccum))
    for (AccumWord& a : w.accum) {
      for (uint32_t& c : a.acc) c = bits(lanes::kAcc);
      a.reveal = bits(lanes::kRev);
    }
}

}  // namespace zb
