#include "zb_vp_host.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <fmt/core.h>

#include "tile_io.h"
#include "zb_rop_regs.h"
#include "zb_tlm_dma.h"

namespace zb::vp {

using sc_core::sc_time;

namespace {

constexpr uint64_t kAlign = 1u << 20;
uint64_t align_up(uint64_t n) { return (n + kAlign - 1) / kAlign * kAlign; }

// The memory the job's stream or a pass's fragments take at most.
uint64_t stream_bytes(const HostJob& j) {
  if (!j.trace) return trace_bound(*j.scene, *j.plan);
  if (j.programming == Programming::kStream) return serialized_size(*j.trace);
  uint64_t most = 0;
  for (const TracePass& p : j.trace->passes) most = std::max<uint64_t>(most, p.fragments.size());
  return most * kTraceFragmentBytes;
}

}  // namespace

HostLayout layout_for(const std::vector<HostJob>& jobs) {
  uint64_t pixels = 1, stream = 1;
  for (const HostJob& j : jobs) {
    pixels = std::max<uint64_t>(pixels, uint64_t(j.width()) * uint64_t(j.height()));
    stream = std::max(stream, stream_bytes(j));
  }
  HostLayout l;
  l.fb = 0;
  l.depth = align_up(pixels * 4);
  l.stream = l.depth + align_up(pixels * 4);
  l.bytes = l.stream + align_up(stream);
  return l;
}

ZbVpHost::ZbVpHost(sc_core::sc_module_name name, int rops, std::vector<HostJob>& jobs,
                   HostLayout layout)
    : sc_module(name), mem("mem"), jobs_(jobs), layout_(layout) {
  for (int i = 0; i < rops; ++i) {
    rop.push_back(std::make_unique<tlm_utils::simple_initiator_socket<ZbVpHost>>(
        fmt::format("rop{}", i).c_str()));
    irq.push_back(std::make_unique<sc_core::sc_in<bool>>(fmt::format("irq{}", i).c_str()));
  }
  mem.register_invalidate_direct_mem_ptr(this, &ZbVpHost::invalidate);
  SC_HAS_PROCESS(ZbVpHost);
  SC_THREAD(run);
}

void ZbVpHost::invalidate(sc_dt::uint64 start, sc_dt::uint64 end) { mem_dma_.invalidate(start, end); }

void ZbVpHost::run() {
  for (HostJob& job : jobs_) run_job(job);
  qk_.sync();
  sc_core::sc_stop();
}

void ZbVpHost::run_job(HostJob& job) {
  const auto wall = std::chrono::steady_clock::now();
  qk_.sync();
  job.start = sc_core::sc_time_stamp();
  write_reg(job, reg::kFbAddrLo, uint32_t(layout_.fb));
  write_reg(job, reg::kFbAddrHi, uint32_t(layout_.fb >> 32));
  write_reg(job, reg::kFbStride, uint32_t(job.width()) * 4);
  write_reg(job, reg::kDepthAddrLo, uint32_t(layout_.depth));
  write_reg(job, reg::kDepthAddrHi, uint32_t(layout_.depth >> 32));
  write_reg(job, reg::kDepthStride, uint32_t(job.width()) * 4);
  if (job.trace) {  // a scene's stream is counted as it is written
    job.sent_passes = job.trace->passes.size();
    for (const TracePass& p : job.trace->passes) job.sent_fragments += p.fragments.size();
  }
  if (job.programming == Programming::kStream)
    write_stream(job);
  else
    program_registers(job);
  const size_t n = size_t(job.width()) * size_t(job.height());
  job.passes = read_reg(job, reg::kPasses);
  job.fragments_in = read_reg64(job, reg::kFragmentsInLo);
  job.cycles = read_reg64(job, reg::kCyclesLo);
  job.dma_transactions = read_reg64(job, reg::kDmaTransactionsLo);
  if (job.error.empty()) {
    job.frame.resize(n);
    job.depth.resize(n);
    mem_access(tlm::TLM_READ_COMMAND, layout_.fb, reinterpret_cast<uint8_t*>(job.frame.data()), n * 4);
    mem_access(tlm::TLM_READ_COMMAND, layout_.depth, reinterpret_cast<uint8_t*>(job.depth.data()),
               n * 4);
  }
  qk_.sync();
  job.end = sc_core::sc_time_stamp();
  job.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall).count();
}

// The trace into memory, in place where the memory grants DMI (else made here and written in
// bursts), then RUN_STREAM.
void ZbVpHost::write_stream(HostJob& job) {
  const size_t room = layout_.bytes - layout_.stream;  // the stream's region (layout_for)
  uint8_t* at = mem_dma_.view(*mem.operator->(), qk_, tlm::TLM_WRITE_COMMAND, layout_.stream, room);
  std::unique_ptr<uint8_t[]> own;  // not zeroed: only what is written is touched
  if (!at) {
    own.reset(new uint8_t[room]);
    at = own.get();
  }
  size_t bytes;
  if (job.trace) {
    serialize_trace(*job.trace, at);
    bytes = serialized_size(*job.trace);
  } else {
    const TraceCounts c = serialize_trace(*job.scene, *job.plan, at, room);
    bytes = c.bytes;
    job.sent_passes = c.passes;
    job.sent_fragments = c.fragments;
  }
  if (own) mem_access(tlm::TLM_WRITE_COMMAND, layout_.stream, at, bytes);
  else mem_dma_.charge(qk_, tlm::TLM_WRITE_COMMAND, bytes);
  if (bytes > UINT32_MAX) {
    job.error = fmt::format("the stream's {} bytes do not fit STREAM_BYTES (32 bits): a smaller "
                            "frame, or --programming registers", bytes);
    return;
  }
  write_reg(job, reg::kStreamAddrLo, uint32_t(layout_.stream));
  write_reg(job, reg::kStreamAddrHi, uint32_t(layout_.stream >> 32));
  write_reg(job, reg::kStreamBytes, uint32_t(bytes));
  command(job, uint32_t(Command::kRunStream));
}

