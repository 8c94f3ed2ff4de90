// The example platform's host (docs/systemc.md "zblend_vp"): a CPU model that writes a frame's
// command stream into memory, programs a ROP through its registers, waits for its interrupt and
// reads the frame back, loosely timed with its own quantum keeper.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "io/trace.h"
#include "rop/fixed.h"
#include "zb_tlm_dma.h"

namespace zb::vp {

// How the host programs the ROP: the whole trace in memory and RUN_STREAM, or command by
// command through the registers (each pass's fragments in memory, DRAW).
enum class Programming { kStream, kRegisters };

struct HostJob {
  int rop = 0;                 // which ROP (its socket and interrupt)
  // The frame: a trace, or (stream programming only) a scene's fragments and a plan, whose
  // trace the host writes straight into memory as the feeder makes it.
  const Trace* trace = nullptr;
  const RasterizedScene* scene = nullptr;
  const PassPlan* plan = nullptr;
  Programming programming = Programming::kStream;
  int width() const { return trace ? trace->width : scene->viewport.width; }
  int height() const { return trace ? trace->height : scene->viewport.height; }
  // Filled in by the run:
  std::vector<Rgba8> frame;    // read back from the framebuffer in memory
  std::vector<uint32_t> depth;
  uint32_t status = 0;         // STATUS at the end
  std::string error;           // what failed, if anything
  sc_core::sc_time start, end;  // simulated time of the host's first write and of the frame read
  uint64_t rop_transactions = 0;  // register accesses
  // The ROP's counters, read from its registers after the frame.
  uint64_t passes = 0, fragments_in = 0, cycles = 0, dma_transactions = 0;
  uint64_t sent_passes = 0, sent_fragments = 0;  // what the host gave it
  double wall_ms = 0;
};

// Where the host puts things in memory: the colour framebuffer at 0, the depth plane after it,
// then the command stream (or a pass's fragments).
struct HostLayout {
  uint64_t fb = 0, depth = 0, stream = 0, bytes = 0;
};
HostLayout layout_for(const std::vector<HostJob>& jobs);

class ZbVpHost : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<ZbVpHost> mem;
  std::vector<std::unique_ptr<tlm_utils::simple_initiator_socket<ZbVpHost>>> rop;
  std::vector<std::unique_ptr<sc_core::sc_in<bool>>> irq;

  ZbVpHost(sc_core::sc_module_name name, int rops, std::vector<HostJob>& jobs, HostLayout layout);

 private:
  void run();
  void run_job(HostJob& job);
  void write_stream(HostJob& job);
  void program_registers(HostJob& job);
  uint32_t command(HostJob& job, uint32_t cmd);  // writes COMMAND, waits, returns STATUS
  void write_reg(HostJob& job, uint64_t addr, uint32_t v);
  uint32_t read_reg(HostJob& job, uint64_t addr);
  uint64_t read_reg64(HostJob& job, uint64_t lo);
  void reg_access(HostJob& job, tlm::tlm_command cmd, uint64_t addr, uint32_t& v);
  void mem_access(tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len);
  void invalidate(sc_dt::uint64 start, sc_dt::uint64 end);

  std::vector<HostJob>& jobs_;
  HostLayout layout_;
  tlm_utils::tlm_quantumkeeper qk_;
  DmaPort mem_dma_{4096, true};  // its memory traffic: DMI where granted
};

}  // namespace zb::vp
