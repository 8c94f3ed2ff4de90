// The RTL driver of one tile (docs/rtl.md "Tile port"): the setup cycle (pass state, counter
// clear, fast clear), the load beats, the stream with its back-pressure, the drain and the store
// beats, through zb_rop's ports on one model, with the checks of driver_checks.h and the
// monitor's events (monitor_feed.h) along the way.
#pragma once

#include <cstddef>
#include <cstdint>

#include "rop/backend.h"
#include "rop/framebuffer.h"
#include "rtl_rop.h"
#include "tile_bins.h"
#include "tile_io.h"

namespace zb {

struct Sim;

// One tile of a pass.
struct TileJob {
  int x0 = 0, y0 = 0;                 // tile origin, pixels
  TileIo io;                          // the planes fast-cleared, loaded and stored
  uint16_t state = 0;                 // pack_state of the pass state
  const Framebuffer* src = nullptr;   // the planes loaded from here
  Framebuffer* dst = nullptr;         // and stored here (src, or a replay's copy)
  const Streamed* stream = nullptr;   // the tile's fragments in stream order
  size_t n = 0;
  const Fragment* pass = nullptr;     // the pass's fragments, by Streamed::index (the probe's)
  uint64_t* accepted = nullptr;       // the pass's accept cycles, by Streamed::index: written
  uint64_t seed = 0;                  // tile_seed: back-pressure and idle inputs
  double backpressure = 0;            // RtlOptions'
  bool check_timing = true;
  bool reread_stores = false;
};

struct TileResult {
  TileRun run;      // in the model's cycles
  PassStats stats;  // the RTL's counters; cycles: streaming cycles
  bool go = true;   // false: the retire sink asked to stop
};

// Runs `job` on `sim`. Throws std::runtime_error when the RTL breaks the port contract, its
// timing or its counters.
TileResult run_tile(Sim& sim, const TileJob& job);

// The tile's random seed in a pass: the same tile gets the same back-pressure however many
// models run the pass.
uint64_t tile_seed(uint64_t run_seed, uint64_t pass, size_t tile);

}  // namespace zb
