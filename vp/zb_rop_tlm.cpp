#include "zb_rop_tlm.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "geometry/geometry.h"
#include "io/trace.h"
#include "rtl_params.h"
#include "zb_tlm_payload.h"

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

constexpr uint32_t kBusBytes = 8;  // DMA beats: a DMI access is timed as a burst of them
// The most a command buffers (a stream, a DRAW's fragments): the model fetches before it runs.
constexpr uint64_t kMaxBuffer = uint64_t{256} << 20;

uint32_t word_of(Rgba8 c) { return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24; }
Rgba8 rgba_of(uint32_t w) { return {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)}; }

}  // namespace

ZbRopTlm::ZbRopTlm(sc_core::sc_module_name name, const RopTlmOptions& options)
    : sc_module(name), regs("regs"), dma("dma"), irq_o("irq_o"), options_(options),
      inside_(make_inside(options.inside)) {
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
  const auto lo = [](uint64_t x) { return uint32_t(x); };
  const auto hi = [](uint64_t x) { return uint32_t(x >> 32); };
  switch (a) {
    case reg::kId: v = kIdValue; return true;
    case reg::kVersion: v = kVersionValue; return true;
    case reg::kStatus: v = status_; return true;
    case reg::kCommand: v = 0; return true;
    case reg::kFrameSize: v = frame_size_; return true;
    case reg::kFrameFormat: v = frame_format_; return true;
    case reg::kWboit: v = wboit_; return true;
    case reg::kClearColor: v = clear_color_; return true;
    case reg::kPassState: v = pass_state_; return true;
    case reg::kFragAddrLo: v = lo(frag_addr_); return true;
    case reg::kFragAddrHi: v = hi(frag_addr_); return true;
    case reg::kFragCount: v = frag_count_; return true;
    case reg::kOpKind: v = op_kind_; return true;
    case reg::kOpColor: v = op_color_; return true;
    case reg::kOpDepth: v = op_depth_; return true;
    case reg::kFbAddrLo: v = lo(fb_addr_); return true;
    case reg::kFbAddrHi: v = hi(fb_addr_); return true;
    case reg::kFbStride: v = fb_stride_; return true;
    case reg::kDepthAddrLo: v = lo(depth_addr_); return true;
    case reg::kDepthAddrHi: v = hi(depth_addr_); return true;
    case reg::kDepthStride: v = depth_stride_; return true;
    case reg::kTileOrigin: v = tile_origin_; return true;
    case reg::kTileSize: v = uint32_t(kRtlTileW); return true;
    case reg::kStreamAddrLo: v = lo(stream_addr_); return true;
    case reg::kStreamAddrHi: v = hi(stream_addr_); return true;
    case reg::kStreamBytes: v = stream_bytes_; return true;
    case reg::kErrorInfo: v = error_info_; return true;
    case reg::kPasses: v = uint32_t(frame_passes_); return true;
  }
  const struct { uint64_t at, value; } wide[] = {
      {reg::kFragmentsInLo, frame_stats_.fragments_in},
      {reg::kFragmentsPassedLo, frame_stats_.fragments_passed},
      {reg::kColorWritesLo, frame_stats_.color_writes},
      {reg::kCyclesLo, frame_cycles_},
      {reg::kDmaBytesLo, frame_dma_bytes_},
      {reg::kDmaTransactionsLo, frame_dma_tx_}};
  for (const auto& w : wide) {
    if (a == w.at) { v = lo(w.value); return true; }
    if (a == w.at + 4) { v = hi(w.value); return true; }
  }
  return false;  // a hole in the map
}

