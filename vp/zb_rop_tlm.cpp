#include "zb_rop_tlm.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "geometry/geometry.h"
#include "io/trace.h"
#include "rtl_params.h"
#include "tile_io.h"

namespace zb::vp {

using sc_core::sc_time;
using tlm::tlm_generic_payload;

// A command that cannot go on: its code, the detail for last_error() and kErrorInfo.
struct ZbRopTlm::CommandError {
  ErrorCode code;
  std::string text;
  uint32_t info = 0;
};

namespace {

// The most a DRAW buffers: the model fetches its fragments before it draws them.
constexpr uint64_t kMaxBuffer = uint64_t{256} << 20;


}  // namespace

ZbRopTlm::ZbRopTlm(sc_core::sc_module_name name, const RopTlmOptions& options)
    : sc_module(name), regs("regs"), dma("dma"), irq_o("irq_o"), options_(options),
      inside_(make_inside(options.inside)), port_(options.burst, options.dmi) {
  if (options_.burst == 0) throw std::invalid_argument("ZbRopTlm: burst of 0 bytes");
  regs.register_b_transport(this, &ZbRopTlm::b_transport);
  regs.register_transport_dbg(this, &ZbRopTlm::transport_dbg);
  dma.register_invalidate_direct_mem_ptr(this, &ZbRopTlm::invalidate_dmi);
  SC_HAS_PROCESS(ZbRopTlm);
  SC_THREAD(run);
  SC_METHOD(drive_irq);
  sensitive << irq_changed_;
}

ZbRopTlm::~ZbRopTlm() = default;

// ---- The target socket: the register map ------------------------------------------------------

bool ZbRopTlm::read_reg(uint64_t a, uint32_t& v) const {
  if (reg::read_write(a)) {
    v = rw(a);
    return true;
  }
  switch (a) {
    case reg::kId: v = kIdValue; return true;
    case reg::kVersion: v = kVersionValue; return true;
    case reg::kStatus: v = status_; return true;
    case reg::kCommand: v = 0; return true;
    case reg::kTileSize: v = uint32_t(kRtlTileW); return true;
    case reg::kErrorInfo: v = error_info_; return true;
    case reg::kPasses: v = uint32_t(pass_stats_.size()); return true;
  }
  PassStats frame;  // the frame's counters: its passes' so far
  for (const PassStats& p : pass_stats_) frame += p;
  const struct { uint64_t at, value; } wide[] = {
      {reg::kFragmentsInLo, frame.fragments_in},
      {reg::kFragmentsPassedLo, frame.fragments_passed},
      {reg::kColorWritesLo, frame.color_writes},
      {reg::kCyclesLo, frame_cycles_},
      {reg::kDmaBytesLo, port_.counts().bytes - frame_dma_.bytes},
      {reg::kDmaTransactionsLo, port_.counts().transactions - frame_dma_.transactions}};
  for (const auto& w : wide) {
    if (a == w.at) { v = uint32_t(w.value); return true; }
    if (a == w.at + 4) { v = uint32_t(w.value >> 32); return true; }
  }
  return false;  // a hole in the map
}

ZbRopTlm::Write ZbRopTlm::write_reg(uint64_t a, uint32_t v, const sc_time& delay, bool debug) {
  if (reg::read_write(a)) {
    rw_[a / 4] = v;
    return Write::kOk;
  }
  if (a == reg::kStatus) {
    if (debug) return Write::kSideEffect;
    // Writing back the error bit clears its code too.
    set_status(status_ & ~(v & (status::kDone | status::kError)) &
               ~((v & status::kError) ? 0xffu << status::kCodeShift : 0u));
    return Write::kOk;
  }
  if (a == reg::kCommand) {
    if (debug) return Write::kSideEffect;
    if (status_ & status::kBusy) {  // dropped; the running command goes on
      error_text_ = fmt::format("command {} written while command {} runs", v, command_);
      error_info_ = v;
      set_status(status_ | status::kError | uint32_t(ErrorCode::kBusy) << status::kCodeShift);
      return Write::kOk;
    }
    command_ = v;
    set_status(status::kBusy);
    kick_.notify(delay);  // the command starts at the writer's local time
    return Write::kOk;
  }
  return Write::kReadOnly;
}

void ZbRopTlm::set_status(uint32_t s) {
  status_ = s;
  irq_changed_.notify(sc_core::SC_ZERO_TIME);
}

// The interrupt line has one driver, this method, whichever process changed STATUS.
void ZbRopTlm::drive_irq() { irq_o.write((status_ & (status::kDone | status::kError)) != 0); }

// Base protocol: 4-byte accesses to word addresses of the map, no byte enables, no streaming.
void ZbRopTlm::b_transport(tlm_generic_payload& tx, sc_time& delay) {
  delay += options_.clock;  // a register access takes a clock
  tx.set_dmi_allowed(false);
  const uint64_t a = tx.get_address();
  uint32_t v = 0;
  if (tx.get_byte_enable_ptr() != nullptr) {
    tx.set_response_status(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
  } else if (tx.get_data_length() != 4 || tx.get_streaming_width() < 4) {
    tx.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
  } else if (a % 4 != 0 || !read_reg(a, v)) {
    tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
  } else if (tx.is_read()) {
    std::memcpy(tx.get_data_ptr(), &v, 4);
    tx.set_response_status(tlm::TLM_OK_RESPONSE);
  } else if (tx.is_write()) {
    std::memcpy(&v, tx.get_data_ptr(), 4);
    tx.set_response_status(write_reg(a, v, delay, false) == Write::kOk
                               ? tlm::TLM_OK_RESPONSE
                               : tlm::TLM_COMMAND_ERROR_RESPONSE);
  } else {
    tx.set_response_status(tlm::TLM_OK_RESPONSE);  // TLM_IGNORE_COMMAND
  }
}

// Debug access, without side effects: reads of any words of the map (a hole reads 0), writes of
// the set-up registers; STATUS and COMMAND are not written. Returns the bytes moved: it stops at
// the first word it does not move.
unsigned ZbRopTlm::transport_dbg(tlm_generic_payload& tx) {
  const uint64_t a = tx.get_address();
  const unsigned len = tx.get_data_length();
  if (a % 4 != 0 || len % 4 != 0) return 0;
  unsigned done = 0;
  for (; done < len; done += 4) {
    const uint64_t at = a + done;
    if (at >= reg::kSize) break;
    uint32_t v = 0;
    if (tx.is_read()) {
      read_reg(at, v);
      std::memcpy(tx.get_data_ptr() + done, &v, 4);
    } else if (tx.is_write()) {
      std::memcpy(&v, tx.get_data_ptr() + done, 4);
      if (write_reg(at, v, sc_core::SC_ZERO_TIME, true) != Write::kOk) break;
    } else {
      break;
    }
  }
  return done;
}

// ---- The command thread ----------------------------------------------------------------------

void ZbRopTlm::run() {
  for (;;) {
    wait(kick_);
    qk_.reset();
    error_text_.clear();
    ++totals_.commands;
    uint32_t code = 0;
    try {
      execute(Command(command_));
    } catch (const CommandError& e) {
      code = uint32_t(e.code);
      error_text_ = e.text;
      error_info_ = e.info;
    }
    qk_.sync();  // the command's time passes before its status shows
    // A command dropped while this one ran (busy) stays reported until written back.
    const uint32_t dropped =
        status_ & status::kError ? status::kError | uint32_t(ErrorCode::kBusy) << status::kCodeShift : 0;
    set_status(code ? (status::kError | code << status::kCodeShift) : (status::kDone | dropped));
  }
}

void ZbRopTlm::execute(Command c) {
  const auto order = [this](bool ok, const char* what) {
    if (!ok) throw CommandError{ErrorCode::kOrder, what};
  };
  switch (c) {
    case Command::kBeginFrame: {
      order(!in_pass_, "BEGIN_FRAME inside a pass (END_PASS first)");
      const WboitFormat wb{int(rw(reg::kWboit) & 0xff), int(rw(reg::kWboit) >> 8 & 0xff), int(rw(reg::kWboit) >> 16 & 0xff)};
      begin_frame(int(rw(reg::kFrameSize) & 0xffff), int(rw(reg::kFrameSize) >> 16), int(rw(reg::kFrameFormat) & 0xff),
                  int(rw(reg::kFrameFormat) >> 8 & 0xff), wb, unpack_rgba(rw(reg::kClearColor)));
      return;
    }
    case Command::kBeginPass:
      if (rw(reg::kPassState) > 0xffff) throw CommandError{ErrorCode::kBadSetup, "PASS_STATE above 16 bits"};
      begin_pass(uint16_t(rw(reg::kPassState)));
      return;
    case Command::kDraw: {
      order(in_pass_, "DRAW outside a pass (BEGIN_PASS first)");
      const std::vector<Fragment> f = fetch_fragments(rw64(reg::kFragAddrLo), rw(reg::kFragCount));
      inside_->backend().draw(f.data(), f.size());
      return;
    }
    case Command::kEndPass: end_pass(); return;
    case Command::kFrameOp: {
      if (rw(reg::kOpKind) >= kFrameOpKinds)
        throw CommandError{ErrorCode::kBadSetup,
                           fmt::format("OP_KIND {} is not a frame operation (0 to {})", rw(reg::kOpKind),
                                       kFrameOpKinds - 1)};
      frame_op(FrameOp{FrameOpKind(rw(reg::kOpKind)), unpack_rgba(rw(reg::kOpColor)), rw(reg::kOpDepth), false});
      return;
    }
    case Command::kEndFrame: end_frame(); return;
    case Command::kTileStore:
    case Command::kTileLoad: {
      const bool load = c == Command::kTileLoad;
      order(frame_open_ && !in_pass_, load ? "TILE_LOAD outside a frame or inside a pass"
                                           : "TILE_STORE outside a frame or inside a pass");
      const int x = int(rw(reg::kTileOrigin) & 0xffff), y = int(rw(reg::kTileOrigin) >> 16);
      if (x % kRtlTileW || y % kRtlTileW || x >= width_ || y >= height_)
        throw CommandError{ErrorCode::kBadSetup,
                           fmt::format("TILE_ORIGIN ({}, {}) is not a tile's corner in the {}x{} "
                                       "frame (multiples of {})",
                                       x, y, width_, height_, kRtlTileW)};
      try {
        if (load) load_tile(x / kRtlTileW, y / kRtlTileW);
        else store_tile(x / kRtlTileW, y / kRtlTileW);
      } catch (const std::logic_error& e) {  // the RTL's layers passes wait for their resolve
        throw CommandError{ErrorCode::kOrder,
                           fmt::format("{}: {}", load ? "TILE_LOAD" : "TILE_STORE", e.what())};
      }
      return;
    }
    case Command::kRunStream: run_stream(); return;
  }
  throw CommandError{ErrorCode::kBadCommand, fmt::format("COMMAND {} is not a command (1 to {})",
                                                         uint32_t(c), kLastCommand)};
}

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

// The tile of (tx, ty), clipped to the frame, and the strides its rows are moved with.
ZbRopTlm::TileRows ZbRopTlm::tile_rows(int tx, int ty) const {
  TileRows t;
  t.x0 = tx * kRtlTileW, t.y0 = ty * kRtlTileW;
  t.w = std::min(kRtlTileW, width_ - t.x0), t.h = std::min(kRtlTileW, height_ - t.y0);
  t.depth = rw64(reg::kDepthAddrLo) != 0;
  if (rw(reg::kFbStride) < uint32_t(width_) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FB_STRIDE {} is less than a row of {} pixels", rw(reg::kFbStride),
                                   width_)};
  if (t.depth && rw(reg::kDepthStride) < uint32_t(width_) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("DEPTH_STRIDE {} is less than a row of {} pixels",
                                   rw(reg::kDepthStride), width_)};
  return t;
}

uint64_t ZbRopTlm::TileRows::color_at(const ZbRopTlm& r, int y) const {
  return r.rw64(reg::kFbAddrLo) + uint64_t(y) * r.rw(reg::kFbStride) + uint64_t(x0) * 4;
}
uint64_t ZbRopTlm::TileRows::depth_at(const ZbRopTlm& r, int y) const {
  return r.rw64(reg::kDepthAddrLo) + uint64_t(y) * r.rw(reg::kDepthStride) + uint64_t(x0) * 4;
}

// The tile's colour rows to the framebuffer in memory, then its depth rows when DEPTH_ADDR is set.
void ZbRopTlm::store_tile(int tx, int ty) {
  const Framebuffer& fb = framebuffer();
  const TileRows t = tile_rows(tx, ty);
  std::vector<uint8_t> row(size_t(t.w) * 4);
  for (int y = t.y0; y < t.y0 + t.h; ++y) {
    for (int x = 0; x < t.w; ++x) {
      const uint32_t c = pack_rgba(fb.color_at(t.x0 + x, y));
      std::memcpy(&row[size_t(x) * 4], &c, 4);
    }
    dma_access(tlm::TLM_WRITE_COMMAND, t.color_at(*this, y), row.data(), row.size());
  }
  if (!t.depth) return;
  for (int y = t.y0; y < t.y0 + t.h; ++y) {
    for (int x = 0; x < t.w; ++x) {
      const uint32_t d = fb.depth_at(t.x0 + x, y);
      std::memcpy(&row[size_t(x) * 4], &d, 4);
    }
    dma_access(tlm::TLM_WRITE_COMMAND, t.depth_at(*this, y), row.data(), row.size());
  }
}

// The tile's colour rows from the framebuffer in memory, and its depth rows when DEPTH_ADDR is
// set (each word within the frame's depth width); all read before the inside takes any.
void ZbRopTlm::load_tile(int tx, int ty) {
  const TileRows t = tile_rows(tx, ty);
  RegionLoad r;
  r.x0 = t.x0, r.y0 = t.y0, r.width = t.w, r.height = t.h;
  r.color.resize(size_t(t.w) * size_t(t.h));
  std::vector<uint8_t> row(size_t(t.w) * 4);
  for (int y = 0; y < t.h; ++y) {
    dma_access(tlm::TLM_READ_COMMAND, t.color_at(*this, t.y0 + y), row.data(), row.size());
    for (int x = 0; x < t.w; ++x) {
      uint32_t c;
      std::memcpy(&c, &row[size_t(x) * 4], 4);
      r.color[size_t(y) * size_t(t.w) + size_t(x)] = unpack_rgba(c);
    }
  }
  if (t.depth) {
    r.depth.resize(r.color.size());
    for (int y = 0; y < t.h; ++y) {
      dma_access(tlm::TLM_READ_COMMAND, t.depth_at(*this, t.y0 + y), row.data(), row.size());
      for (int x = 0; x < t.w; ++x) {
        uint32_t d;
        std::memcpy(&d, &row[size_t(x) * 4], 4);
        if (d > depth_max(depth_bits_)) {
          const uint64_t at = t.depth_at(*this, t.y0 + y) + uint64_t(x) * 4;
          throw CommandError{ErrorCode::kBadTile,
                             fmt::format("TILE_LOAD: depth 0x{:x} at 0x{:x} exceeds the frame's {} bits",
                                         d, at, depth_bits_),
                             uint32_t(at)};
        }
        r.depth[size_t(y) * size_t(t.w) + size_t(x)] = d;
      }
    }
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
  scan.pass = [this](TracePass& p) {
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
  for (uint64_t i = 0; i < count; ++i) {
    const uint8_t* rec = &bytes[i * kTraceFragmentBytes];
    if (decode_fragment(rec, width_, height_, depth_bits_, samples_, out[i])) continue;
    std::string why;  // again, for the message
    decode_fragment(rec, width_, height_, depth_bits_, samples_, out[i], &why);
    throw CommandError{ErrorCode::kBadFragment, fmt::format("fragment {}: {}", i, why),
                       uint32_t(i)};
  }
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

// ---- The initiator socket: DMA ---------------------------------------------------------------

void ZbRopTlm::dma_access(tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len) {
  uint64_t failed = 0;
  const tlm::tlm_response_status r = port_.access(*dma.operator->(), qk_, cmd, addr, data, len, failed);
  if (r != tlm::TLM_OK_RESPONSE)
    throw CommandError{ErrorCode::kDma,
                       fmt::format("DMA {} at 0x{:x}: {}",
                                   cmd == tlm::TLM_READ_COMMAND ? "read" : "write", failed,
                                   response_text(r)),
                       uint32_t(failed)};
}

void ZbRopTlm::invalidate_dmi(sc_dt::uint64 start, sc_dt::uint64 end) {
  port_.invalidate(start, end);
}

RopTlmTotals ZbRopTlm::totals() const {
  RopTlmTotals t = totals_;
  const DmaCounts& c = port_.counts();
  t.dma_bytes = c.bytes;
  t.dma_transactions = c.transactions;
  t.dmi_accesses = c.dmi_accesses;
  t.dmi_grants = c.dmi_grants;
  t.dmi_invalidations = c.dmi_invalidations;
  return t;
}

}  // namespace zb::vp
