// The lock-step scoreboard (docs/testbench.md "A mismatch"): the golden model's write log for
// every fragment of a pass, against the RTL's retire port as the monitor reports it
// (tb/rtlmodel/retire_monitor.h), and every stored tile beat against the golden frame. The first
// wrong, missing or extra write stops the run; the earliest one is kept (the tiles of a
// tile-parallel run finish out of order).
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "retire_monitor.h"
#include "rop/framebuffer.h"
#include "rop/rop.h"

namespace zb {

// The first divergence: where, when, and both sides.
struct Divergence {
  bool store = false;   // a stored beat's word, not a retire
  Retire retire;        // the monitor's transaction (for a store: pixel, tile and cycle only)
  PixelWrites golden;   // what the golden model wrote for retire.fragment (retires)
  std::string what;     // one line: the plane(s), both values
};

// What the RTL retired for one fragment: per stage the cycle (tile-relative) and the writes.
struct RtlRetired {
  static constexpr uint64_t kNever = ~uint64_t{0};
  uint64_t cycle[2] = {kNever, kNever};  // X4, X11
  PixelWrites writes[2];
};

class Scoreboard final : public RetireSink {
 public:
  // A pass begins: the last pass's log and records go.
  void begin_pass();
  // The golden model's writes for the pass's next fragment.
  void expect(const PixelWrites& w) { expected_.push_back(w); }
  // Before the RTL runs the pass: `golden` is the golden frame after it (the stores' reference).
  void arm(const Framebuffer& golden);

  bool retire(const Retire& r) override;
  bool store(const StoreBeat& b) override;
  const PixelWrites* expected(uint32_t fragment) const override {
    return fragment < expected_.size() ? &expected_[fragment] : nullptr;
  }

  const std::optional<Divergence>& first() const { return first_; }
  const std::vector<PixelWrites>& expected() const { return expected_; }
  const std::vector<RtlRetired>& rtl() const { return rtl_; }

 private:
  bool diverge(Divergence d);

  std::vector<PixelWrites> expected_;
  std::vector<RtlRetired> rtl_;  // per fragment; each tile's model writes its own fragments
  const Framebuffer* golden_ = nullptr;
  std::mutex mutex_;             // first_
  std::optional<Divergence> first_;
};

// "depth 0x00abcd", "no depth", "no colour, accumulation acc(..) reveal n", ... for one
// stage's writes.
std::string describe_writes(RetireStage stage, const PixelWrites& w, int depth_bits);

}  // namespace zb
