// The co-simulation's driver: one stream of pass commands and fragments into both modules
// (zb_golden_sc.h, zb_rtl_sc.h), their buffers compared bit for bit after every pass.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

#include "io/trace.h"
#include "zb_sc_types.h"

namespace zb::sc {

class ZbGoldenSc;
class ZbRtlSc;

// One trace's run (a method on a scene, or a trace file).
struct CosimResult {
  std::string name;
  uint64_t fragments = 0;
  uint64_t passes = 0;
  uint64_t mismatches = 0;        // pixels differing in any plane, summed over the compares
  std::string first_mismatch;     // the first differing pixel and both values, or a counter
  sc_core::sc_time golden_time, rtl_time;  // the modules' busy_time() over the run
  uint64_t golden_stream_cycles = 0, rtl_stream_cycles = 0;  // PassStats::cycles, summed
  uint64_t golden_tile_cycles = 0, rtl_tile_cycles = 0;      // the modules' tile_io_cycles()
  double wall_ms = 0;
};

class ZbCosimSc : public sc_core::sc_module {
 public:
  sc_core::sc_fifo_out<PassCommand> golden_cmd_o, rtl_cmd_o;
  sc_core::sc_fifo_out<Fragment> golden_frag_o, rtl_frag_o;
  sc_core::sc_fifo_in<PassStats> golden_stats_i, rtl_stats_i;

  // Runs `traces` in order on `golden` and `rtl`, then stops the simulation.
  ZbCosimSc(sc_core::sc_module_name name, std::vector<std::pair<std::string, Trace>> traces,
            const ZbGoldenSc& golden, const ZbRtlSc& rtl, sc_core::sc_time clock_period);

  const std::vector<CosimResult>& results() const { return results_; }

 private:
  void run();
  CosimResult run_trace(const std::string& name, const Trace& t);
  void send(const PassCommand& c);
  void compare(CosimResult& r, const char* where);

  std::vector<std::pair<std::string, Trace>> traces_;
  const ZbGoldenSc& golden_;
  const ZbRtlSc& rtl_;
  sc_core::sc_time period_;
  std::vector<CosimResult> results_;
};

}  // namespace zb::sc
