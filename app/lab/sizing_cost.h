// The sizing's cost model (docs/sizing.md "The cost model"): what a method costs the RTL, counted
// while the golden model renders it. A backend wrapper sees every pass's fragment stream and
// bins it into tiles, as the RTL driver (tb/rtlmodel/tile_bins.cpp) does, at every analysed tile size at
// once.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rop/backend.h"
#include "rtl_timing.h"
#include "tile_io.h"

namespace zb {

// The tile port's traffic of the tile schedule (TileSchedule::kTile): a run per tile and group
// of passes (up to a frame operation left on the host), per pass a copy or sweep before it when
// the frame operations on the resident tile need one, its setup cycle, its loads as each plane
// is first needed; one store.
struct ResidentTraffic {
  uint64_t tile_runs = 0;       // tiles loaded (once a group)
  uint64_t io_cycles = 0;
  uint64_t beats = 0;
  std::array<uint64_t, kTilePlanes> plane_pixels{};
  // Pixels of the frame operations left on the host (a copy or resolve with no group waiting):
  // a pixel a clock on a tile port. Clears are fast clears.
  uint64_t host_op_pixels = 0;
  // The same runs with two tile buffers (two_buffer_group, rtl_timing.h): every cycle of the
  // groups, streaming included, with the port's loads and stores beside the other buffer's work.
  uint64_t two_buffer_cycles = 0;
  // Every cycle of the groups, streaming included, with the tile memory's banks of
  // kBankVariants[v] (docs/rtl.md "Renamed copies"): with one tile buffer, and with two.
  std::array<uint64_t, 4> variant_cycles{};
  std::array<uint64_t, 4> two_buffer_variant_cycles{};
};

// The tile memory's banks the lab compares: copies by reads (zb_rop before renaming), and copies
// renamed with depth banks' generations of 1, 2 (zb_rop's, kRtlBanks) and 3 bits.
struct BankVariant {
  const char* name;  // in lab.csv's columns
  TileBanks banks;
};
constexpr std::array<BankVariant, 4> kBankVariants = {{
    {"copied", {false, 1}}, {"renamed_g1", {true, 1}}, {"renamed_g2", {true, 2}}, {"renamed_g3", {true, 3}}}};

// A method's cost with square tiles of one size. The fields without a schedule in their name
// are the pass schedule's (every pass loads and stores each tile it touches); the streaming
// cycles are the same under both.
struct TileCost {
  int tile = 0;
  uint64_t tiles_loaded = 0;    // summed over passes: the tiles each pass touches
  uint64_t stream_cycles = 0;   // per touched tile: issue cycles as zb_rop's window, drain
  uint64_t tile_io_cycles = 0;  // per touched tile: setup, load and store beats (tile_io.h)
  uint64_t tile_beats = 0;      // beats loaded and stored
  // With a second tile buffer (IssueSchedule::run_two_buffers; docs/rtl.md "A second tile
  // buffer", proposed): per pass, the first fragment offered to the last drain, and the pass's
  // cycles, tile port included, summed over passes.
  uint64_t two_buffer_stream = 0;
  uint64_t two_buffer_cycles = 0;
  // The same stream with a tile port that takes no cycles: the pipeline's own cost (fill and
  // drain once a pass, a buffer reloaded only after its last tile drained), not the port's.
  uint64_t two_buffer_pipe = 0;
  // Per plane (colour, depth, coverage, peel, accumulation): pixels loaded plus pixels stored.
  std::array<uint64_t, kTilePlanes> plane_pixels{};
  ResidentTraffic resident;     // the tile schedule's
  // The RTL's clock cycles for the frame without back-pressure (`zblend render --backend rtl`
  // reports them as rtl_cycles plus the tile I/O).
  uint64_t rtl_cycles() const { return stream_cycles + tile_io_cycles; }
  uint64_t io_cycles(TileSchedule s) const {
    return s == TileSchedule::kTile ? resident.io_cycles : tile_io_cycles;
  }
  // Tile-port bytes moved (loads and stores, each plane its width), rounded up from bits.
  uint64_t port_bytes(TileSchedule s, int depth_bits, int coverage_samples,
                      const WboitFormat& wboit) const;
};

struct MethodCost {
  uint64_t passes = 0;
  PassStats totals;              // fragments and the datapath's colour and depth accesses
  // Of totals' colour reads and writes, those of accumulate passes: the accumulation word's
  // (4 * wboit.acc_bits + wboit.rev_bits bits each).
  uint64_t accum_accesses = 0;
  WboitFormat wboit;
  uint64_t frame_ops = 0;        // host frame operations (depth peeling): clears, copies, resolve
  uint64_t frame_op_pixels = 0;  // pixels those touch, frame_ops * width * height
  std::vector<TileCost> tiles;   // one per cost_tile_sizes()

