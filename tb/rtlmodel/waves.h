// The RTL model's waveforms (docs/testbench.md "Waves"): their time, and the GTKWave save file
// written beside every FST. One clock period is 10 ns: cycle c's falling edge is at c * 10 ns,
// its rising edge (where the cycle's inputs are sampled and its writes land) at c * 10 + 5 ns.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "retire_monitor.h"

namespace zb {

constexpr uint64_t kWaveClockPs = 10000;  // the FST's unit is 1 ps
constexpr uint64_t wave_fall_ps(uint64_t cycle) { return cycle * kWaveClockPs; }
constexpr uint64_t wave_rise_ps(uint64_t cycle) { return cycle * kWaveClockPs + kWaveClockPs / 2; }
// "123455 ns": cycle's rising edge, as GTKWave shows it.
std::string wave_rise_text(uint64_t cycle);

struct WaveMarker {
  uint64_t cycle = 0;  // at its rising edge
  std::string name;
};

// What a save file shows: the cycles zoomed to, the markers (the first is the primary marker
// as well; at most 26, named A to Z), and the cycle the testbench flags as the first wrong write.
struct WaveView {
  static constexpr uint64_t kNone = std::numeric_limits<uint64_t>::max();
  uint64_t from = 0, to = kNone;  // kNone: to the end of the file
  std::vector<WaveMarker> markers;
  uint64_t mismatch = kNone;
  std::string title;
};

// The testbench's signals in a waveform (tb/rtlmodel/zb_wave_probe.sv, scope tb), as the driver sets
// them for the coming cycle: the fragment offered, and the writes landing at its rising edge.
struct WaveProbe {
  static constexpr uint32_t kNone = ~0u;
  uint32_t pass_no = 0, frag_index = kNone, frag_prim = kNone;
  bool x4_retire = false, x4_dwe = false, x4_vwe = false;
  uint32_t x4_index = kNone, x4_depth = 0, x4_cov = 0;
  bool x11_retire = false, x11_cwe = false, x11_awe = false;
  uint32_t x11_index = kNone, x11_color = 0, x11_reveal = 0;
  std::array<uint32_t, 4> x11_acc{};
  bool x11_lwe = false;
  PixelLayers x11_layers;
  bool mismatch = false;
  void retire(const Retire& r, const PixelWrites* golden);
  void next_cycle();  // after a rising edge: the retires and the flag were that cycle's
};

// The lock-step monitor's transactions into a probe, then to the run's sink when there is one
// (without, every transaction passes: a replay only shows). A transaction the sink refuses is
// the first wrong write: the probe flags it.
class ProbeSink final : public RetireSink {
 public:
  ProbeSink(RetireSink* next, WaveProbe& probe) : next_(next), probe_(probe) {}
  bool retire(const Retire& r) override;
  bool store(const StoreBeat& b) override;
  const PixelWrites* expected(uint32_t fragment) const override {
    return next_ ? next_->expected(fragment) : nullptr;
  }

 private:
  RetireSink* next_;
  WaveProbe& probe_;
};

// Writes `fst`'s save file (the same path with .gtkw): the testbench's signals, zb_rop's ports,
// then each pipeline stage's own signals in pipeline order, each a group; the markers; the
// view's cycles. The signals are the FST's (its hierarchy is read back). Returns its path;
// `gtkw`, when given, is the path instead.
std::string write_save_file(const std::string& fst, const WaveView& view, const std::string& gtkw = "");

}  // namespace zb
