// zb_rop's timing facts, the one source the cost model (app/lab/sizing_cost.h), the SystemC golden
// module (tb/systemc/) and the RTL driver's checks take them from. The RTL states the same numbers
// (zb_rop.sv: Span, Last; zb_issue_window.sv: WINDOW); tests/rtl/test_rtl_timing.cpp fails when
// the two disagree, by reading them from the Verilated model and measuring streams on it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rtl_params.h"
#include "tile_bins.h"

namespace zb {

// docs/rtl.md "Issue window". Fragments offered every cycle from a tile's first streaming cycle
// (cycle 0) reach the window two cycles after they are accepted. Each cycle the window picks its
// oldest fragment whose pixel is free: no older fragment in the window has that pixel, and the
// pick would issue at least kRtlIssueSpan cycles after the pixel's last issue. The pick issues
// (M, the plane reads) two cycles later, after the pick register K. The window takes a fragment
// in a cycle that begins with a free slot. busy_o falls kRtlDrain cycles after the last issue.
constexpr uint64_t kRtlFirstIssue = 4;  // a lone fragment: accepted 0, window 2, K 3, issued 4
constexpr uint64_t kRtlIssueSpan = 4;   // cycles between issues to one pixel
constexpr uint64_t kRtlDrain = 12;

// One touched tile of a pass for the two-buffer schedule: its fragments' pixel keys (distinct
// from every other tile's: frame pixel indices), and its cycles at the tile port before its
// stream (setup and load beats, tile_io.h) and after its drain (store beats).
struct TileStream {
  const uint32_t* pixel = nullptr;
  size_t n = 0;
  uint64_t load_cycles = 0, store_cycles = 0;
};

// A pass's cycles with two tile buffers (docs/rtl.md "A second tile buffer").
struct OverlapCycles {
  uint64_t stream = 0;  // the first fragment offered to the last tile's drain
  uint64_t total = 0;   // the first port cycle to the end of the last store (or drain)
};

// One tile's run under the tile schedule (TileSchedule::kTile) for the two-buffer timing: its
// port cycles before its first pass (every load and preload of the group, moved ahead: loads
// read the frame as it was at the group's start), the cycles its buffer is busy (per pass: the
// setup, a copy's or sweep's reads on the buffer's own memories, the stream with its fill and
// drain), and its store's port cycles.
struct ResidentRun {
  uint64_t load = 0, work = 0, store = 0;
};

// A group's cycles with two tile buffers under the tile schedule (the proposed RTL of docs/rtl.md
// "A second tile buffer"): run k works in buffer k % 2 once its load has ended and run k - 1's
// work has; the one port runs load 0, load 1, store 0, load 2, store 1, ..., each when the port
// is free, a store once its run's work has ended, a load once its buffer's run before it is
// stored. Returns the end of the last store (0 for no runs).
uint64_t two_buffer_group(const std::vector<ResidentRun>& runs);

// The issue schedule of a tile's stream, cycle for cycle as zb_rop issues it.
class IssueSchedule {
 public:
  // `window` slots (2 or more, as zb_issue_window); pixel keys below `keys` (a tile's or a frame's pixel index).
  explicit IssueSchedule(unsigned window = kRtlWindow, size_t keys = 0);

  // Schedules a stream of `n` fragments to pixels `pixel[0..n)`, offered every cycle without
  // back-pressure; writes each one's issue cycle to issue[k] when `issue` is not null. Returns
  // the stream's cycles: the last issue + kRtlDrain (0 for an empty stream).
  // With `accept`, fragment k was accepted in cycle accept[k] instead (back-pressure: valid
  // gaps and stall_i), and the window may take it from cycle accept[k] + 1: the schedule then
  // says when a stream whose accepts are known must issue.
  uint64_t run(const uint32_t* pixel, size_t n, uint64_t* issue = nullptr,
               const uint64_t* accept = nullptr);
  // The same for tile `tile` of `bins` (the driver's stream of that tile), the fragments `f` of
  // a frame `width` pixels wide; issue[k] for the tile's k-th fragment.
  uint64_t run_tile(const TileBins& bins, size_t tile, const Fragment* f, int width,
                    uint64_t* issue = nullptr);

  // A pass's touched tiles, in the driver's order, with two tile buffers: the proposed RTL of
  // docs/rtl.md "A second tile buffer", not zb_rop's yet. Tile k streams in buffer k % 2 while
  // the one tile port, in the order load 0, load 1, store 0, load 2, store 1, ..., loads the
  // next tile into the other buffer and stores the one before; a tile is stored once drained,
  // loaded once the tile before it in its buffer is stored, and offered from the cycle after its
  // load and the last fragment before it. Fragments of consecutive tiles share the window.
  OverlapCycles run_two_buffers(const std::vector<TileStream>& tiles);

 private:
  struct Entry {
    uint32_t pixel;
    uint32_t index;     // in the stream
    uint64_t earliest;  // first cycle it may be picked; kNever while an older one has its pixel
  };
  static constexpr uint64_t kNever = ~uint64_t{0};

  // The window's loop over the concatenated stream pixel[0..n): fragment `next` may be taken
  // from cycle ready(next) (kNever: not yet known; the window then holds older fragments);
  // issued(k, c) reports fragment k's issue cycle c. Returns the last issue cycle.
  template <class Ready, class Issued>
  uint64_t schedule(const uint32_t* pixel, size_t n, Ready&& ready, Issued&& issued);

  unsigned window_;
  uint32_t run_ = 0;                // stamps the pixels this run has seen
  std::vector<uint32_t> stamp_;     // per pixel key: run_ when last_ and pending_ are this run's
  std::vector<uint64_t> last_;      // the pixel's last issue cycle
  std::vector<uint32_t> pending_;   // the pixel's fragments in the window
  std::vector<Entry> entries_;      // the window, oldest first
  std::vector<uint32_t> tile_pixels_;  // run_tile's stream
};

}  // namespace zb
