// Co-simulation: the golden model and the RTL in lock-step on the same calls. Every write the
// RTL makes is compared at its cycle with the golden model's write for that fragment
// (scoreboard.h); after every pass and frame operation every colour, depth, coverage, peel,
// accumulation and revealage bit of the frame is compared too, and the pass counters. The first mismatch stops the run
// with a report naming both sides and an FST of the cycles around it.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "rop/backend.h"
#include "rop/rop.h"
#include "rtl_params.h"
#include "rtl_rop.h"
#include "scoreboard.h"

namespace zb {

struct CosimOptions {
  RtlOptions rtl;
  std::string mismatch_fst = "out/mismatch.fst";  // waveform around the first mismatch
  uint64_t window = 24;                            // cycles before and after the touching fragments
  bool lockstep = true;  // every write at its cycle (off: the end-of-pass comparison alone)
};

// Thrown at the first mismatch; what() is the whole multi-line report.
class MismatchError : public std::runtime_error {
 public:
  MismatchError(const std::string& report, int x, int y, std::string fst)
      : std::runtime_error(report), x_(x), y_(y), fst_(std::move(fst)) {}
  int x() const { return x_; }  // -1 when a counter, not a pixel, differed
  int y() const { return y_; }
  const std::string& fst_path() const { return fst_; }

 private:
  int x_, y_;
  std::string fst_;
};

class Cosim final : public Backend {
 public:
  explicit Cosim(CosimOptions options = {});
  const char* name() const override { return "both"; }
  using Backend::begin_frame;
  // The suites' frames: at the RTL's coverage sample count (a parameter set may change it).
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color) {
    begin_frame(width, height, depth_bits, clear_color, kRtlCoverageSamples, WboitFormat{});
  }
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                   int coverage_samples, const WboitFormat& wboit) override;
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  // Compares the frames and counters; returns the RTL's stats (with cycles). Under the tile
  // schedule the RTL runs the pass with its group (frame_op, finish_frame): zeros here.
  PassStats end_pass() override;
  // Runs the group waiting on the RTL, if any, compared; then applies the frame operation on
  // both sides and compares every plane after it.
  void frame_op(const FrameOp& op) override;
  void finish_frame(std::vector<PassStats>& stats) override;
  const Framebuffer& framebuffer() const override { return rtl_.framebuffer(); }

  void label_pass(const std::string& name) override { next_pass_name_ = name; }

  const GoldenRop& golden() const { return golden_; }
  const RtlRop& rtl() const { return rtl_; }
  uint64_t pixels_compared() const { return pixels_compared_; }
  uint64_t fragments() const { return fragments_; }
  uint64_t mismatches() const { return mismatches_; }  // mismatching pixels (only the failing pass)
  uint64_t passes() const { return passes_; }
  // A warning when this run compared nothing, else empty.
  std::string nothing_checked_warning() const;

 private:
  [[noreturn]] void report_pixel(int x, int y, size_t differing);
  [[noreturn]] void report_divergence(const Divergence& d);
  const TileRun* tile_run(int x, int y) const;  // the last pass's run of the tile of (x, y)
  // The pass's fragments at (x, y) up to fragment `last`, oldest first, each with what both
  // sides wrote; widens [lo, hi] to their accept cycles.
  std::string pixel_history(int x, int y, uint64_t& lo, uint64_t& hi, size_t limit,
                            size_t last = SIZE_MAX) const;
  // The pass's fragments at (x, y) up to fragment `last`: a marker at each accept (waves.h).
  std::vector<WaveMarker> accept_markers(int x, int y, size_t last = SIZE_MAX) const;
  // Replays `run`'s tile with an FST of the cycles [lo, hi] and opt_.window around them (the
  // whole tile when lo > hi) and a save file showing `view` there: the report's waveform
  // lines; `fst` names the FST written. The run's own FST (a trace) gets the view too.
  std::string waveform(int x, int y, const TileRun& run, uint64_t lo, uint64_t hi,
                       WaveView view, std::string& fst);
  // Compares every plane of the two frames; throws MismatchError on the first difference.
  void compare_frames();
  // The RTL's group (tile schedule) run and compared: writes, frames, each pass's counters.
  void run_group();
  // After the RTL ran the group: its frames and each pass's counters.
  void check_group(const std::vector<PassStats>& rtl);
  [[noreturn]] void report_counters(const PassStats& rtl, const PassStats& golden, size_t k);
  // "frame F pass P "name"": the group's pass k, or (k = npos) the whole group.
  std::string pass_label(size_t k = std::string::npos) const;
  void at_pass(size_t k) { state_ = group_[k].state; }  // the reports' state line

  Scoreboard scoreboard_;
  CosimOptions opt_;
  GoldenRop golden_;
  RtlRop rtl_;
  Framebuffer before_;  // the frame at the start of the group (both sides agreed then)
  RopState state_;
  // The passes the RTL runs together (one but under the tile schedule), in order.
  struct GroupPass {
    RopState state;
    std::string name;
    uint64_t in_frame = 0;  // its number in the frame, from 1
    PassStats golden;
  };
  std::vector<GroupPass> group_;
  std::string next_pass_name_, op_name_;
  uint64_t pass_in_frame_ = 0, frame_no_ = 0;
  uint64_t pixels_compared_ = 0, fragments_ = 0, mismatches_ = 0, passes_ = 0;
};

}  // namespace zb
