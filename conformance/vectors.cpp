#include "vectors.h"

#include <array>
#include <iterator>

#include <fmt/format.h>

#include "tile_io.h"

namespace zb::conformance {
namespace {

uint32_t pack(Rgba8 c) {
  return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24;
}

// A 128-bit command word; fields are set by their bit range in conformance_spec.md's table.
struct Word {
  uint64_t lo = 0, hi = 0;  // [63:0], [127:64]
  explicit Word(Opcode op) { hi = uint64_t(op) << 56; }
  Word& field(int lsb, uint64_t value) {  // a field inside [63:0] or inside [127:64]
    if (lsb < 64) lo |= value << lsb;
    else hi |= value << (lsb - 64);
    return *this;
  }
};

class Writer {
 public:
  void put(const Word& w) {
    fmt::format_to(std::back_inserter(body_), "{:016x}{:016x}\n", w.hi, w.lo);
    ++words_;
  }
  void put_ops(const std::vector<FrameOp>& ops) {
    for (const FrameOp& op : ops) {
      Word w(kOpFrameOp);
      w.field(0, uint64_t(op.kind));
      // Unused fields stay zero: the value for the clears of colour and the resolve under, the
      // depth for the depth clear; the resolve wboit has none.
      if (op.kind == FrameOpKind::kClearColor || op.kind == FrameOpKind::kResolveUnder)
        w.field(32, pack(op.value));
      if (op.kind == FrameOpKind::kClearDepth) w.field(64, op.depth);
      put(w);
    }
  }
  Stream finish(uint64_t fragments) {
    Stream s;
    s.hex = fmt::format("{:032x}\n", words_) + body_;
    s.words = words_;
    s.fragments = fragments;
    return s;
  }

 private:
  std::string body_;
  uint64_t words_ = 0;
};

}  // namespace

Stream encode_stream(const Trace& t) {
  Writer out;
  out.put(Word(kOpFrame)
              .field(0, uint64_t(t.width))
              .field(16, uint64_t(t.height))
              .field(32, uint64_t(t.depth_bits))
              .field(40, uint64_t(t.coverage_samples))
              .field(64, pack(t.clear_color))
              .field(96, uint64_t(t.wboit.acc_bits))
              .field(104, uint64_t(t.wboit.rev_bits))
              .field(112, uint64_t(t.wboit.weight_bits)));
  uint64_t fragments = 0;
  for (const TracePass& p : t.passes) {
    out.put_ops(p.frame_ops);
    out.put(Word(kOpPass).field(0, pack_state(p.state)));
    for (const Fragment& f : p.fragments)  // front is the feeder's: not sent
      out.put(Word(kOpFrag)
                  .field(0, f.x)
                  .field(16, f.y)
                  .field(32, f.z)
                  .field(64, pack(f.color))
                  .field(96, f.coverage));
    fragments += p.fragments.size();
    out.put(Word(kOpEndPass));
  }
  out.put_ops(t.final_ops);
  out.put(Word(kOpEnd));
  return out.finish(fragments);
}

const char* to_string(Plane p) {
  switch (p) {
    case Plane::kColor: return "color";
    case Plane::kDepth: return "depth";
    case Plane::kCoverage: return "coverage";
    case Plane::kPeel: return "peel";
    case Plane::kAccum: return "accum";
  }
  return "?";
}

int hex_digits(Plane p, const WboitFormat& f) {
  switch (p) {
    case Plane::kCoverage: return 2;
    case Plane::kAccum: return (accum_word_bits(f) + 3) / 4;
    default: return 8;
  }
}

namespace {

// The accumulation word of pixel i, its fields from bit 0 up: acc R, G, B, A, then r.
std::string accum_word(const Framebuffer& fb, size_t i) {
  std::array<uint64_t, 3> bits{};  // at most 4 * 32 + 16 = 144 bits
  int at = 0;
  auto put = [&](uint64_t v, int width) {
    for (int b = 0; b < width; ++b, ++at)
      if (v >> b & 1u) bits[size_t(at / 64)] |= uint64_t{1} << (at % 64);
  };
  for (const uint32_t a : fb.accum_at(i)) put(a, fb.wboit.acc_bits);
  put(fb.reveal_at(i), fb.wboit.rev_bits);
  std::string s;
  for (int d = hex_digits(Plane::kAccum, fb.wboit) - 1; d >= 0; --d)
    s += "0123456789abcdef"[(bits[size_t(d / 16)] >> (d % 16 * 4)) & 15u];
  return s;
}

}  // namespace

std::string plane_word(const Framebuffer& fb, Plane p, size_t i) {
  switch (p) {
    case Plane::kColor: return fmt::format("{:08x}", pack(fb.color[i]));
    case Plane::kDepth: return fmt::format("{:08x}", fb.depth[i]);
    case Plane::kCoverage: return fmt::format("{:02x}", fb.coverage[i]);
    case Plane::kPeel: return fmt::format("{:08x}", fb.peel[i]);
    case Plane::kAccum: return accum_word(fb, i);
  }
  return "";
}

std::string plane_hex(const Framebuffer& fb, Plane p) {
  const size_t n = size_t(fb.width) * size_t(fb.height);
  std::string out;
  out.reserve(n * size_t(hex_digits(p, fb.wboit) + 1));
  for (size_t i = 0; i < n; ++i) {
    out += plane_word(fb, p, i);
    out += '\n';
  }
  return out;
}

}  // namespace zb::conformance