ZbRopTlm::Write ZbRopTlm::write_reg(uint64_t a, uint32_t v, const sc_time& delay, bool debug) {
  const auto set_lo = [v](uint64_t& x) { x = (x & ~uint64_t{0xffffffff}) | v; };
  const auto set_hi = [v](uint64_t& x) { x = (x & 0xffffffffu) | uint64_t(v) << 32; };
  switch (a) {
    case reg::kStatus:
      if (debug) return Write::kSideEffect;
      // Writing back the error bit clears its code too.
      set_status(status_ & ~(v & (status::kDone | status::kError)) &
                 ~((v & status::kError) ? 0xffu << status::kCodeShift : 0u));
      return Write::kOk;
    case reg::kCommand:
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
    case reg::kFrameSize: frame_size_ = v; return Write::kOk;
    case reg::kFrameFormat: frame_format_ = v; return Write::kOk;
    case reg::kWboit: wboit_ = v; return Write::kOk;
    case reg::kClearColor: clear_color_ = v; return Write::kOk;
    case reg::kPassState: pass_state_ = v; return Write::kOk;
    case reg::kFragAddrLo: set_lo(frag_addr_); return Write::kOk;
    case reg::kFragAddrHi: set_hi(frag_addr_); return Write::kOk;
    case reg::kFragCount: frag_count_ = v; return Write::kOk;
    case reg::kOpKind: op_kind_ = v; return Write::kOk;
    case reg::kOpColor: op_color_ = v; return Write::kOk;
    case reg::kOpDepth: op_depth_ = v; return Write::kOk;
    case reg::kFbAddrLo: set_lo(fb_addr_); return Write::kOk;
    case reg::kFbAddrHi: set_hi(fb_addr_); return Write::kOk;
    case reg::kFbStride: fb_stride_ = v; return Write::kOk;
    case reg::kDepthAddrLo: set_lo(depth_addr_); return Write::kOk;
    case reg::kDepthAddrHi: set_hi(depth_addr_); return Write::kOk;
    case reg::kDepthStride: depth_stride_ = v; return Write::kOk;
    case reg::kTileOrigin: tile_origin_ = v; return Write::kOk;
    case reg::kStreamAddrLo: set_lo(stream_addr_); return Write::kOk;
    case reg::kStreamAddrHi: set_hi(stream_addr_); return Write::kOk;
    case reg::kStreamBytes: stream_bytes_ = v; return Write::kOk;
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
      const WboitFormat wb{int(wboit_ & 0xff), int(wboit_ >> 8 & 0xff), int(wboit_ >> 16 & 0xff)};
      begin_frame(int(frame_size_ & 0xffff), int(frame_size_ >> 16), int(frame_format_ & 0xff),
                  int(frame_format_ >> 8 & 0xff), wb, rgba_of(clear_color_));
      return;
    }
    case Command::kBeginPass:
      if (pass_state_ > 0xffff) throw CommandError{ErrorCode::kBadSetup, "PASS_STATE above 16 bits"};
      begin_pass(uint16_t(pass_state_));
      return;
    case Command::kDraw:
      order(in_pass_, "DRAW outside a pass (BEGIN_PASS first)");
      draw(fetch_fragments(frag_addr_, frag_count_));
      return;
    case Command::kEndPass: end_pass(); return;
    case Command::kFrameOp: {
      if (op_kind_ >= kFrameOpKinds)
        throw CommandError{ErrorCode::kBadSetup,
                           fmt::format("OP_KIND {} is not a frame operation (0 to {})", op_kind_,
                                       kFrameOpKinds - 1)};
      frame_op(FrameOp{FrameOpKind(op_kind_), rgba_of(op_color_), op_depth_, false});
      return;
    }
    case Command::kEndFrame: end_frame(); return;
    case Command::kTileStore: {
      order(frame_open_ && !in_pass_, "TILE_STORE outside a frame or inside a pass");
      const int x = int(tile_origin_ & 0xffff), y = int(tile_origin_ >> 16);
      if (x % kRtlTileW || y % kRtlTileW || x >= width_ || y >= height_)
        throw CommandError{ErrorCode::kBadSetup,
                           fmt::format("TILE_ORIGIN ({}, {}) is not a tile's corner in the {}x{} "
                                       "frame (multiples of {})",
                                       x, y, width_, height_, kRtlTileW)};
      try {
        store_tile(x / kRtlTileW, y / kRtlTileW);
      } catch (const std::logic_error& e) {  // the RTL's layers passes wait for their resolve
        throw CommandError{ErrorCode::kOrder, fmt::format("TILE_STORE: {}", e.what())};
      }
      return;
    }
    case Command::kRunStream: run_stream(); return;
  }
  throw CommandError{ErrorCode::kBadCommand, fmt::format("COMMAND {} is not a command (1 to 8)",
                                                         uint32_t(c))};
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
  frame_stats_ = {};
  pass_stats_.clear();
  frame_passes_ = frame_cycles_ = frame_dma_bytes_ = frame_dma_tx_ = 0;
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

