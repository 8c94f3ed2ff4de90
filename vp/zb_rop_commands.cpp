// ZbRopTlm's commands (docs/systemc.md "ZbRopTlm"): what each does to the inside and to memory
// once the command thread (zb_rop_tlm.cpp) has taken it from COMMAND.
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "io/trace.h"
#include "rtl_params.h"
#include "tile_io.h"
#include "zb_rop_tlm.h"

namespace zb::vp {

namespace {

// The most a DRAW buffers: the model fetches its fragments before it draws them.
constexpr uint64_t kMaxBuffer = uint64_t{256} << 20;

}  // namespace

void ZbRopTlm::begin_frame(int width, int height, int depth_bits, int samples,
                           const WboitFormat& wboit, Rgba8 clear) {
  if (width < 1 || height < 1 || width > kMaxFrameSize || height > kMaxFrameSize)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FRAME_SIZE {}x{} is out of range (1 to {})", width, height,
                                   kMaxFrameSize)};
  if (depth_bits < kMinDepthBits || depth_bits > kMaxDepthBits || !valid_coverage_samples(samples) ||
      !valid_wboit_format(wboit))
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FRAME_FORMAT {} depth bits, {} samples or WBOIT {}/{}/{} bits "
                                   "out of range (docs/datapath.md)",
                                   depth_bits, samples, wboit.acc_bits, wboit.rev_bits,
                                   wboit.weight_bits)};
  try {
    inside_->backend().begin_frame(width, height, depth_bits, clear, samples, wboit);
  } catch (const std::invalid_argument& e) {
    throw CommandError{ErrorCode::kBadSetup, e.what()};
  }
  frame_open_ = true;
  width_ = width, height_ = height, depth_bits_ = depth_bits, samples_ = samples;
  pass_stats_.clear();
  frame_cycles_ = 0;
  frame_dma_ = port_.counts();
  cycles_seen_ = inside_->cycles();
}

void ZbRopTlm::begin_pass(uint16_t bits) {
  if (!frame_open_ || in_pass_)
    throw CommandError{ErrorCode::kOrder, "BEGIN_PASS outside a frame or inside a pass"};
  RopState state;
  if (!unpack_state(bits, state))
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("PASS_STATE 0x{:04x} is not a valid pass state", bits)};
  try {
    inside_->backend().begin_pass(state);
  } catch (const std::invalid_argument& e) {
    throw CommandError{ErrorCode::kBadSetup, e.what()};
  }
  in_pass_ = true;
}

void ZbRopTlm::end_pass() {
  if (!in_pass_) throw CommandError{ErrorCode::kOrder, "END_PASS outside a pass"};
  pass_stats_.push_back(inside_->backend().end_pass());
  in_pass_ = false;
  ++totals_.passes;
  count_cycles();
}

void ZbRopTlm::frame_op(const FrameOp& op) {
  if (!frame_open_ || in_pass_)
    throw CommandError{ErrorCode::kOrder, "FRAME_OP outside a frame or inside a pass"};
  inside_->backend().frame_op(op);
  count_cycles();
}

void ZbRopTlm::end_frame() {
  if (!frame_open_ || in_pass_)
    throw CommandError{ErrorCode::kOrder, "END_FRAME outside a frame or inside a pass"};
  // A backend that runs passes later (the RTL's layers groups) counts them here.
  inside_->backend().finish_frame(pass_stats_);
  count_cycles();
  const Framebuffer& fb = framebuffer();
  for (int ty = 0; ty * kRtlTileW < fb.height; ++ty)
    for (int tx = 0; tx * kRtlTileW < fb.width; ++tx) store_tile(tx, ty);
  frame_open_ = false;
}

