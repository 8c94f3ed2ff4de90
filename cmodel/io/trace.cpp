#include "trace.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "geometry/geometry.h"
#include "atomic_file.h"

namespace zb {
namespace {

constexpr char kMagic[8] = {'Z', 'B', 'T', 'R', 'A', 'C', 'E', '\0'};
// 2: coverage samples in the header, coverage per fragment; 3: 13-bit pass state (3-bit blend,
// peel_test), frame operations before each pass and after the last; 4: the accumulation,
// revealage and weight widths in the header (blend 5, frame operation 4); 5: 16-bit pass
// state (layers, blend 6, frame operation 5). Version 4 files read as they are.
constexpr uint32_t kVersion = 5;
constexpr uint32_t kOldestVersion = 4;
constexpr uint32_t kMaxFrameOps = 64;
constexpr uint32_t kMaxPasses = 1024;
constexpr uint32_t kMaxNameLength = 256;

void put(std::string& out, const void* p, size_t n) { out.append(static_cast<const char*>(p), n); }
void put_u8(std::string& out, uint8_t v) { out.push_back(static_cast<char>(v)); }
void put_u16(std::string& out, uint16_t v) { for (int i = 0; i < 2; ++i) put_u8(out, uint8_t(v >> (8 * i))); }
void put_u32(std::string& out, uint32_t v) { for (int i = 0; i < 4; ++i) put_u8(out, uint8_t(v >> (8 * i))); }
void put_u64(std::string& out, uint64_t v) { for (int i = 0; i < 8; ++i) put_u8(out, uint8_t(v >> (8 * i))); }

// Reads little-endian fields, with the offset of each for error messages.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void fail(size_t at, const std::string& what) const {
    throw TraceError(fmt::format("trace '{}': byte {}: {}", name_, at, what), at);
  }
  size_t offset() const { return pos_; }
  size_t remaining() const { return bytes_.size() - pos_; }
  uint64_t get(int n, const char* what) {
    if (remaining() < size_t(n)) fail(pos_, fmt::format("truncated, expected {}", what));
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint64_t(uint8_t(bytes_[pos_ + size_t(i)])) << (8 * i);
    pos_ += size_t(n);
    return v;
  }
  const uint8_t* take(size_t n, const char* what) {
    if (remaining() < n) fail(pos_, fmt::format("truncated, expected {}", what));
    const auto* p = reinterpret_cast<const uint8_t*>(bytes_.data() + pos_);
    pos_ += n;
    return p;
  }
  std::string get_string(size_t n, const char* what) {
    if (remaining() < n) fail(pos_, fmt::format("truncated, expected {}", what));
    std::string s(bytes_.substr(pos_, n));
    pos_ += n;
    return s;
  }

 private:
  std::string_view bytes_;
  const std::string& name_;
  size_t pos_ = 0;
};

void put_ops(std::string& out, const std::vector<FrameOp>& ops) {
  put_u32(out, uint32_t(ops.size()));
  for (const FrameOp& op : ops) {
    put_u8(out, uint8_t(op.kind));
    for (uint8_t c : {op.value.r, op.value.g, op.value.b, op.value.a}) put_u8(out, c);
    put_u32(out, op.depth);
  }
}

// `kinds`: the frame operation codes the file's version has.
std::vector<FrameOp> get_ops(Reader& r, const std::string& where, uint64_t kinds) {
  const size_t at = r.offset();
  const uint64_t n = r.get(4, "a frame op count");
  if (n > kMaxFrameOps) r.fail(at, fmt::format("{}: {} frame ops is more than {}", where, n, kMaxFrameOps));
  std::vector<FrameOp> ops(static_cast<size_t>(n));
  for (FrameOp& op : ops) {
    const size_t at_op = r.offset();
    const uint64_t kind = r.get(1, "a frame op kind");
    if (kind >= kinds) r.fail(at_op, fmt::format("{}: frame op kind {} is unknown", where, kind));
    op.kind = FrameOpKind(kind);
    op.value.r = uint8_t(r.get(1, "a frame op value"));
    op.value.g = uint8_t(r.get(1, "a frame op value"));
    op.value.b = uint8_t(r.get(1, "a frame op value"));
    op.value.a = uint8_t(r.get(1, "a frame op value"));
    op.depth = uint32_t(r.get(4, "a frame op depth"));
  }
  return ops;
}

}  // namespace

