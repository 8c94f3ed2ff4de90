#include "vectors.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "geometry/geometry.h"
#include "rop/rop.h"
#include "tile_io.h"

namespace zb::conformance {
namespace {

uint32_t pack(Rgba8 c) {
  return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24;
}
Rgba8 unpack(uint32_t w) { return {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)}; }

// The commands' fields (docs/conformance.md "stream.hex"): bit ranges of the 128-bit word, each
// inside [63:0] or inside [127:64]. The encoder and the decoder both read them from here.
struct Field {
  int lsb, width;
};
constexpr uint64_t mask(Field f) { return f.width == 64 ? ~uint64_t{0} : (uint64_t{1} << f.width) - 1; }
constexpr Field kOpcodeField{120, 8};
constexpr Field kFrameWidth{0, 16}, kFrameHeight{16, 16}, kFrameDepthBits{32, 8},
    kFrameSamples{40, 8}, kFrameClear{64, 32}, kFrameAccBits{96, 8}, kFrameRevBits{104, 8},
    kFrameWeightBits{112, 8};
// The whole 16-bit pass state: [15:13] is mlab-K's K - 1 (the adapter's state_layers_i).
constexpr Field kPassState{0, kStateBits};
constexpr Field kFragX{0, 16}, kFragY{16, 16}, kFragZ{32, 32}, kFragRgba{64, 32},
    kFragCoverage{96, 8};
constexpr Field kOpKind{0, 4}, kOpValue{32, 32}, kOpDepth{64, 32};

// A 128-bit command word.
struct Word {
  uint64_t lo = 0, hi = 0;  // [63:0], [127:64]
  Word() = default;
  explicit Word(Opcode op) { field(kOpcodeField, op); }
  Word& field(Field f, uint64_t value) {
    if (f.lsb < 64) lo |= value << f.lsb;
    else hi |= value << (f.lsb - 64);
    return *this;
  }
  uint64_t get(Field f) const {
    return (f.lsb < 64 ? lo >> f.lsb : hi >> (f.lsb - 64)) & mask(f);
  }
  // True when no bit outside the opcode and `fields` is set.
  bool only(std::initializer_list<Field> fields) const {
    Word used;
    used.field(kOpcodeField, 0xff);
    for (const Field f : fields) used.field(f, mask(f));
    return (lo & ~used.lo) == 0 && (hi & ~used.hi) == 0;
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
      w.field(kOpKind, uint64_t(op.kind));
      // Unused fields stay zero: the value for the clears of colour and the resolve under, the
      // depth for the depth clear; the resolves of wboit and layers have none.
      if (op.kind == FrameOpKind::kClearColor || op.kind == FrameOpKind::kResolveUnder)
        w.field(kOpValue, pack(op.value));
      if (op.kind == FrameOpKind::kClearDepth) w.field(kOpDepth, op.depth);
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
              .field(kFrameWidth, uint64_t(t.width))
              .field(kFrameHeight, uint64_t(t.height))
              .field(kFrameDepthBits, uint64_t(t.depth_bits))
              .field(kFrameSamples, uint64_t(t.coverage_samples))
              .field(kFrameClear, pack(t.clear_color))
              .field(kFrameAccBits, uint64_t(t.wboit.acc_bits))
              .field(kFrameRevBits, uint64_t(t.wboit.rev_bits))
              .field(kFrameWeightBits, uint64_t(t.wboit.weight_bits)));
  uint64_t fragments = 0;
  for (const TracePass& p : t.passes) {
    out.put_ops(p.frame_ops);
    out.put(Word(kOpPass).field(kPassState, pack_state(p.state)));
    for (const Fragment& f : p.fragments)  // front is the feeder's: not sent
      out.put(Word(kOpFrag)
                  .field(kFragX, f.x)
                  .field(kFragY, f.y)
                  .field(kFragZ, f.z)
                  .field(kFragRgba, pack(f.color))
                  .field(kFragCoverage, f.coverage));
    fragments += p.fragments.size();
    out.put(Word(kOpEndPass));
  }
  out.put_ops(t.final_ops);
  out.put(Word(kOpEnd));
  return out.finish(fragments);
}

namespace {

const char* command_name(uint64_t op) {
  switch (op) {
    case kOpFrame: return "FRAME";
    case kOpPass: return "PASS";
    case kOpFrag: return "FRAG";
    case kOpEndPass: return "END_PASS";
    case kOpFrameOp: return "FRAME_OP";
    case kOpEnd: return "END";
  }
  return "?";
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// stream.hex line by line, each a word; fail() names the file and the line last read.
class StreamReader {
 public:
  StreamReader(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  int line() const { return line_; }
  bool at_end() const { return pos_ >= text_.size(); }

  [[noreturn]] void fail(const std::string& what) const { fail_at(line_, what); }
  [[noreturn]] void fail_at(int line, const std::string& what) const {
    throw TraceError(fmt::format("{} line {}: {}", name_, line, what));
  }

  // The next line as a word; false at the end of the text.
  bool next(Word& w) {
    if (at_end()) return false;
    const size_t end = std::min(text_.find('\n', pos_), text_.size());
    std::string_view s(text_.data() + pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    if (s.size() != 32)
      fail(fmt::format("{} characters where a word's 32 hex digits belong ($readmemh, one word a "
                       "line, no addresses or comments)", s.size()));
    w = Word();
    for (size_t i = 0; i < 32; ++i) {
      const int v = hex_value(s[i]);
      if (v < 0)
        fail(fmt::format("column {}: character 0x{:02x} is not a hex digit", i + 1, uint8_t(s[i])));
      uint64_t& half = i < 16 ? w.hi : w.lo;
      half = half << 4 | uint64_t(v);
    }
    return true;
  }

 private:
  const std::string& text_;
  const std::string& name_;
  size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace

Trace decode_stream(const std::string& text, const std::string& name) {
  StreamReader in(text, name);
  Word w;
  if (!in.next(w))
    in.fail_at(1, "the file is empty (a stream.hex starts with the count of its words; export "
                  "the suite again: zblend conformance export DIR)");
  if (w.hi != 0) in.fail("the count line is not a count: its upper 64 bits are set");
  if (w.lo < 2)
    in.fail(fmt::format("the count line announces {} word{}: a stream holds at least FRAME and "
                        "END", w.lo, w.lo == 1 ? "" : "s"));
  const uint64_t count = w.lo;
  Trace t;
  TracePass pass;
  std::vector<FrameOp> ops;  // the frame operations before the next pass, or after the last
  bool in_pass = false, ended = false;
  int pass_line = 0;  // where the open pass began
  for (uint64_t n = 0; n < count && !ended; ++n) {
    if (!in.next(w))
      in.fail_at(in.line() + 1, fmt::format("the file ends here, but its count line announces {} "
                                            "words (through line {}): it is truncated (copy or "
                                            "export it again)", count, count + 1));
    const uint64_t op = w.get(kOpcodeField);
    const char* cmd = command_name(op);
    if (op < kOpFrame || op > kOpEnd)
      in.fail(fmt::format("opcode 0x{:02x} is not a command (0x01 FRAME to 0x06 END)", op));
    if ((n == 0) != (op == kOpFrame))
      in.fail(n == 0 ? fmt::format("the first word is {}, not FRAME (a stream starts with the "
                                   "frame)", cmd)
                     : std::string("a second FRAME (a stream has one, its first word)"));
    auto check_fields = [&](std::initializer_list<Field> fields) {
      if (!w.only(fields))
        in.fail(fmt::format("{} has bits set outside its fields (unused bits are zero: "
                            "docs/conformance.md \"stream.hex\")", cmd));
    };
    auto check_between_passes = [&] {
      if (in_pass)
        in.fail(fmt::format("{} inside the pass that line {} opened (END_PASS closes it first)",
                            cmd, pass_line));
    };
    switch (op) {
      case kOpFrame: {
        check_fields({kFrameWidth, kFrameHeight, kFrameDepthBits, kFrameSamples, kFrameClear,
                      kFrameAccBits, kFrameRevBits, kFrameWeightBits});
        t.width = int(w.get(kFrameWidth));
        t.height = int(w.get(kFrameHeight));
        t.depth_bits = int(w.get(kFrameDepthBits));
        t.coverage_samples = int(w.get(kFrameSamples));
        t.clear_color = unpack(uint32_t(w.get(kFrameClear)));
        t.wboit = {int(w.get(kFrameAccBits)), int(w.get(kFrameRevBits)),
                   int(w.get(kFrameWeightBits))};
        if (t.width < 1 || t.width > kMaxFrameSize || t.height < 1 || t.height > kMaxFrameSize)
          in.fail(fmt::format("FRAME: frame {}x{} is out of range (width and height 1 to {})",
                              t.width, t.height, kMaxFrameSize));
        if (t.depth_bits < kMinDepthBits || t.depth_bits > kMaxDepthBits)
          in.fail(fmt::format("FRAME: depth_bits {} is out of range ({} to {})", t.depth_bits,
                              kMinDepthBits, kMaxDepthBits));
        if (!valid_coverage_samples(t.coverage_samples))
          in.fail(fmt::format("FRAME: coverage_samples {} is not 1, 2, 4, 8 or 16",
                              t.coverage_samples));
        if (!valid_wboit_format(t.wboit))
          in.fail(fmt::format("FRAME: acc_bits {}, rev_bits {}, weight_bits {}: the ranges are {} "
                              "to {}, {} to {} and {} to {}", t.wboit.acc_bits, t.wboit.rev_bits,
                              t.wboit.weight_bits, kMinAccBits, kMaxAccBits, kMinRevBits,
                              kMaxRevBits, kMinWeightBits, kMaxWeightBits));
        break;
      }
      case kOpPass: {
        check_fields({kPassState});
        check_between_passes();
        pass = TracePass{fmt::format("pass-{}", t.passes.size() + 1), std::move(ops), {}, {}};
        ops.clear();
        const uint64_t state = w.get(kPassState);
        if (!unpack_state(uint16_t(state), pass.state))
          in.fail(fmt::format("PASS: state 0x{:x} is not a pass state register (blend [7:5] at "
                              "most 6; docs/datapath.md \"The pass state\")", state));
        in_pass = true;
        pass_line = in.line();
        break;
      }
      case kOpFrag: {
        check_fields({kFragX, kFragY, kFragZ, kFragRgba, kFragCoverage});
        if (!in_pass) in.fail("FRAG outside a pass (fragments come between PASS and END_PASS)");
        Fragment f;
        const uint64_t x = w.get(kFragX), y = w.get(kFragY), z = w.get(kFragZ);
        const uint64_t coverage = w.get(kFragCoverage);
        if (x >= uint64_t(t.width) || y >= uint64_t(t.height))
          in.fail(fmt::format("FRAG: pixel ({}, {}) is outside the {}x{} frame", x, y, t.width,
                              t.height));
        if (z > depth_max(t.depth_bits))
          in.fail(fmt::format("FRAG: depth 0x{:x} exceeds the {}-bit depth (at most 0x{:x})", z,
                              t.depth_bits, depth_max(t.depth_bits)));
        if (coverage > uint64_t(t.coverage_samples))
          in.fail(fmt::format("FRAG: coverage {} exceeds the frame's {} samples", coverage,
                              t.coverage_samples));
        f.x = uint16_t(x);
        f.y = uint16_t(y);
        f.z = uint32_t(z);
        f.color = unpack(uint32_t(w.get(kFragRgba)));
        f.coverage = uint8_t(coverage);
        pass.fragments.push_back(f);
        break;
      }
      case kOpEndPass:
        check_fields({});
        if (!in_pass) in.fail("END_PASS without a PASS before it");
        t.passes.push_back(std::move(pass));
        in_pass = false;
        break;
      case kOpFrameOp: {
        check_fields({kOpKind, kOpValue, kOpDepth});
        check_between_passes();
        const uint64_t kind = w.get(kOpKind);
        if (kind >= kFrameOpKinds)
          in.fail(fmt::format("FRAME_OP: kind {} is not a frame operation (0 clear colour, 1 clear "
                              "depth, 2 copy depth to peel, 3 resolve under, 4 resolve wboit, 5 "
                              "resolve layers)", kind));
        FrameOp o;
        o.kind = FrameOpKind(kind);
        o.value = unpack(uint32_t(w.get(kOpValue)));
        o.depth = uint32_t(w.get(kOpDepth));
        ops.push_back(o);
        break;
      }
      case kOpEnd:
        check_fields({});
        check_between_passes();
        if (n + 1 != count)
          in.fail(fmt::format("END, but the count line announces {} words (through line {}): "
                              "correct the count", count, count + 1));
        ended = true;
        break;
    }
  }
  if (!ended)
    in.fail(fmt::format("the last word is {}, not END (the count line announces {} words)",
                        command_name(w.get(kOpcodeField)), count));
  if (!in.at_end())
    in.fail_at(in.line() + 1, fmt::format("a line after END (the count line announces {} words, "
                                          "through line {}): remove it or correct the count",
                                          count, count + 1));
  t.final_ops = std::move(ops);
  return t;
}

Trace read_stream(const std::string& path) {
  std::error_code ec;
  // An ifstream opens a directory and then reads nothing: say what it is.
  if (std::filesystem::is_directory(path, ec))
    throw TraceError(fmt::format("{}: is a directory (give a test's stream.hex)", path));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw TraceError(fmt::format("{}: cannot open: {} (give a test's stream.hex, from zblend "
                                 "conformance export)", path, std::strerror(errno)));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw TraceError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  return decode_stream(bytes.str(), path);
}

FrameHistory stream_history(Trace t, const std::vector<std::pair<int, int>>& pixels,
                            const Arithmetic& arithmetic) {
  for (TracePass& p : t.passes) p.name.clear();
  return record_history(t, pixels, arithmetic);
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

uint64_t frame_digest(const Framebuffer& fb) {
  const size_t n = size_t(fb.width) * size_t(fb.height);
  uint64_t h = 0xcbf29ce484222325ull;
  auto add = [&h](uint32_t word) { h = (h ^ word) * 0x100000001b3ull; };
  for (size_t i = 0; i < n; ++i) add(pack(fb.color[i]));
  for (size_t i = 0; i < n; ++i) add(fb.depth[i]);
  for (size_t i = 0; i < n; ++i) add(fb.coverage[i]);
  for (size_t i = 0; i < n; ++i) add(fb.peel[i]);
  return h;
}

namespace {

// The golden model, its frame's digest taken as each pass ends.
class DigestingRop final : public Backend {
 public:
  explicit DigestingRop(const Arithmetic& arithmetic) { golden_.set_arithmetic(arithmetic); }
  const char* name() const override { return "golden"; }
  using Backend::begin_frame;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color, int coverage_samples,
                   const WboitFormat& wboit) override {
    golden_.begin_frame(width, height, depth_bits, clear_color, coverage_samples, wboit);
  }
  void begin_pass(const RopState& state) override { golden_.begin_pass(state); }
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override { golden_.draw(fragments, count); }
  PassStats end_pass() override {
    digests.push_back({int(digests.size()) + 1, frame_digest(golden_.framebuffer())});
    return golden_.end_pass();
  }
  void frame_op(const FrameOp& op) override { golden_.frame_op(op); }
  const Framebuffer& framebuffer() const override { return golden_.framebuffer(); }

  std::vector<PassDigest> digests;

 private:
  GoldenRop golden_;
};

}  // namespace

GoldenReplay replay_golden(const Trace& trace, const Arithmetic& arithmetic) {
  DigestingRop rop(arithmetic);
  replay_trace(trace, rop);
  return {std::move(rop.digests), rop.framebuffer()};
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