// The tile of (tx, ty), clipped to the frame, and its rows in memory.
ZbRopTlm::TileRows ZbRopTlm::tile_rows(int tx, int ty) const {
  TileRows t;
  t.x0 = tx * kRtlTileW, t.y0 = ty * kRtlTileW;
  t.w = std::min(kRtlTileW, width_ - t.x0), t.h = std::min(kRtlTileW, height_ - t.y0);
  if (rw(reg::kFbStride) < uint32_t(width_) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FB_STRIDE {} is less than a row of {} pixels", rw(reg::kFbStride),
                                   width_)};
  const bool depth = rw64(reg::kDepthAddrLo) != 0;
  if (depth && rw(reg::kDepthStride) < uint32_t(width_) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("DEPTH_STRIDE {} is less than a row of {} pixels",
                                   rw(reg::kDepthStride), width_)};
  const auto plane = [&](uint64_t addr, uint32_t stride) {
    return TileRows::Plane{addr + uint64_t(t.y0) * stride + uint64_t(t.x0) * 4, stride};
  };
  t.color = plane(rw64(reg::kFbAddrLo), rw(reg::kFbStride));
  if (depth) t.depth = plane(rw64(reg::kDepthAddrLo), rw(reg::kDepthStride));
  return t;
}

// The tile's colour rows to the framebuffer in memory, then its depth rows when DEPTH_ADDR is set.
void ZbRopTlm::store_tile(int tx, int ty) {
  const Framebuffer& fb = framebuffer();
  const TileRows t = tile_rows(tx, ty);
  std::vector<uint32_t> row(size_t(t.w));
  const auto store = [&](const TileRows::Plane& plane, auto word) {
    for (int k = 0; k < t.h; ++k) {
      for (int x = 0; x < t.w; ++x) row[size_t(x)] = word(t.x0 + x, t.y0 + k);
      dma_access(tlm::TLM_WRITE_COMMAND, plane.row(k), reinterpret_cast<uint8_t*>(row.data()),
                 row.size() * 4);
    }
  };
  store(t.color, [&](int x, int y) { return pack_rgba(fb.color_at(x, y)); });
  if (t.depth.first) store(t.depth, [&](int x, int y) { return fb.depth_at(x, y); });
}

// The tile's colour rows from the framebuffer in memory, and its depth rows when DEPTH_ADDR is
// set (each word within the frame's depth width); all read before the inside takes any.
void ZbRopTlm::load_tile(int tx, int ty) {
  const TileRows t = tile_rows(tx, ty);
  RegionLoad r;
  r.x0 = t.x0, r.y0 = t.y0, r.width = t.w, r.height = t.h;
  std::vector<uint32_t> words(size_t(t.w) * size_t(t.h));
  const auto load = [&](const TileRows::Plane& plane, bool depth) {
    for (int k = 0; k < t.h; ++k) {
      uint32_t* row = &words[size_t(k) * size_t(t.w)];
      dma_access(tlm::TLM_READ_COMMAND, plane.row(k), reinterpret_cast<uint8_t*>(row),
                 size_t(t.w) * 4);
      for (int x = 0; depth && x < t.w; ++x)
        if (row[x] > depth_max(depth_bits_)) {
          const uint64_t at = plane.row(k) + uint64_t(x) * 4;
          throw CommandError{ErrorCode::kBadTile,
                             fmt::format("TILE_LOAD: depth 0x{:x} at 0x{:x} exceeds the frame's {} bits",
                                         row[x], at, depth_bits_),
                             uint32_t(at)};
        }
    }
  };
  load(t.color, false);
  for (const uint32_t w : words) r.color.push_back(unpack_rgba(w));
  if (t.depth.first) {
    load(t.depth, true);
    r.depth = std::move(words);
  }
  inside_->backend().load_region(r);
  count_cycles();  // the passes a backend ran first (the RTL's waiting ones)
}

// RUN_STREAM's stream, read as the parse goes through the DMA port: in place where DMI covers
// a read, else fetched into a buffer kept from read to read.
class ZbRopTlm::StreamBytes final : public TraceBytes {
 public:
  StreamBytes(ZbRopTlm& rop, uint64_t addr, size_t size) : rop_(rop), addr_(addr), size_(size) {}
  size_t size() const override { return size_; }
  const uint8_t* read(size_t at, size_t n) override { return rop_.dma_read(addr_ + at, n); }

