#include "trace.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "geometry/geometry.h"
#include "raster/sample_coverage.h"
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

// Writes little-endian fields at a cursor into a buffer sized by serialized_size.
class Writer {
 public:
  explicit Writer(uint8_t* out) : p_(out) {}
  void bytes(const void* src, size_t n) {
    std::memcpy(p_, src, n);
    p_ += n;
  }
  void u(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) *p_++ = uint8_t(v >> (8 * i));
  }
  void fragments(const Fragment* f, size_t n) {
    for (size_t i = 0; i < n; ++i, p_ += kTraceFragmentBytes) encode_fragment(p_, f[i]);
  }
  uint8_t* at() { return p_; }
  void skip(size_t n) { p_ += n; }

 private:
  uint8_t* p_;
};

// Reads little-endian fields, with the offset of each for error messages.
class Reader {
 public:
  Reader(TraceBytes& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void fail(size_t at, const std::string& what) const {
    throw TraceError(fmt::format("trace '{}': byte {}: {}", name_, at, what), at);
  }
  size_t offset() const { return pos_; }
  size_t remaining() const { return bytes_.size() - pos_; }
  // n bytes, valid until the next call.
  const uint8_t* take(size_t n, const char* what) {
    if (remaining() < n) fail(pos_, fmt::format("truncated, expected {}", what));
    const uint8_t* p = bytes_.read(pos_, n);
    pos_ += n;
    return p;
  }
  uint64_t get(int n, const char* what) {
    const uint8_t* p = take(size_t(n), what);
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint64_t(p[i]) << (8 * i);
    return v;
  }
  std::string get_string(size_t n, const char* what) {
    const uint8_t* p = take(n, what);
    return std::string(reinterpret_cast<const char*>(p), n);
  }

 private:
  TraceBytes& bytes_;
  const std::string& name_;
  size_t pos_ = 0;
};

// A trace already in memory.
class ViewBytes final : public TraceBytes {
 public:
  explicit ViewBytes(std::string_view bytes) : bytes_(bytes) {}
  size_t size() const override { return bytes_.size(); }
  const uint8_t* read(size_t at, size_t) override {
    return reinterpret_cast<const uint8_t*>(bytes_.data() + at);
  }

