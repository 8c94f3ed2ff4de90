// One Verilated zb_rop with its context, clock and optional FST, and what the driver keeps per
// model. Which build it is (assertion, speed, injected defects, mutant netlist) is the
// library's: each zbrtl variant compiles the driver with its own define.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include <verilated.h>
#include <verilated_fst_c.h>

#include "driver_checks.h"
#include "monitor_feed.h"
#include "rtl_rop.h"
#include "waves.h"

#ifdef ZB_RTL_BUG
#include "Vzb_rop_bug.h"
#include "Vzb_rop_bug_probe.h"
#include "Vzb_rop_bug_zb_rop.h"
using VModel = Vzb_rop_bug;
using VParams = Vzb_rop_bug_zb_rop;
using VProbe = Vzb_rop_bug_probe;
#elif defined(ZB_RTL_FAST)
#include "Vzb_rop_fast.h"
#include "Vzb_rop_fast_probe.h"
#include "Vzb_rop_fast_zb_rop.h"
using VModel = Vzb_rop_fast;
using VParams = Vzb_rop_fast_zb_rop;
using VProbe = Vzb_rop_fast_probe;
#elif defined(ZB_RTL_FCOV)
#include "Vzb_rop_fcov.h"
#include "Vzb_rop_fcov_probe.h"
#include "Vzb_rop_fcov_zb_rop.h"
using VModel = Vzb_rop_fcov;
using VParams = Vzb_rop_fcov_zb_rop;
using VProbe = Vzb_rop_fcov_probe;
#elif defined(ZB_RTL_MUT)
#include "Vzb_rop_mut.h"
#include "Vzb_rop_mut_probe.h"
#include "Vzb_rop_mut_zb_rop.h"
using VModel = Vzb_rop_mut;
using VParams = Vzb_rop_mut_zb_rop;
using VProbe = Vzb_rop_mut_probe;
#else
#include "Vzb_rop.h"
#include "Vzb_rop_probe.h"
#include "Vzb_rop_zb_rop.h"
using VModel = Vzb_rop;
using VParams = Vzb_rop_zb_rop;
using VProbe = Vzb_rop_probe;
#endif

namespace zb {

class CoverageTotals;

// Makes `ctx` the thread's Verilator context, under the lock every model's making and unmaking
// takes (rop_model.cpp says why).
void use_context(VerilatedContext* ctx);

// The FST opens at the first cycle it holds (dump_from), so its time starts there; beside
// zb_rop it holds the testbench's probe (waves.h), and its save file is written when it closes.
// The model comes out of reset with every tile beat read once.
struct Sim {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<VModel> top;
  std::unique_ptr<VerilatedFstC> fst;
  std::string fst_path;
  std::unique_ptr<VProbe> probe;
  WaveProbe wave;                // the probe's inputs for the coming cycle
  WaveView view;                 // the save file's
  CoverageTotals* coverage = nullptr;
  MonitorFeed feed;              // with RtlOptions::retire_sink or an FST
  ScheduleCheck timing;
  uint64_t cycle = 0;
  uint64_t dump_from, dump_to;

  // `path`: an FST of cycles [from, to] when set.
  Sim(const std::string& path, const RtlOptions& o, CoverageTotals* totals = nullptr,
      uint64_t from = 0, uint64_t to = std::numeric_limits<uint64_t>::max());
  ~Sim();
  Sim(const Sim&) = delete;
  Sim& operator=(const Sim&) = delete;

  void idle_inputs();

  // One clock: falling edge with the inputs as set, then the rising edge that samples them.
  // The inputs must be evaluated before the rising edge: Verilator's assertions read the values
  // of the last evaluation, so inputs set after the falling edge's would reach them a cycle late.
  void tick() {
    const bool dump = fst && cycle - dump_from <= dump_to - dump_from;
    if (dump) begin_dump();
    top->clk_i = 0;
    ctx->time(wave_fall_ps(cycle));
    top->eval();
    if (dump) fst->dump(wave_fall_ps(cycle));
    top->clk_i = 1;
    ctx->time(wave_rise_ps(cycle));
    top->eval();
    if (dump) fst->dump(wave_rise_ps(cycle));
    wave.next_cycle();
    ++cycle;
  }

 private:
  void make(const std::string& path, const RtlOptions& o);
  void reset();
  void begin_dump();  // opens the FST at its first cycle, shows the probe
  void add_coverage() noexcept;
};

}  // namespace zb
