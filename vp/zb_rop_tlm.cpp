#include "zb_rop_tlm.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "rtl_params.h"
#include "tile_io.h"

namespace zb::vp {

using sc_core::sc_time;
using tlm::tlm_generic_payload;

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