 private:
  ZbRopTlm& rop_;
  uint64_t addr_;
  size_t size_;
};

// The stream is run as it is read, a block of fragments at a time. A fault stops it and
// abandons the frame: what came before it ran on the inside, but no tile reaches the
// framebuffer in memory.
void ZbRopTlm::run_stream() {
  if (in_pass_) throw CommandError{ErrorCode::kOrder, "RUN_STREAM inside a pass"};
  StreamBytes bytes(*this, rw64(reg::kStreamAddrLo), rw(reg::kStreamBytes));
  TraceScan scan;
  scan.header = [this](const Trace& t) {
    begin_frame(t.width, t.height, t.depth_bits, t.coverage_samples, t.wboit, t.clear_color);
  };
  scan.pass = [this](const TracePass& p, uint64_t) {
    for (const FrameOp& op : p.frame_ops) frame_op(op);
    inside_->backend().label_pass(p.name);
    begin_pass(pack_state(p.state));
  };
  scan.fragments = [this](const Fragment* f, size_t n) { inside_->backend().draw(f, n); };
  scan.pass_end = [this] { end_pass(); };
  scan.final_ops = [this](const std::vector<FrameOp>& ops) {
    for (const FrameOp& op : ops) frame_op(op);
  };
  try {
    scan_trace(bytes, fmt::format("at 0x{:x}", rw64(reg::kStreamAddrLo)), scan);
  } catch (const TraceError& e) {
    abandon_frame();
    throw CommandError{ErrorCode::kBadStream, e.what(), uint32_t(e.byte)};
  } catch (const CommandError&) {
    abandon_frame();
    throw;
  }
  end_frame();
}

// A pass broken off is ended on the inside (its counters dropped); no tile is stored.
void ZbRopTlm::abandon_frame() {
  if (in_pass_) inside_->backend().end_pass();
  in_pass_ = false;
  frame_open_ = false;
}

const uint8_t* ZbRopTlm::dma_read(uint64_t addr, size_t len) {
  if (const uint8_t* p = port_.view(*dma.operator->(), qk_, tlm::TLM_READ_COMMAND, addr, len)) {
    port_.charge(qk_, tlm::TLM_READ_COMMAND, len);
    return p;
  }
  if (read_buf_.size() < len) read_buf_.resize(len);
  dma_access(tlm::TLM_READ_COMMAND, addr, read_buf_.data(), len);
  return read_buf_.data();
}

std::vector<Fragment> ZbRopTlm::fetch_fragments(uint64_t addr, uint64_t count) {
  if (count * kTraceFragmentBytes > kMaxBuffer)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FRAG_COUNT {} is above the model's {} MiB of fragments",
                                   count, kMaxBuffer >> 20)};
  std::vector<uint8_t> bytes(count * kTraceFragmentBytes);
  dma_access(tlm::TLM_READ_COMMAND, addr, bytes.data(), bytes.size());
  std::vector<Fragment> out(count);
  std::string why;
  const size_t good = decode_fragments(bytes.data(), count, width_, height_, depth_bits_, samples_,
                                       out.data(), why);
  if (good < count)
    throw CommandError{ErrorCode::kBadFragment, fmt::format("fragment {}: {}", good, why),
                       uint32_t(good)};
  return out;
}

void ZbRopTlm::count_cycles() {
  const uint64_t now = inside_->cycles(), n = now - cycles_seen_;
  cycles_seen_ = now;
  frame_cycles_ += n;
  totals_.cycles += n;
  totals_.compute += options_.clock * double(n);
  qk_.inc(options_.clock * double(n));
  if (qk_.need_sync()) qk_.sync();
}

}  // namespace zb::vp
