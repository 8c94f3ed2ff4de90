// What the RTL driver checks beside the monitor's lock-step comparison: the port's refusals and
// drain, each tile's stream against the issue schedule (rtl_timing.h, the cost model's source),
// and the RTL's counters against what the driver drove. A failed check throws a one-line
// message naming the tile; tests grep some of them, so their wording is fixed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "rtl_params.h"
#include "rtl_rop.h"
#include "rtl_timing.h"
#include "tile_bins.h"
#include "tile_io.h"

namespace zb {

// The driver's one way to fail: std::runtime_error for the RTL breaking its contract,
// std::invalid_argument or std::logic_error for a caller's mistake.
template <class E = std::runtime_error, class... A>
[[noreturn]] void fail(fmt::format_string<A...> format, A&&... args) {
  throw E(fmt::format(format, std::forward<A>(args)...));
}

constexpr uint64_t kDrainLimit = 1000;  // cycles busy_o (or frag_ready_o low) may last

// frag_ready_o must be low in a cycle with stall_i, tile_req_i or tile_clear_i (docs/rtl.md
// "Port timing"); the driver offers nothing then, so only this sees a port that would take one.
[[noreturn]] void fail_ready(int x0, int y0, uint64_t cycle, const char* why);
inline void check_refuses(bool ready, int x0, int y0, uint64_t cycle, const char* why) {
  if (ready) fail_ready(x0, y0, cycle, why);
}
// An offer refused for more than kDrainLimit cycles in a row, or a drain that long.
[[noreturn]] void fail_not_ready(int x0, int y0);
[[noreturn]] void fail_busy(int x0, int y0);

// Each tile's streaming cycles must be the issue schedule's: a slower or faster RTL is a defect
// too. One per model: the schedule and its buffers are reused from tile to tile.
class ScheduleCheck {
 public:
  // The stream f[0..n) of `run`'s tile. `accepted` (by Streamed::index): the accept cycles,
  // scheduled from under back-pressure; null without. `x4` (the monitor's, by position): each
  // fragment must reach X4 a fixed number of cycles after its issue; null without a monitor.
  void check(const TileRun& run, const Streamed* f, size_t n, const uint64_t* accepted,
             const std::vector<uint64_t>* x4);

 private:
  IssueSchedule schedule_{kRtlWindow, size_t(kRtlTileW) * kRtlTileH};
  std::vector<uint32_t> pixels_;
  std::vector<uint64_t> issue_, accepts_;
};

// The RTL's counters at the end of a tile's drain.
struct StreamCounters {
  uint64_t in = 0, passed = 0, killed = 0, cycles = 0, stall_cycles = 0;
};
// killed = in - passed; the cycles the driver clocked since the counter clear, and the offers
// it saw refused (cnt_stall_cycles_o's events).
void audit_stream(const TileRun& run, const StreamCounters& c, uint64_t clocked,
                  uint64_t refused_offers);
// The tile port's beat counters against the beats the driver moved.
void audit_beats(const TileRun& run, uint64_t want_loads, uint64_t want_stores);

// A stored tile read again (RtlOptions::reread_stores): beat b's words of `planes` as read now
// against the store's read; `what` names the read.
void check_reread(const TileRun& run, uint8_t planes, const BeatWords& now,
                  const BeatWords& first, size_t b, const char* what);
// Its load-back's beat counters at beat b: stores saturated at `most`, loads climbing to it.
void audit_reload(const TileRun& run, uint64_t stores, uint64_t loads, uint64_t most,
                  uint64_t want_loads, size_t b);

}  // namespace zb