  const TileCost& at(int tile) const;  // throws std::invalid_argument for another size
  // The figure "cheapest" ranks by: RTL cycles at `tile`, plus a cycle per pixel of every
  // frame operation (a tile port writes a word a clock).
  uint64_t cycles(int tile) const { return at(tile).rtl_cycles() + frame_op_pixels; }
  // Bytes moved, rounded up from bits: tile loads and stores (each plane its width) and
  // the datapath's colour (32 bits; the accumulation word in accumulate passes) and depth
  // (depth_bits) reads and writes in tile memory. The accumulation plane and word are
  // `wboit`'s, the frame's.
  uint64_t traffic_bytes(int tile, int depth_bits, int coverage_samples) const;
  // The tile size of least cycles (then least bytes, then the smaller tile: less memory).
  int best_tile(int depth_bits, int coverage_samples) const;
};

// The square tile sizes the cost model counts: the analysed ones (kAnalysisTileSizes) and the
// built model's (kRtlTileW), so a lab run on any build has its own tile's cost.
std::vector<int> cost_tile_sizes();

// Bits of one pixel in the tile memory: colour 32, depth and peel depth_bits each, coverage
// coverage_bits(samples), the accumulation word (zb_rop's five planes).
uint64_t tile_pixel_bits(int depth_bits, int coverage_samples, const WboitFormat& wboit = {});

// What a CostCounter counts: everything the lab compares (every tile size of cost_tile_sizes,
// both schedules, two buffers, the bank variants), or only zb_rop's tile under the pass
// schedule (streaming and tile port cycles, traffic): what a model timed like the RTL needs.
enum class CostScope { kLab, kPassSchedule };

// Wraps a backend, forwarding every call, and counts the method's cost.
class CostCounter final : public Backend {
 public:
  // `beat`: the tile port's pixels per clock (zb_rop's BEAT; other widths for the sweep).
  explicit CostCounter(Backend& inner, int beat = kRtlBeat, CostScope scope = CostScope::kLab)
      : inner_(inner), beat_(beat), scope_(scope) {}
  ~CostCounter() override = default;
  const char* name() const override { return inner_.name(); }
  using Backend::begin_frame;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                   int coverage_samples, const WboitFormat& wboit) override;
  void label_pass(const std::string& name) override { inner_.label_pass(name); }
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  PassStats end_pass() override;
  void finish_frame(std::vector<PassStats>& stats) override;
  void frame_op(const FrameOp& op) override;
  void load_region(const RegionLoad& r) override;
  const Framebuffer& framebuffer() const override { return inner_.framebuffer(); }

  const MethodCost& cost() const { return cost_; }

 private:
  // One tile size's binning of the current pass: each tile's stream, as frame pixel indices.
  struct Grid {
    int size = 0, columns = 0;
    std::vector<std::vector<uint32_t>> stream;  // per tile: its fragments' pixel keys (draw)
    std::vector<uint32_t> touched;  // tiles with a fragment, in first-touch order
    TileStates states;
    // The tile schedule's: the frame's planes per tile, and the group's passes with the tiles
    // each touches (sorted).
    TileStates resident_states, group_start;
    std::vector<std::vector<uint32_t>> group;  // per pass of the group: its tiles, sorted
    std::vector<std::vector<uint64_t>> group_stream;  // and each one's stream cycles
  };
  void end_group();  // the tile schedule's group ends: its traffic
  std::vector<RopState> pass_states_;  // the frame's, for finish_frame's counters
  std::vector<TileStates::GroupStep> group_steps_;  // the tile schedule's group
  size_t group_passes_ = 0;
  Backend& inner_;
  int beat_;
  CostScope scope_;
  RopState state_;
  int width_ = 0, height_ = 0;
  std::vector<Grid> grids_;
  IssueSchedule schedule_;
  MethodCost cost_;
};

}  // namespace zb
