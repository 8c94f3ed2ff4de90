// zb_rop's tile port traffic (docs/rtl.md "Tile port"): which planes a pass fast-clears, loads
// and stores for a tile, from the pass state and the tile's planes as the frame holds them,
// and the port's cycles. The RTL driver, the SystemC driver and the cost model all take their
// tile traffic from here.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rop/backend.h"
#include "rop/fragment.h"
#include "rop/framebuffer.h"
#include "rtl_params.h"

namespace zb {

// A colour as zb_rop's ports carry it: r | g << 8 | b << 16 | a << 24.
constexpr uint32_t pack_rgba(Rgba8 c) {
  return uint32_t{c.r} | uint32_t{c.g} << 8 | uint32_t{c.b} << 16 | uint32_t{c.a} << 24;
}
constexpr Rgba8 unpack_rgba(uint32_t v) {
  return {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
}

// zb_pkg::planes_t: bit p selects plane p of the tile port. The first four hold a word of at
// most 32 bits a pixel (kWordPlanes); the accumulation plane (accumulate mode, docs/datapath.md
// "7. Accumulate blend") a wider one, AccumWord. The layers plane (layers mode, "8. Layers")
// never crosses the port: it is only fast-cleared (empty), and a store's resolve reads it.
enum : uint8_t {
  kPlaneColor = 1, kPlaneDepth = 2, kPlaneCoverage = 4, kPlanePeel = 8, kPlaneAccum = 16,
  kPlaneLayers = 32
};
constexpr int kTilePlanes = 6;
constexpr int kWordPlanes = 4;
constexpr int kAccumPlane = 4;   // kPlaneAccum's number
constexpr int kLayersPlane = 5;  // kPlaneLayers'
// zb_rop's tile_planes_i: the planes the port moves; kPlaneLayers is tile_mlab_i with a clear.
constexpr int kPortPlanes = 5;
constexpr uint8_t port_planes(uint8_t planes) { return uint8_t(planes & ((1u << kPortPlanes) - 1)); }
// zb_rop's state_i and state_layers_i: a packed pass state (pack_state) split.
constexpr uint32_t port_state(uint16_t bits) { return bits & 0x1fffu; }
constexpr uint32_t port_state_layers(uint16_t bits) { return uint32_t(bits) >> 13; }

// A pixel's accumulation word, zb_rop's {r, acc_A, acc_B, acc_G, acc_R} (acc_R at bit 0):
// Framebuffer::accum and Framebuffer::reveal of one pixel.
struct AccumWord {
  std::array<uint32_t, 4> acc{};  // R, G, B, A
  uint32_t reveal = 0;
  friend bool operator==(const AccumWord& x, const AccumWord& y) {
    return x.acc == y.acc && x.reveal == y.reveal;
  }
  friend bool operator!=(const AccumWord& x, const AccumWord& y) { return !(x == y); }
};
// The word's bits, 4 ACC_BITS + REV_BITS (zb_rop's AccW).
constexpr int accum_word_bits(const WboitFormat& f) { return 4 * f.acc_bits + f.rev_bits; }
// The cleared word: accumulation 0, revealage 1.0.
AccumWord accum_clear_word(const WboitFormat& f);
// "acc(r,g,b,a) reveal n", for reports.
std::string accum_text(const AccumWord& w);
std::string accum_text(const std::array<uint32_t, 4>& acc, uint32_t reveal);

// The planes a pass with state `s` may read (a layers pass: the colour its resolve puts the
// layers over), and may write (every pixel of a written plane is
// stored, so it must be whole in the tile memory: loaded or fast-cleared).
uint8_t planes_read(const RopState& s);
uint8_t planes_written(const RopState& s);

// One tile's traffic in one pass: plane masks, and per plane the fast clear's value (colour
// pack_rgba, depth, coverage count, peel depth; the accumulation plane's in accum_clear).
struct TileIo {
  uint8_t clear = 0, load = 0, store = 0;
  std::array<uint32_t, kWordPlanes> clear_value{};
  AccumWord accum_clear;
};

// The order the driver runs a frame's tiles and passes in (docs/rtl.md "Schedules"): pass after
// pass, each loading and storing every tile it touches; or tile after tile, each tile loaded
// once, every pass up to the next host frame operation run on it, stored once.
enum class TileSchedule : uint8_t { kPass, kTile };
const char* to_string(TileSchedule s);
// "pass" or "tile"; false for anything else.
bool parse_schedule(const std::string& name, TileSchedule& out);
// Whether a frame operation ends the tile schedule's group, applied to its stores' colour
// (docs/rtl.md "Tile operations"): the resolves.
inline bool resolves(FrameOpKind k) {
  return k == FrameOpKind::kResolveUnder || k == FrameOpKind::kResolveWboit ||
         k == FrameOpKind::kResolveLayers;
}
// What a store's read applies to colour (zb_rop's tile_resolve_i, tile_wboit_i, tile_mlab_i).
enum class StoreResolve : uint8_t { kNone, kUnder, kWboit, kLayers };

// Beats of a w x h tile: a beat is `beat` neighbours of one row. Loads and stores move the
// whole tile also where the frame clips it: every word's fast-clear generation must follow
// the plane's (zb_plane), so none may be left behind.
uint64_t tile_beats(int w, int h, int beat);
// The tile's cycles at the port, beside its streaming (IssueSchedule): one setup cycle (pass
// state, counter clear and fast clear), then its load beats, later its store beats. On a
// resident tile a copy of depth to peel takes a read a beat and one cycle more (the last beat's
// load), a sweep a read a beat.
constexpr uint64_t kRtlTileSetup = 1;
constexpr uint64_t kRtlCopyTail = 1;
uint64_t tile_io_cycles(uint64_t beats, const TileIo& io);

// One beat at the built model's port: per word plane (kPlane* bit order) and lane, the word
// (colour pack_rgba, depth, coverage count, peel depth), w[p][lane]; and per lane the
// accumulation word, w.accum[lane].
struct BeatWords {
  std::array<std::array<uint32_t, kRtlBeat>, kWordPlanes> words{};
  std::array<AccumWord, kRtlBeat> accum{};
  std::array<uint32_t, kRtlBeat>& operator[](size_t p) { return words[p]; }
  const std::array<uint32_t, kRtlBeat>& operator[](size_t p) const { return words[p]; }
};

// Allocates the planes a pass in state `s` stores (the accumulation planes are lazy), on the
// thread that dispatches its tiles, before any tile runs.
void prepare_stores(Framebuffer& fb, const RopState& s);

// The fast clear's beat: each plane's clear value in lane 0.
BeatWords clear_beat(const TileIo& io);

// The port's sweep of one kRtlTileW x kRtlTileH tile of a frame: beat k at address k, lane l
// the pixel (x0 + (k % beats per row) * kRtlBeat + l, y0 + k / beats per row). The RTL and
// SystemC drivers move every beat through their ports; this holds the pixels and the edge.
class TileSweep {
 public:
  TileSweep(int frame_w, int frame_h, int x0, int y0);
  int beats() const { return int(tile_beats(kRtlTileW, kRtlTileH, kRtlBeat)); }
  // Beat k's words from `fb`: lanes beyond the frame's edge 0.
  BeatWords load(const Framebuffer& fb, int k) const;
  // Beat k's words of `planes` (colour, depth, coverage, peel, accumulation) into `fb`, lanes within
  // the frame. Tiles store on several threads at once, so a store allocates nothing: a plane
  // missing or of another size (the frame replaced under the pass) is std::logic_error, a fault
  // of the host, never reported as the RTL's mismatch. prepare_stores allocates them first.
  void store(const BeatWords& words, uint8_t planes, Framebuffer& fb, int k) const;
  // Beat k's lane l in the frame (its index in `fb`'s planes), or -1 beyond its edge.
  int64_t pixel(const Framebuffer& fb, int k, int l) const;

 private:
  int x0_, y0_, w_, h_;
};

// The tile memory's banks as planned (docs/rtl.md "Renamed copies"). With `rename`, a copy of
// depth to peel that a clear of depth follows trades the two planes' banks (in the next setup
// cycle, with the fast clear of depth) instead of a read a beat, and the depth banks' words
// carry a generation of gen_bits: 2^gen_bits - 1 fast clears of a written bank between reads of
// every beat (a sweep otherwise; the other planes have one bit: a sweep after each).
struct TileBanks {
  bool rename = false;
  int gen_bits = 1;
};
constexpr TileBanks kRtlBanks{true, kRtlDepthGenBits};  // zb_rop's (TILE_OPS, DEPTH_GEN)

// Each tile's planes as the frame holds them: cleared to one value (the tile memory takes the
// value, not the words: fast clear) or words stored by a pass or made by a frame operation.
class TileStates {
 public:
  TileStates() = default;
  // A frame just begun: every plane cleared (colour `clear_color`, depth the far value,
  // coverage 0, peel 0, accumulation accum_clear_word(wboit), no layers), as Framebuffer's
  // constructor fills it. The layers plane stays cleared: it is never stored.
  TileStates(int width, int height, int tile, int depth_bits, Rgba8 clear_color,
             const WboitFormat& wboit = {});

  void frame_op(const FrameOp& op);
  TileIo plan(size_t tile, const RopState& s) const;
  // A resident tile's group (docs/rtl.md "Schedules"), planned from the tile's planes as the
  // frame holds them at the group's start (this object's state then): per step, a pass (when
  // it touches the tile) or a frame operation run on the tile. Loads read the frame as it was
  // at the group's start: a plane an operation changed is never loaded after it (a cleared one
  // is fast-cleared; a copy runs on the tile, the frame's depth loaded for it if need be).
  struct GroupStep {
    bool pass = false;
    bool touches = false;  // a pass with fragments in the tile
    RopState state;        // a pass's
    FrameOp op;            // else: a clear, a copy of depth to peel or (last) a resolve
  };
  struct RunPlan {
    struct Step {
      size_t step = 0;      // the pass's index in the group's steps
      TileIo io;            // its setup's fast clear and its loads (io.store unused)
      uint8_t preload = 0;  // before it: planes loaded for a copy (the frame's depth)
      bool copy = false;    // then a read of every beat copying depth to peel
      bool sweep = false;   // or a read of every beat (a fast clear may follow)
      bool swap = false;    // TileBanks::rename: depth and peel trade banks in its setup
    };
    std::vector<Step> steps;        // the passes that touch the tile
    uint8_t preload_after = 0;      // after the last, before the store: as a Step's
    bool copy_after = false, sweep_after = false;
    bool swap_after = false;        // then a setup cycle of its own for the trade,
    uint32_t swap_after_depth = 0;  // its fast clear of depth to this,
    TileIo clear_after;             // and these fast clears (clear_after.clear: planes)
    StoreResolve resolve = StoreResolve::kNone;  // the group's last step, if a resolve
    uint8_t store = 0;              // planes stored (made in the tile since their last clear)
    bool closing_setup() const { return swap_after || clear_after.clear; }
    // The reads of a sweep after the last pass: a store is one, unless a fast clear comes between.
    bool sweep_reads() const { return sweep_after && (!store || closing_setup()); }
  };
  RunPlan plan_tile(size_t tile, const GroupStep* steps, size_t n, TileBanks banks = kRtlBanks) const;
  // A resolve has closed the group (its stores apply it): the next pass begins another.
  static bool closed(const std::vector<GroupStep>& steps) {
    return !steps.empty() && !steps.back().pass && resolves(steps.back().op.kind);
  }
  void stored(size_t tile, uint8_t planes);  // the pass stored these planes of the tile
  // A region loaded into the frame (Backend::load_region): every tile it covers holds its
  // colour (and depth) in the frame now, loaded at the tile's next pass.
  void loaded(const RegionLoad& r);

 private:
  struct Plane {
    bool cleared = true;
    uint32_t value = 0;
  };
  int depth_bits_ = 24;
  int tile_ = 1, columns_ = 1;
  AccumWord accum_clear_;
  std::vector<std::array<Plane, kTilePlanes>> planes_;
  void apply(std::array<Plane, kTilePlanes>& t, const FrameOp& op) const;
  TileIo plan(const std::array<Plane, kTilePlanes>& t, const RopState& s) const;
};

}  // namespace zb