Trace make_trace(const RasterizedScene& rs, const PassPlan& plan) {
  Trace t;
  t.width = rs.viewport.width;
  t.height = rs.viewport.height;
  t.depth_bits = rs.viewport.depth_bits;
  t.coverage_samples = rs.viewport.coverage_samples;
  t.wboit = rs.viewport.wboit;
  t.clear_color = rs.background;
  for (const PassState& p : plan.passes) {
    TracePass tp{p.name, {}, p.rop, pass_fragments(rs, p)};
    for (const FrameOp& op : p.frame_ops) tp.frame_ops.push_back(resolve_op(op, rs.background));
    t.passes.push_back(std::move(tp));
  }
  for (const FrameOp& op : plan.final_ops) t.final_ops.push_back(resolve_op(op, rs.background));
  return t;
}

void encode_fragment(std::string& out, const Fragment& f) {
  uint8_t rec[kTraceFragmentBytes] = {};
  const auto set = [&rec](int at, uint64_t v, int n) {
    for (int i = 0; i < n; ++i) rec[at + i] = uint8_t(v >> (8 * i));
  };
  set(0, f.x, 2);
  set(2, f.y, 2);
  set(4, f.z, 4);
  rec[8] = f.color.r, rec[9] = f.color.g, rec[10] = f.color.b, rec[11] = f.color.a;
  rec[12] = f.front ? 1 : 0;
  rec[13] = f.coverage;  // flags bits 8..15
  set(16, f.prim, 4);
  out.append(reinterpret_cast<const char*>(rec), sizeof rec);
}

bool decode_fragment(const uint8_t* rec, int width, int height, int depth_bits, int samples,
                     Fragment& f, std::string* why) {
  const auto bad = [why](std::string text) {
    if (why) *why = std::move(text);
    return false;
  };
  auto get = [rec](int at, int n) {
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint64_t(rec[at + i]) << (8 * i);
    return v;
  };
  f.x = uint16_t(get(0, 2));
  f.y = uint16_t(get(2, 2));
  const uint64_t z = get(4, 4);
  f.color = {rec[8], rec[9], rec[10], rec[11]};
  const uint64_t flags = get(12, 4);
  f.prim = uint32_t(get(16, 4));
  if (f.x >= width || f.y >= height)
    return bad(fmt::format("fragment ({}, {}) is outside the {}x{} frame", f.x, f.y, width, height));
  if (z > depth_max(depth_bits))
    return bad(fmt::format("fragment depth {} exceeds {} bits", z, depth_bits));
  if (flags & ~uint64_t{0xff01}) return bad("fragment flags have reserved bits set");
  const uint64_t coverage = (flags >> 8) & 0xffu;
  if (coverage > uint64_t(samples))
    return bad(fmt::format("fragment coverage {} exceeds the {} samples", coverage, samples));
  f.z = uint32_t(z);
  f.front = flags & 1;
  f.coverage = uint8_t(coverage);
  return true;
}

std::string serialize_trace(const Trace& t) {
  std::string out;
  out.reserve(serialized_size(t));
  put(out, kMagic, sizeof kMagic);
  put_u32(out, kVersion);
  put_u32(out, uint32_t(t.width));
  put_u32(out, uint32_t(t.height));
  put_u32(out, uint32_t(t.depth_bits));
  put_u32(out, uint32_t(t.coverage_samples));
  for (int v : {t.wboit.acc_bits, t.wboit.rev_bits, t.wboit.weight_bits}) put_u8(out, uint8_t(v));
  for (uint8_t c : {t.clear_color.r, t.clear_color.g, t.clear_color.b, t.clear_color.a}) put_u8(out, c);
  put_u32(out, uint32_t(t.passes.size()));
  for (const TracePass& p : t.passes) {
    put_u32(out, uint32_t(p.name.size()));
    put(out, p.name.data(), p.name.size());
    put_ops(out, p.frame_ops);
    put_u16(out, pack_state(p.state));
    put_u64(out, p.fragments.size());
    for (const Fragment& f : p.fragments) encode_fragment(out, f);
  }
  put_ops(out, t.final_ops);
  return out;
}

