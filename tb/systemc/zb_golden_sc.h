// The golden model (cmodel/rop/rop.h) as a SystemC module, timed like zb_rop: docs/systemc.md.
#pragma once

#include <cstdint>
#include <vector>

#include <systemc>

#include "rop/rop.h"
#include "rtl_timing.h"
#include "tile_bins.h"
#include "tile_io.h"
#include "zb_sc_types.h"

namespace zb::sc {

class ZbGoldenSc : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i;
  sc_core::sc_fifo_in<PassCommand> cmd_i;
  sc_core::sc_fifo_in<Fragment> frag_i;
  sc_core::sc_fifo_out<PassStats> stats_o;

  explicit ZbGoldenSc(sc_core::sc_module_name name);

  const Framebuffer& framebuffer() const { return rop_.framebuffer(); }
  // Clock cycles spent in passes (stream cycles by zb_rop's issue rule, tile cycles by the
  // driver's tile traffic, tb/rtlmodel/tile_io.h), and the simulated time they took: from the
  // first rising edge of each pass to its PassStats.
  uint64_t busy_cycles() const { return busy_cycles_; }
  uint64_t tile_io_cycles() const { return io_cycles_; }
  sc_core::sc_time busy_time() const { return busy_time_; }
  // The last pass's fragments, in the order they arrived (render()'s pass order).
  const std::vector<Fragment>& pass_fragments() const { return frags_; }

 private:
  void run();
  PassStats run_pass();
  void wait_cycles(uint64_t n);

  GoldenRop rop_;
  TileStates tiles_;
  RopState state_;
  std::vector<Fragment> frags_;
  TileBins bins_;
  IssueSchedule schedule_;        // zb_rop's issue window
  std::vector<uint64_t> issue_;   // its issue cycles
  std::vector<uint32_t> order_;   // its fragments in issue order
  uint64_t busy_cycles_ = 0, io_cycles_ = 0;
  sc_core::sc_time busy_time_;
};

}  // namespace zb::sc