void ZbRopTlm::draw(const std::vector<Fragment>& fragments) {
  inside_->backend().draw(fragments.data(), fragments.size());
}

void ZbRopTlm::end_pass() {
  if (!in_pass_) throw CommandError{ErrorCode::kOrder, "END_PASS outside a pass"};
  pass_stats_.push_back(inside_->backend().end_pass());
  frame_stats_ += pass_stats_.back();
  in_pass_ = false;
  ++frame_passes_;
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
  frame_stats_ = {};
  for (const PassStats& p : pass_stats_) frame_stats_ += p;
  count_cycles();
  const Framebuffer& fb = framebuffer();
  for (int ty = 0; ty * kRtlTileW < fb.height; ++ty)
    for (int tx = 0; tx * kRtlTileW < fb.width; ++tx) store_tile(tx, ty);
  frame_open_ = false;
}

// The tile's colour rows to the framebuffer in memory, then its depth rows when DEPTH_ADDR is set.
void ZbRopTlm::store_tile(int tx, int ty) {
  const Framebuffer& fb = framebuffer();
  const int x0 = tx * kRtlTileW, y0 = ty * kRtlTileW;
  const int w = std::min(kRtlTileW, fb.width - x0), h = std::min(kRtlTileW, fb.height - y0);
  if (fb_stride_ < uint32_t(fb.width) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("FB_STRIDE {} is less than a row of {} pixels", fb_stride_,
                                   fb.width)};
  if (depth_addr_ != 0 && depth_stride_ < uint32_t(fb.width) * 4)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("DEPTH_STRIDE {} is less than a row of {} pixels",
                                   depth_stride_, fb.width)};
  std::vector<uint8_t> row(size_t(w) * 4);
  for (int y = y0; y < y0 + h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint32_t c = word_of(fb.color_at(x0 + x, y));
      std::memcpy(&row[size_t(x) * 4], &c, 4);
    }
    dma_access(tlm::TLM_WRITE_COMMAND, fb_addr_ + uint64_t(y) * fb_stride_ + uint64_t(x0) * 4,
               row.data(), row.size());
  }
  if (depth_addr_ == 0) return;
  for (int y = y0; y < y0 + h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint32_t d = fb.depth_at(x0 + x, y);
      std::memcpy(&row[size_t(x) * 4], &d, 4);
    }
    dma_access(tlm::TLM_WRITE_COMMAND, depth_addr_ + uint64_t(y) * depth_stride_ + uint64_t(x0) * 4,
               row.data(), row.size());
  }
}

