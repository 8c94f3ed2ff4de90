// zblend's ROP as a TLM-2.0 block for virtual platforms (docs/systemc.md "ZbRopTlm"): a register
// map behind a target socket, a DMA initiator socket that fetches the command and fragment stream
// and stores tiles to a framebuffer in memory (DMI where granted), loosely timed with a quantum
// keeper. Inside, the golden model timed by the cost model or the Verilated zb_rop.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "rop/backend.h"
#include "zb_rop_inside.h"
#include "zb_rop_regs.h"
#include "zb_tlm_dma.h"

namespace zb::vp {

struct RopTlmOptions {
  InsideKind inside = InsideKind::kGolden;
  sc_core::sc_time clock{10, sc_core::SC_NS};  // the ROP's clock: a cycle of the inside
  bool dmi = true;            // use DMI where the memory grants it
  uint32_t burst = 4096;      // bytes a DMA b_transport moves at most
};

// What the ROP did, for reports and tests (not on the bus: the counters are registers too).
struct RopTlmTotals {
  uint64_t passes = 0, cycles = 0;  // cycles: the inside's, summed over commands
  sc_core::sc_time compute;         // cycles times the clock
  uint64_t dma_bytes = 0, dma_transactions = 0, dmi_accesses = 0, dmi_grants = 0,
           dmi_invalidations = 0, commands = 0;
};

class ZbRopTlm : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<ZbRopTlm> regs;
  tlm_utils::simple_initiator_socket<ZbRopTlm> dma;
  sc_core::sc_out<bool> irq_o;  // STATUS done or error, until written back

  ZbRopTlm(sc_core::sc_module_name name, const RopTlmOptions& options = {});
  ~ZbRopTlm() override;

  const Framebuffer& framebuffer() const { return inside_->backend().framebuffer(); }
  RopTlmTotals totals() const;
  const std::string& last_error() const { return error_text_; }  // the last error's detail

 private:
  // A command that cannot go on: its code, the detail for last_error() and kErrorInfo.
  struct CommandError {
    ErrorCode code;
    std::string text;
    uint32_t info = 0;
  };
  class StreamBytes;
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  unsigned transport_dbg(tlm::tlm_generic_payload& tx);
  void invalidate_dmi(sc_dt::uint64 start, sc_dt::uint64 end);
  bool read_reg(uint64_t addr, uint32_t& value) const;
  enum class Write { kOk, kReadOnly, kSideEffect };
  Write write_reg(uint64_t addr, uint32_t value, const sc_core::sc_time& delay, bool debug);
  void set_status(uint32_t status);
  void drive_irq();

  void run();  // SC_THREAD: one command at a time
  void execute(Command c);
  void begin_frame(int width, int height, int depth_bits, int samples, const WboitFormat& wboit,
                   Rgba8 clear);
  void begin_pass(uint16_t state);
  void end_pass();
  void frame_op(const FrameOp& op);
  void end_frame();
  // A tile's rectangle in the frame and where its rows lie in memory (the strides checked).
  struct TileRows {
    int x0 = 0, y0 = 0, w = 0, h = 0;
    struct Plane {
      uint64_t first = 0;   // row y0's first pixel; 0 for depth: DEPTH_ADDR not set
      uint32_t stride = 0;
      uint64_t row(int k) const { return first + uint64_t(k) * stride; }  // row y0 + k
    } color, depth;
  };
  TileRows tile_rows(int tx, int ty) const;
  void store_tile(int tx, int ty);
  void load_tile(int tx, int ty);
  void run_stream();
  void abandon_frame();
  std::vector<Fragment> fetch_fragments(uint64_t addr, uint64_t count);
  void count_cycles();  // the inside's cycles since the last call, into local time
  void dma_access(tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len);
  // Memory [addr, addr + len): in place where DMI covers it, else read into read_buf_; good
  // until the next wait or read.
  const uint8_t* dma_read(uint64_t addr, size_t len);

  RopTlmOptions options_;
  std::unique_ptr<RopInside> inside_;
  tlm_utils::tlm_quantumkeeper qk_;
  sc_core::sc_event kick_, irq_changed_;

  // Registers: the read-write ones as words, by offset / 4 (reg::read_write); the rest.
  std::array<uint32_t, reg::kSize / 4> rw_{};
  uint32_t rw(uint64_t at) const { return rw_[at / 4]; }
  uint64_t rw64(uint64_t lo) const { return rw(lo) | uint64_t(rw(lo + 4)) << 32; }
  uint32_t status_ = 0, command_ = 0, error_info_ = 0;
  // The open frame's passes' counters (finish_frame may fill them in: the RTL's layers groups).
  std::vector<PassStats> pass_stats_;
  uint64_t frame_cycles_ = 0;
  DmaCounts frame_dma_;  // the port's counts when the frame began
  int width_ = 0, height_ = 0, depth_bits_ = 0, samples_ = 0;  // the open frame's
  std::vector<uint8_t> read_buf_;  // dma_read's without DMI, kept for the next

  // The command sequence's state.
  bool frame_open_ = false, in_pass_ = false;
  uint64_t cycles_seen_ = 0;
  std::string error_text_;
  RopTlmTotals totals_;  // but the DMA's, which are port_'s
  DmaPort port_;
};

}  // namespace zb::vp