// The frame command by command: the same steps RUN_STREAM takes from the trace.
void ZbVpHost::program_registers(HostJob& job) {
  const Trace& t = *job.trace;
  const auto op = [&](const FrameOp& o) {
    write_reg(job, reg::kOpKind, uint32_t(o.kind));
    write_reg(job, reg::kOpColor, pack_rgba(o.value));
    write_reg(job, reg::kOpDepth, o.depth);
    return command(job, uint32_t(Command::kFrameOp));
  };
  write_reg(job, reg::kFrameSize, uint32_t(t.width) | uint32_t(t.height) << 16);
  write_reg(job, reg::kFrameFormat, uint32_t(t.depth_bits) | uint32_t(t.coverage_samples) << 8);
  write_reg(job, reg::kWboit, uint32_t(t.wboit.acc_bits) | uint32_t(t.wboit.rev_bits) << 8 |
                                  uint32_t(t.wboit.weight_bits) << 16);
  write_reg(job, reg::kClearColor, pack_rgba(t.clear_color));
  if (command(job, uint32_t(Command::kBeginFrame)) & status::kError) return;
  for (const TracePass& p : t.passes) {
    for (const FrameOp& o : p.frame_ops)
      if (op(o) & status::kError) return;
    write_reg(job, reg::kPassState, pack_state(p.state));
    if (command(job, uint32_t(Command::kBeginPass)) & status::kError) return;
    std::string bytes;
    bytes.reserve(p.fragments.size() * kTraceFragmentBytes);
    for (const Fragment& f : p.fragments) encode_fragment(bytes, f);
    mem_access(tlm::TLM_WRITE_COMMAND, layout_.stream, reinterpret_cast<uint8_t*>(bytes.data()),
               bytes.size());
    write_reg(job, reg::kFragAddrLo, uint32_t(layout_.stream));
    write_reg(job, reg::kFragAddrHi, uint32_t(layout_.stream >> 32));
    if (p.fragments.size() > UINT32_MAX) {
      job.error = fmt::format("pass '{}': {} fragments do not fit FRAG_COUNT (32 bits)", p.name,
                              p.fragments.size());
      return;
    }
    write_reg(job, reg::kFragCount, uint32_t(p.fragments.size()));
    if (command(job, uint32_t(Command::kDraw)) & status::kError) return;
    if (command(job, uint32_t(Command::kEndPass)) & status::kError) return;
  }
  for (const FrameOp& o : t.final_ops)
    if (op(o) & status::kError) return;
  command(job, uint32_t(Command::kEndFrame));
}

// Writes COMMAND, waits for the interrupt, writes STATUS back; an error is recorded in the job.
uint32_t ZbVpHost::command(HostJob& job, uint32_t cmd) {
  write_reg(job, reg::kCommand, cmd);
  qk_.sync();  // the ROP runs from the host's time on
  sc_core::sc_in<bool>& line = *irq[size_t(job.rop)];
  if (!line.read()) wait(line.posedge_event());
  const uint32_t s = read_reg(job, reg::kStatus);
  job.status = s;
  if (s & status::kError) {
    job.error = fmt::format("command {}: STATUS 0x{:x} (error code {}), ERROR_INFO {}", cmd, s,
                            (s >> status::kCodeShift) & 0xff, read_reg(job, reg::kErrorInfo));
  }
  write_reg(job, reg::kStatus, status::kDone | status::kError);
  return s;
}

void ZbVpHost::write_reg(HostJob& job, uint64_t addr, uint32_t v) {
  reg_access(job, tlm::TLM_WRITE_COMMAND, addr, v);
}

uint32_t ZbVpHost::read_reg(HostJob& job, uint64_t addr) {
  uint32_t v = 0;
  reg_access(job, tlm::TLM_READ_COMMAND, addr, v);
  return v;
}

uint64_t ZbVpHost::read_reg64(HostJob& job, uint64_t lo) {
  const uint64_t low = read_reg(job, lo);
  return low | uint64_t(read_reg(job, lo + 4)) << 32;
}

void ZbVpHost::reg_access(HostJob& job, tlm::tlm_command cmd, uint64_t addr, uint32_t& v) {
  tlm::tlm_generic_payload tx;
  set_payload(tx, cmd, addr, &v, 4);
  sc_time delay = qk_.get_local_time();
  (*rop[size_t(job.rop)])->b_transport(tx, delay);
  qk_.set(delay);
  ++job.rop_transactions;
  if (tx.is_response_error())
    throw std::runtime_error(fmt::format("host: register 0x{:x}: {}", addr, tx.get_response_string()));
  if (qk_.need_sync()) qk_.sync();
}

void ZbVpHost::mem_access(tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len) {
  uint64_t failed = 0;
  const tlm::tlm_response_status r = mem_dma_.access(*mem.operator->(), qk_, cmd, addr, data, len, failed);
  if (r != tlm::TLM_OK_RESPONSE)
    throw std::runtime_error(fmt::format("host: memory at 0x{:x}: {}", failed, response_text(r)));
}

}  // namespace zb::vp