// A whole frame from the trace in memory, through the same steps as the registers' commands.
void ZbRopTlm::run_stream() {
  if (in_pass_) throw CommandError{ErrorCode::kOrder, "RUN_STREAM inside a pass"};
  if (stream_bytes_ > kMaxBuffer)
    throw CommandError{ErrorCode::kBadSetup,
                       fmt::format("STREAM_BYTES {} is above the model's {} MiB", stream_bytes_,
                                   kMaxBuffer >> 20)};
  // Fetched whole into a buffer kept from frame to frame: a DMI pointer may be taken back
  // while the frame runs, so the stream is never read in place.
  if (stream_cap_ < stream_bytes_) {
    stream_buf_.reset(new uint8_t[stream_bytes_]);  // not zeroed: the fetch fills it
    stream_cap_ = stream_bytes_;
  }
  dma_access(tlm::TLM_READ_COMMAND, stream_addr_, stream_buf_.get(), stream_bytes_);
  const std::string_view bytes(reinterpret_cast<const char*>(stream_buf_.get()), stream_bytes_);
  // The whole stream is checked first (a malformed one runs nothing), then run pass by pass:
  // the model holds one pass's fragments at a time.
  const std::string name = fmt::format("at 0x{:x}", stream_addr_);
  try {
    scan_trace(bytes, name, {}, {}, {});
  } catch (const TraceError& e) {
    throw CommandError{ErrorCode::kBadStream, e.what(), uint32_t(e.byte)};
  }
  scan_trace(
      bytes, name,
      [this](const Trace& t) {
        begin_frame(t.width, t.height, t.depth_bits, t.coverage_samples, t.wboit, t.clear_color);
      },
      [this](TracePass& p) {
        for (const FrameOp& op : p.frame_ops) frame_op(op);
        inside_->backend().label_pass(p.name);
        begin_pass(pack_state(p.state));
        draw(p.fragments);
        end_pass();
      },
      [this](const std::vector<FrameOp>& ops) {
        for (const FrameOp& op : ops) frame_op(op);
      });
  end_frame();
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
    std::string why;
    if (!decode_fragment(&bytes[i * kTraceFragmentBytes], width_, height_, depth_bits_, samples_,
                         out[i], &why))
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

bool ZbRopTlm::dmi_covers(tlm::tlm_command cmd, uint64_t addr, size_t len) const {
  if (!dmi_valid_ || addr < dmi_.get_start_address() || addr + len - 1 > dmi_.get_end_address())
    return false;
  return cmd == tlm::TLM_READ_COMMAND ? dmi_.is_read_allowed() : dmi_.is_write_allowed();
}

void ZbRopTlm::dma_access(tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len) {
  const bool read = cmd == tlm::TLM_READ_COMMAND;
  while (len > 0) {
    if (options_.dmi && dmi_covers(cmd, addr, len)) {
      uint8_t* p = dmi_.get_dmi_ptr() + (addr - dmi_.get_start_address());
      if (read) std::memcpy(data, p, len);
      else std::memcpy(p, data, len);
      const uint64_t beats = (len + kBusBytes - 1) / kBusBytes;
      qk_.inc((read ? dmi_.get_read_latency() : dmi_.get_write_latency()) * double(beats));
      ++totals_.dmi_accesses;
      totals_.dma_bytes += len;
      frame_dma_bytes_ += len;
      if (qk_.need_sync()) qk_.sync();
      return;
    }
    const size_t n = std::min<size_t>(len, options_.burst);
    tlm::tlm_generic_payload tx;
    set_payload(tx, cmd, addr, data, n);
    sc_time delay = qk_.get_local_time();
    dma->b_transport(tx, delay);
    qk_.set(delay);
    ++totals_.dma_transactions;
    ++frame_dma_tx_;
    if (tx.is_response_error())
      throw CommandError{ErrorCode::kDma,
                         fmt::format("DMA {} of {} bytes at 0x{:x}: {}", read ? "read" : "write",
                                     n, addr, tx.get_response_string()),
                         uint32_t(addr)};
    totals_.dma_bytes += n;
    frame_dma_bytes_ += n;
    if (options_.dmi && tx.is_dmi_allowed() && !dmi_covers(cmd, addr, 1)) {
      tlm::tlm_dmi d;
      tlm_generic_payload req;
      req.set_command(cmd);
      req.set_address(addr);
      if (dma->get_direct_mem_ptr(req, d)) {
        dmi_ = d;
        dmi_valid_ = true;
        ++totals_.dmi_grants;
      }
    }
    if (qk_.need_sync()) qk_.sync();
    addr += n;
    data += n;
    len -= n;
  }
}

void ZbRopTlm::invalidate_dmi(sc_dt::uint64 start, sc_dt::uint64 end) {
  if (dmi_valid_ && start <= dmi_.get_end_address() && end >= dmi_.get_start_address()) {
    dmi_valid_ = false;
    ++totals_.dmi_invalidations;
  }
}

}  // namespace zb::vp
