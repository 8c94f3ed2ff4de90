// The RTL backend: the Verilated zb_rop driven through the Backend interface. Fragments of a
// pass are binned into tiles; each touched tile is loaded, streamed (with random back-pressure),
// drained and stored back (tile_driver.h), under the checks of driver_checks.h. See
// docs/datapath.md and the zb_rop port list.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "retire_monitor.h"
#include "rop/backend.h"
#include "rtl_params.h"
#include "tile_io.h"
#include "waves.h"

namespace zb {

class CoverageTotals;

struct RtlOptions {
  double backpressure = 0;  // probability per cycle of stall_i, and (independently) of a valid gap
  uint64_t seed = 1;        // back-pressure pattern; deterministic
  std::string trace_path;   // FST of the whole run when set
  // Verilator plusargs for the model. The bug build (zbrtl_bug) reads +zb_bug_window and
  // +zb_bug_accum: the issue window's or the accumulation's defect instead of the blend's
  // (docs/testbench.md "A checker that can fail").
  std::vector<std::string> plusargs;
  bool assertions = true;   // the RTL's assertions; off shows what the comparison alone catches
  // Each tile's streaming cycles must be the issue schedule's (rtl_timing.h, the cost model's
  // source; under back-pressure, of the accepts the RTL made): an RTL slower or faster than
  // specified fails.
  bool check_timing = true;
  // After each store, read the stored planes again: every word must read the same (a tile read
  // leaves the planes as they were, fresh words included). The tiles suite sets it.
  bool reread_stores = false;
  // kPass: each pass loads and stores every tile it touches; kTile: the passes between two host
  // frame operations run on the resident tile, one load and one store a tile (docs/rtl.md
  // "Schedules"). The frame's bits are the same.
  TileSchedule schedule = TileSchedule::kPass;
  // Models run a pass's tiles side by side (tiles are independent: each starts drained, its
  // planes loaded or cleared). Planes, counters and cycles are those of one model whatever the
  // number. A trace needs one waveform: with trace_path set the run uses one model.
  int threads = 1;
  // The lock-step monitor's sink (retire_monitor.h): every fragment's writes at their cycle and
  // every stored beat. Not owned; none when null.
  RetireSink* retire_sink = nullptr;
  // Coverage build only (ZBLEND_RTL_COVERAGE): the model's line and toggle counts are added
  // here when it closes. Not owned; ignored in other builds.
  CoverageTotals* coverage = nullptr;
};

// The cycles of one tile's run (one pass, or on a resident tile every pass of a group), in
// cycles since reset; stall, RTL and load-beat counts summed over its passes.
struct TileRun {
  int x0 = 0, y0 = 0;          // tile origin, pixels
  TileIo io;                   // the planes fast-cleared, loaded and stored
  uint64_t load_begin = 0;     // the setup cycle (state write, counter clear, fast clear)
  uint64_t stream_begin = 0;   // first streaming cycle (after the load beats)
  uint64_t stream_end = 0;     // cycle after the drain (busy_o low)
  uint64_t store_end = 0;      // cycle after the last tile-store read
  uint64_t stall_cycles = 0;   // the RTL's cnt_stall_cycles_o
  uint64_t rtl_cycles = 0;     // the RTL's cnt_cycles_o at the end of the drain
  uint64_t load_beats = 0;     // the RTL's cnt_tile_loads_o and cnt_tile_stores_o
  uint64_t store_beats = 0;
  uint64_t stream_cycles = 0;  // of its passes' streams (a resident tile runs several)
};

// Thrown by RtlRop::end_pass when the retire sink stopped the run. The tiles that ran are in
// tile_runs(), their cycles rebased as in a whole pass.
class RtlStopped : public std::runtime_error {
 public:
  RtlStopped() : std::runtime_error("rtl: the run was stopped by its retire sink") {}
};

class RtlRop final : public Backend {
 public:
  explicit RtlRop(RtlOptions options = {});
  ~RtlRop() override;
  RtlRop(const RtlRop&) = delete;
  RtlRop& operator=(const RtlRop&) = delete;

  const char* name() const override { return "rtl"; }
  // Which Verilated build of zb_rop this program links (docs/rtl.md "Two builds"), for its
  // header line: "speed build, no assertions" or "assertion build".
  static const char* build();
  // The layers a pixel the model's layers unit keeps (LAYERS; 0 in the mutant netlist's).
  static int model_layers();
  using Backend::begin_frame;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                   int coverage_samples, const WboitFormat& wboit) override;
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  // PassStats summed over tiles; `cycles` counts streaming cycles (first offer to drain). Under
  // TileSchedule::kTile the pass runs later (flush) and this returns zeros.
  PassStats end_pass() override;
  // Runs the passes not yet run (kTile: the group since the last host frame operation) and
  // returns their counters; empty when none wait.
  std::vector<PassStats> flush();
  bool pending() const;  // passes wait for flush
  // flush(), then under kTile every pass's counters of the frame into `stats`.
  void finish_frame(std::vector<PassStats>& stats) override;
  // Under kTile, with passes waiting and no resolve yet: clears, copies of depth to peel and
  // the resolves run on the resident tiles with them (docs/rtl.md "Tile operations"; a resolve
  // on the store, closing the group). Else the passes waiting run first and the host applies
  // it.
  void frame_op(const FrameOp& op) override;
  void load_region(const RegionLoad& r) override;
  bool on_tile() const;  // whether frame_op now joins the group
  // std::logic_error while passes wait (finish_frame or flush first).
  const Framebuffer& framebuffer() const override;

  // Cumulative cycles at the tile port (setup, load and store beats), and every cycle since
  // reset.
  uint64_t tile_io_cycles() const;
  uint64_t total_cycles() const;
  uint64_t stall_cycles() const;  // summed cnt_stall_cycles_o

  // The last group of passes run (one pass under kPass): its fragments, pass after pass, the
  // cycle each was accepted, its tiles, the number of its last pass (since construction, from
  // 0), its passes and the one (from 0) a fragment of it belongs to.
  const std::vector<Fragment>& pass_fragments() const;
  const std::vector<uint64_t>& accept_cycles() const;
  const std::vector<TileRun>& tile_runs() const;
  uint64_t pass_number() const;
  size_t group_passes() const;
  size_t pass_of(uint32_t fragment) const;

  // Replays the last group's tile at origin (x0, y0) on a fresh model, starting from `before`
  // (the frame as it was at the start of the group), dumping an FST of cycles [from, to] to
  // `fst_path`, and its save file showing `view` (waves.h). Returns the tile's frame after the
  // replay (only that tile's pixels updated). A fresh model holds no state of earlier passes
  // (the planes' fast-clear epochs): a defect that needs them may not show in the replay.
  Framebuffer replay_tile(const Framebuffer& before, int x0, int y0, const std::string& fst_path,
                          uint64_t from, uint64_t to, const WaveView& view) const;
  // What the save file of the run's own FST (RtlOptions::trace_path) shows: markers, zoom.
  void mark_waves(const WaveView& view);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace zb