size_t serialized_size(const Trace& t) {
  const auto ops = [](const std::vector<FrameOp>& v) { return 4 + 9 * v.size(); };
  size_t n = sizeof kMagic + 4 * 5 + 3 + 4 + 4 + ops(t.final_ops);
  for (const TracePass& p : t.passes)
    n += 4 + p.name.size() + ops(p.frame_ops) + 2 + 8 + p.fragments.size() * kTraceFragmentBytes;
  return n;
}

std::string write_trace(const std::string& path, const Trace& trace) {
  return write_file_atomic(path, serialize_trace(trace));
}

void scan_trace(std::string_view bytes, const std::string& name,
                const std::function<void(const Trace&)>& on_header,
                const std::function<void(TracePass&)>& on_pass,
                const std::function<void(const std::vector<FrameOp>&)>& on_final) {
  Reader r(bytes, name);
  if (r.get_string(sizeof kMagic, "the magic 'ZBTRACE'") != std::string(kMagic, sizeof kMagic))
    r.fail(0, "not a zblend trace (bad magic)");
  const size_t at_version = r.offset();
  const uint64_t version = r.get(4, "the version");
  if (version < kOldestVersion || version > kVersion)
    r.fail(at_version, fmt::format("version {} is not supported (this zblend reads {} to {})",
                                   version, kOldestVersion, kVersion));
  // Version 4 has no layers: the core state and frame operations.
  const uint64_t op_kinds = version == 4 ? kCoreFrameOpKinds : kFrameOpKinds;
  Trace t;
  const size_t at_size = r.offset();
  const uint64_t w = r.get(4, "the width"), h = r.get(4, "the height");
  if (w < 1 || w > uint64_t(kMaxFrameSize) || h < 1 || h > uint64_t(kMaxFrameSize))
    r.fail(at_size, fmt::format("frame {}x{} is out of range (1 to {})", w, h, kMaxFrameSize));
  t.width = int(w);
  t.height = int(h);
  const size_t at_bits = r.offset();
  const uint64_t bits = r.get(4, "the depth width");
  if (bits < uint64_t(kMinDepthBits) || bits > uint64_t(kMaxDepthBits))
    r.fail(at_bits, fmt::format("depth width {} is out of range ({} to {})", bits, kMinDepthBits,
                                kMaxDepthBits));
  t.depth_bits = int(bits);
  const size_t at_samples = r.offset();
  const uint64_t samples = r.get(4, "the coverage samples");
  if (samples > uint64_t(kMaxCoverageSamples) || !valid_coverage_samples(int(samples)))
    r.fail(at_samples, fmt::format("coverage samples {} is not a power of two from 1 to {}",
                                   samples, kMaxCoverageSamples));
  t.coverage_samples = int(samples);
  const size_t at_wboit = r.offset();
  t.wboit.acc_bits = int(r.get(1, "the accumulation width"));
  t.wboit.rev_bits = int(r.get(1, "the revealage width"));
  t.wboit.weight_bits = int(r.get(1, "the weight width"));
  if (!valid_wboit_format(t.wboit))
    r.fail(at_wboit, fmt::format("accumulation {}, revealage {}, weight {} bits: out of range "
                                 "({} to {}, {} to {}, {} to {})",
                                 t.wboit.acc_bits, t.wboit.rev_bits, t.wboit.weight_bits,
                                 kMinAccBits, kMaxAccBits, kMinRevBits, kMaxRevBits,
                                 kMinWeightBits, kMaxWeightBits));
  t.clear_color.r = uint8_t(r.get(1, "the clear colour"));
  t.clear_color.g = uint8_t(r.get(1, "the clear colour"));
  t.clear_color.b = uint8_t(r.get(1, "the clear colour"));
  t.clear_color.a = uint8_t(r.get(1, "the clear colour"));
  const size_t at_passes = r.offset();
  const uint64_t passes = r.get(4, "the pass count");
  if (passes > kMaxPasses)
    r.fail(at_passes, fmt::format("{} passes is more than {}", passes, kMaxPasses));
  if (on_header) on_header(t);
  TracePass pass;  // one pass at a time, its buffers kept for the next
  for (uint64_t p = 0; p < passes; ++p) {
    const size_t at_name = r.offset();
    const uint64_t len = r.get(4, "a pass name length");
    if (len > kMaxNameLength) r.fail(at_name, fmt::format("pass name of {} bytes", len));
    pass.name = r.get_string(size_t(len), "a pass name");
    pass.frame_ops = get_ops(r, fmt::format("pass {}", p + 1), op_kinds);
    const size_t at_state = r.offset();
    const uint64_t state_bits = r.get(2, "a pass state");
    if (version == 4 ? !unpack_core_state(state_bits, pass.state)
                     : !unpack_state(uint16_t(state_bits), pass.state))
      r.fail(at_state, fmt::format("pass {}: invalid pass state", p + 1));
    const size_t at_count = r.offset();
    const uint64_t count = r.get(8, "a fragment count");
    if (count > r.remaining() / kTraceFragmentBytes)
      r.fail(at_count, fmt::format("pass {}: {} fragments announced, {} bytes left", p + 1, count,
                                   r.remaining()));
    // Without on_pass the fragments are only checked: nothing is kept.
    Fragment scratch;
    pass.fragments.resize(on_pass ? size_t(count) : 0);
    for (uint64_t i = 0; i < count; ++i) {
      const size_t at = r.offset();
      const uint8_t* rec = r.take(kTraceFragmentBytes, "a fragment");
      Fragment& f = on_pass ? pass.fragments[i] : scratch;
      if (!decode_fragment(rec, t.width, t.height, t.depth_bits, t.coverage_samples, f)) {
        std::string why;  // again, for the message (off the per-fragment path)
        decode_fragment(rec, t.width, t.height, t.depth_bits, t.coverage_samples, f, &why);
        r.fail(at, why);
      }
    }
    if (on_pass) on_pass(pass);
  }
  const std::vector<FrameOp> final_ops = get_ops(r, "after the last pass", op_kinds);
  if (r.remaining() != 0) r.fail(r.offset(), fmt::format("{} bytes after the last pass", r.remaining()));
  if (on_final) on_final(final_ops);
}

