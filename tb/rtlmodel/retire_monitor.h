// The lock-step monitor of zb_rop's retire port (docs/testbench.md "A mismatch"): it turns the
// port's cycles into transactions, one per fragment and stage, each naming the fragment that
// retired. The RTL keeps each pixel's fragments in order, so the k-th retire at a pixel is the
// k-th accepted fragment to that pixel; a retire with no accepted fragment waiting is an extra
// one, and a fragment not retired when its tile has drained is missing. A sink (the
// scoreboard, tb/scoreboard.h) judges each transaction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rop/rop.h"
#include "tile_io.h"

namespace zb {

// zb_rop's mon_* outputs after a rising edge: the writes the planes take at the next one.
struct RetirePort {
  bool x4_valid = false, dwe = false, vwe = false, x11_valid = false, cwe = false, awe = false;
  bool lwe = false;
  uint32_t x4_addr = 0, wdepth = 0, wcov = 0, x11_addr = 0, wcolor = 0;
  AccumWord wacc;
  PixelLayers wlayers;
};

// X4 writes depth and coverage, X11 colour, (accumulate mode) the accumulation word or (layers
// mode) the layers.
enum class RetireStage : uint8_t { kX4, kX11 };
const char* to_string(RetireStage s);

struct Retire {
  enum class Kind : uint8_t {
    kRetired,  // `fragment` retired with `writes`
    kExtra,    // the RTL retired at the pixel, no accepted fragment waited there
    kMissing,  // `fragment` had not retired when its tile drained
  };
  static constexpr uint32_t kNoFragment = ~0u;
  Kind kind = Kind::kRetired;
  RetireStage stage = RetireStage::kX4;
  uint32_t fragment = kNoFragment;  // index in the pass
  int x = 0, y = 0;                 // the pixel
  int tile_x0 = 0, tile_y0 = 0;
  uint64_t tile_cycle = 0;          // cycles since the tile's setup cycle; the write's edge ends it
  PixelWrites writes;               // the RTL's: X4 depth and coverage, X11 colour, accumulation
};

// Beat `beat` of the tile at (tile_x0, tile_y0) as the store read it.
struct StoreBeat {
  int tile_x0 = 0, tile_y0 = 0, beat = 0;
  uint8_t planes = 0;  // kPlane* stored
  uint64_t tile_cycle = 0;
  const BeatWords* words = nullptr;
};

// Judges the monitor's transactions. Called from every model's thread at once in a
// tile-parallel run. Returning false stops the run: no further tile starts, the running ones
// finish, and RtlRop::end_pass throws RtlStopped.
class RetireSink {
 public:
  virtual ~RetireSink() = default;
  virtual bool retire(const Retire& r) = 0;
  virtual bool store(const StoreBeat& b) = 0;
  // The golden model's writes for `fragment` of the pass, for the waveform's probe; null when
  // the sink does not know them.
  virtual const PixelWrites* expected(uint32_t /*fragment*/) const { return nullptr; }
};

// One model's monitor, a tile at a time.
class RetireMonitor {
 public:
  explicit RetireMonitor(RetireSink& sink) : sink_(sink) {}
  // The tile's stream, in the order offered: each fragment's tile word address (y_local *
  // kRtlTileW + x_local) and its index in the pass.
  void begin_tile(int x0, int y0, const uint32_t* addr, const uint32_t* index, size_t n);
  // After a rising edge, with `accepted` of the stream's fragments accepted so far. Returns
  // false once the sink asked to stop.
  bool observe(const RetirePort& p, uint64_t tile_cycle, size_t accepted);
  // The tile has drained: every fragment still waiting to retire is missing.
  bool end_tile(uint64_t tile_cycle);
  // Each fragment's X4 retire, by stream position: its tile cycle (kNoCycle when none yet).
  static constexpr uint64_t kNoCycle = ~uint64_t{0};
  const std::vector<uint64_t>& x4_cycles() const { return x4_cycle_; }
  // A beat the tile's store read, to the sink.
  bool store(const StoreBeat& b) { return go_ = go_ && sink_.store(b); }

 private:
  static constexpr uint32_t kNone = ~0u;
  Retire at(RetireStage stage, uint32_t addr, uint64_t cycle) const;  // pixel, tile, cycle
  bool take(RetireStage stage, uint32_t addr, uint64_t cycle, size_t accepted,
            const PixelWrites& w);

  RetireSink& sink_;
  bool go_ = true;
  int x0_ = 0, y0_ = 0;
  const uint32_t* addr_ = nullptr;
  const uint32_t* index_ = nullptr;
  size_t n_ = 0;
  std::vector<uint32_t> next_;  // per stream position: the next one to its pixel
  std::vector<uint32_t> head_[2], tail_;  // per stage and tile word: the next to retire
  std::vector<uint64_t> x4_cycle_;          // per stream position
};

}  // namespace zb
