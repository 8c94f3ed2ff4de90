#include "vectors.h"

#include <iterator>

#include <fmt/format.h>

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
      // Unused fields stay zero: the value for the clears of colour and the resolve, the
      // depth for the depth clear.
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
              .field(64, pack(t.clear_color)));
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
  }
  return "?";
}

int hex_digits(Plane p) { return p == Plane::kCoverage ? 2 : 8; }

uint32_t plane_value(const Framebuffer& fb, Plane p, size_t i) {
  switch (p) {
    case Plane::kColor: return pack(fb.color[i]);
    case Plane::kDepth: return fb.depth[i];
    case Plane::kCoverage: return fb.coverage[i];
    case Plane::kPeel: return fb.peel[i];
  }
  return 0;
}

std::string plane_hex(const Framebuffer& fb, Plane p) {
  const size_t n = size_t(fb.width) * size_t(fb.height);
  const int digits = hex_digits(p);
  std::string out;
  out.reserve(n * size_t(digits + 1));
  for (size_t i = 0; i < n; ++i)
    fmt::format_to(std::back_inserter(out), "{:0{}x}\n", plane_value(fb, p, i), digits);
  return out;
}

}  // namespace zb::conformance