Trace parse_trace(std::string_view bytes, const std::string& name) {
  Trace t;
  scan_trace(
      bytes, name, [&t](const Trace& header) { t = header; },
      [&t](TracePass& p) { t.passes.push_back(std::move(p)); },
      [&t](const std::vector<FrameOp>& ops) { t.final_ops = ops; });
  return t;
}

Trace read_trace(const std::string& path) {
  std::error_code ec;
  // An ifstream opens a directory and then reads nothing: say what it is.
  if (std::filesystem::is_directory(path, ec)) throw TraceError(fmt::format("trace '{}': is a directory", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TraceError(fmt::format("trace '{}': cannot open: {}", path, std::strerror(errno)));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw TraceError(fmt::format("trace '{}': cannot read: {}", path, std::strerror(errno)));
  return parse_trace(bytes.str(), path);
}

std::vector<PassStats> replay_trace(const Trace& trace, Backend& backend) {
  backend.begin_frame(trace.width, trace.height, trace.depth_bits, trace.clear_color,
                      trace.coverage_samples, trace.wboit);
  std::vector<PassStats> stats;
  for (const TracePass& p : trace.passes) {
    for (const FrameOp& op : p.frame_ops) backend.frame_op(op);
    backend.label_pass(p.name);
    backend.begin_pass(p.state);
    backend.draw(p.fragments);
    stats.push_back(backend.end_pass());
  }
  for (const FrameOp& op : trace.final_ops) backend.frame_op(op);
  backend.finish_frame(stats);  // a backend that defers passes (RTL, kTile) runs them here
  return stats;
}

}  // namespace zb