 private:
  std::string_view bytes_;
};

void put_ops(Writer& w, const std::vector<FrameOp>& ops) {
  w.u(ops.size(), 4);
  for (const FrameOp& op : ops) {
    w.u(uint8_t(op.kind), 1);
    for (uint8_t c : {op.value.r, op.value.g, op.value.b, op.value.a}) w.u(c, 1);
    w.u(op.depth, 4);
  }
}

constexpr size_t kHeaderBytes = sizeof kMagic + 4 * 5 + 3 + 4 + 4;  // through the pass count
size_t ops_bytes(size_t ops) { return 4 + 9 * ops; }
// A pass's name, operations and state: what comes before its fragment count.
size_t pass_head_bytes(size_t name, size_t ops) { return 4 + name + ops_bytes(ops) + 2; }

void put_header(Writer& w, const Trace& t, size_t passes) {
  w.bytes(kMagic, sizeof kMagic);
  for (uint32_t v : {kVersion, uint32_t(t.width), uint32_t(t.height), uint32_t(t.depth_bits),
                     uint32_t(t.coverage_samples)})
    w.u(v, 4);
  for (int v : {t.wboit.acc_bits, t.wboit.rev_bits, t.wboit.weight_bits}) w.u(uint8_t(v), 1);
  for (uint8_t c : {t.clear_color.r, t.clear_color.g, t.clear_color.b, t.clear_color.a}) w.u(c, 1);
  w.u(passes, 4);
}

void put_pass_head(Writer& w, const TracePass& p) {
  w.u(p.name.size(), 4);
  w.bytes(p.name.data(), p.name.size());
  put_ops(w, p.frame_ops);
  w.u(pack_state(p.state), 2);
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

// A trace of `rs` without its passes.
Trace trace_header(const RasterizedScene& rs) {
  Trace t;
  t.width = rs.viewport.width;
  t.height = rs.viewport.height;
  t.depth_bits = rs.viewport.depth_bits;
  t.coverage_samples = rs.viewport.coverage_samples;
  t.wboit = rs.viewport.wboit;
  t.clear_color = rs.background;
  return t;
}

std::vector<FrameOp> resolve_ops(const std::vector<FrameOp>& ops, Rgba8 background) {
  std::vector<FrameOp> out;
  for (const FrameOp& op : ops) out.push_back(resolve_op(op, background));
  return out;
}

}  // namespace

Trace make_trace(const RasterizedScene& rs, const PassPlan& plan) {
  Trace t = trace_header(rs);
  for (const PassState& p : plan.passes)
    t.passes.push_back(TracePass{p.name, resolve_ops(p.frame_ops, rs.background), p.rop,
                                 pass_fragments(rs, p)});
  t.final_ops = resolve_ops(plan.final_ops, rs.background);
  return t;
}

void encode_fragment(std::string& out, const Fragment& f) {
  uint8_t rec[kTraceFragmentBytes];
  encode_fragment(rec, f);
  out.append(reinterpret_cast<const char*>(rec), sizeof rec);
}

void encode_fragment(uint8_t* rec, const Fragment& f) {
  std::memset(rec, 0, kTraceFragmentBytes);
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

size_t decode_fragments(const uint8_t* records, size_t n, int width, int height, int depth_bits,
                        int samples, Fragment* out, std::string& why) {
  for (size_t k = 0; k < n; ++k) {
    const uint8_t* rec = records + k * kTraceFragmentBytes;
    if (decode_fragment(rec, width, height, depth_bits, samples, out[k])) continue;
    decode_fragment(rec, width, height, depth_bits, samples, out[k], &why);  // again, for the message
    return k;
  }
  return n;
}

std::string serialize_trace(const Trace& t) {
  std::string out(serialized_size(t), '\0');
  serialize_trace(t, reinterpret_cast<uint8_t*>(out.data()));
  return out;
}

void serialize_trace(const Trace& t, uint8_t* out) {
  Writer w(out);
  put_header(w, t, t.passes.size());
  for (const TracePass& p : t.passes) {
    put_pass_head(w, p);
    w.u(p.fragments.size(), 8);
    w.fragments(p.fragments.data(), p.fragments.size());
  }
  put_ops(w, t.final_ops);
}

TraceCounts serialize_trace(const RasterizedScene& rs, const PassPlan& plan, uint8_t* out,
                            size_t capacity) {
  Writer w(out);
  const auto room = [&](size_t n) {
    if (size_t(w.at() - out) + n > capacity)
      throw std::logic_error(fmt::format("serialize_trace: the trace outgrows its {} bytes", capacity));
  };
  const Trace header = trace_header(rs);
  room(kHeaderBytes);
  put_header(w, header, plan.passes.size());
  TraceCounts c;
  TracePass head;
  for (const PassState& p : plan.passes) {
    head.name = p.name;
    head.frame_ops = resolve_ops(p.frame_ops, rs.background);
    head.state = p.rop;
    room(pass_head_bytes(head.name.size(), head.frame_ops.size()) + 8);
    put_pass_head(w, head);
    uint8_t* count_at = w.at();
    w.skip(8);
    uint64_t n = 0;
    feed_stored_pass(rs, p, [&](const Fragment* f, size_t k) {
      room(k * kTraceFragmentBytes);
      w.fragments(f, k);
      n += k;
    });
    Writer(count_at).u(n, 8);
    ++c.passes;
    c.fragments += n;
  }
  const std::vector<FrameOp> final_ops = resolve_ops(plan.final_ops, rs.background);
  room(ops_bytes(final_ops.size()));
  put_ops(w, final_ops);
  c.bytes = size_t(w.at() - out);
  return c;
}

size_t trace_bound(const RasterizedScene& rs, const PassPlan& plan) {
  const size_t stored = std::max(rs.fragments.size(), rs.line_fragments.size());
  size_t boxes = 0;  // a coverage pass's most: a fragment a pixel of each triangle's box
  for (const PassState& p : plan.passes)
    if (is_coverage_pass(p.rop)) {
      for (const ScreenTriangle& t : rs.triangles) boxes += coverage_box(t, rs.viewport).pixels();
      break;
    }
  size_t n = kHeaderBytes + ops_bytes(plan.final_ops.size());
  for (const PassState& p : plan.passes) {
    const size_t most = is_coverage_pass(p.rop) ? std::max(stored, boxes) : stored;
    n += pass_head_bytes(p.name.size(), p.frame_ops.size()) + 8 + most * kTraceFragmentBytes;
  }
  return n;
}

size_t serialized_size(const Trace& t) {
  size_t n = kHeaderBytes + ops_bytes(t.final_ops.size());
  for (const TracePass& p : t.passes)
    n += pass_head_bytes(p.name.size(), p.frame_ops.size()) + 8 +
         p.fragments.size() * kTraceFragmentBytes;
  return n;
}

std::string write_trace(const std::string& path, const Trace& trace) {
  return write_file_atomic(path, serialize_trace(trace));
}

void scan_trace(std::string_view bytes, const std::string& name, const TraceScan& scan) {
  ViewBytes view(bytes);
  scan_trace(view, name, scan);
}

void scan_trace(TraceBytes& bytes, const std::string& name, const TraceScan& scan) {
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
  if (scan.header) scan.header(t);
  TracePass pass;  // a pass's head: its fragments go to scan.fragments
  std::vector<Fragment> block(kTraceReadRecords);
  std::string why;
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
    if (scan.pass) scan.pass(pass, count);
    for (uint64_t i = 0; i < count;) {
      const size_t n = size_t(std::min<uint64_t>(count - i, kTraceReadRecords));
      const size_t at = r.offset();
      const uint8_t* records = r.take(n * kTraceFragmentBytes, "a fragment");
      const size_t good = decode_fragments(records, n, t.width, t.height, t.depth_bits,
                                           t.coverage_samples, block.data(), why);
      if (good < n) r.fail(at + good * kTraceFragmentBytes, why);
      if (scan.fragments) scan.fragments(block.data(), n);
      i += n;
    }
    if (scan.pass_end) scan.pass_end();
  }
  const std::vector<FrameOp> final_ops = get_ops(r, "after the last pass", op_kinds);
  if (r.remaining() != 0) r.fail(r.offset(), fmt::format("{} bytes after the last pass", r.remaining()));
  if (scan.final_ops) scan.final_ops(final_ops);
}

Trace parse_trace(std::string_view bytes, const std::string& name) {
  Trace t;
  TraceScan scan;
  scan.header = [&t](const Trace& header) { t = header; };
  scan.pass = [&t](const TracePass& p, uint64_t fragments) {
    t.passes.push_back(p);
    t.passes.back().fragments.reserve(size_t(fragments));
  };
  scan.fragments = [&t](const Fragment* f, size_t n) {
    std::vector<Fragment>& v = t.passes.back().fragments;
    v.insert(v.end(), f, f + n);
  };
  scan.final_ops = [&t](const std::vector<FrameOp>& ops) { t.final_ops = ops; };
  scan_trace(bytes, name, scan);
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
