// The RTL driver of one tile (docs/rtl.md "Tile port"): the setup cycle (pass state, counter
// clear, fast clear), the load beats, the stream with its back-pressure, the drain and the store
// beats, through zb_rop's ports on one model, with the checks of driver_checks.h and the
// monitor's events (monitor_feed.h) along the way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rop/backend.h"
#include "rop/framebuffer.h"
#include "rtl_rop.h"
#include "tile_bins.h"
#include "tile_io.h"

namespace zb {

struct Sim;

// One pass of a tile's run: its state, what its setup fast-clears and its load brings in (the
// planes it needs that the tile memory does not yet hold), and its fragments in stream order.
struct TileStep {
  uint16_t state = 0;                 // pack_state of the pass state
  TileIo io;                          // clear, load and their values; io.store unused
  const Streamed* stream = nullptr;
  size_t n = 0;
  uint64_t seed = 0;                  // tile_seed: back-pressure and idle inputs
  uint8_t preload = 0;                // before the setup: planes loaded for the copy
  bool copy = false;                  // then: copy depth to peel (tile_copy_i)
  bool sweep = false;                 // before the setup: a read of every beat
  bool swap = false;                  // the setup trades depth and peel (a renamed copy)
};

// One tile's run: its passes on the resident tile (docs/rtl.md "Schedules"), one after the
// other, then one store. Pass-major runs have one step.
struct TileJob {
  int x0 = 0, y0 = 0;                 // tile origin, pixels
  std::vector<TileStep> steps;
  uint8_t store = 0;                  // planes stored after the last step
  uint8_t preload_after = 0;          // after the last step, before the store: as a step's
  bool copy_after = false;
  bool sweep_after = false;           // the same (RunPlan::sweep_reads)
  bool swap_after = false;            // then a cycle trading depth and peel, depth cleared to
  uint32_t swap_after_depth = 0;      // this; that cycle also fast-clears these planes
  TileIo clear_after;                 // (clear_after.clear), with its values
  StoreResolve resolve = StoreResolve::kNone;  // what the store's reads apply to colour
  uint32_t background = 0;            // kUnder's, pack_rgba
  const Framebuffer* src = nullptr;   // the planes loaded from here (the group's start)
  Framebuffer* dst = nullptr;         // and stored here (src; the host's frame, the group's
                                      // operations applied; a replay's copy)
  const Fragment* pass = nullptr;     // the run's fragments, by Streamed::index (the probe's)
  uint64_t* accepted = nullptr;       // the run's accept cycles, by Streamed::index: written
  double backpressure = 0;            // RtlOptions'
  bool check_timing = true;
  bool reread_stores = false;
};

struct TileResult {
  TileRun run;                   // in the model's cycles: the first setup to the store's end
  std::vector<PassStats> stats;  // per step, the RTL's counters; cycles: streaming cycles
  bool go = true;                // false: the retire sink asked to stop
};

// Runs `job` on `sim`. Throws std::runtime_error when the RTL breaks the port contract, its
// timing or its counters.
TileResult run_tile(Sim& sim, const TileJob& job);

// The tile's random seed in a pass: the same tile gets the same back-pressure however many
// models run the pass.
uint64_t tile_seed(uint64_t run_seed, uint64_t pass, size_t tile);

}  // namespace zb
