// zb_rop's tile port on the Verilated model: its beat counters (cnt_tile_loads_o,
// cnt_tile_stores_o) show which tiles a pass loads and stores; fast-cleared planes read as the
// clear value wherever the pass did not write, beside the pixels it did (checked against the
// golden model, pixel for pixel).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "rop/rop.h"
#include "rtl_params.h"
#include "rtl_rop.h"
#include "tile_io.h"

namespace zb {
namespace {

constexpr int kW = 2 * kRtlTileW, kH = kRtlTileH;  // two tiles side by side
const uint64_t kBeats = uint64_t(kRtlTileW) * kRtlTileH / kRtlBeat;

// One fragment every third pixel of tile 0's first rows: most beats are written in some pixels
// and not in others.
std::vector<Fragment> sparse_in_tile0(uint32_t z, Rgba8 c) {
  std::vector<Fragment> f;
  for (int y = 0; y < 3; ++y)
    for (int x = y; x < kRtlTileW; x += 3) {
      Fragment g;
      g.x = uint16_t(x);
      g.y = uint16_t(y);
      g.z = z;
      g.color = c;
      f.push_back(g);
    }
  return f;
}

FrameOp op(FrameOpKind kind, Rgba8 value = {}, uint32_t depth = 0) {
  FrameOp o;
  o.kind = kind;
  o.value = value;
  o.depth = depth;
  return o;
}

struct Both {
  RtlRop rtl;
  GoldenRop golden;
  void begin_frame() {
    rtl.begin_frame(kW, kH, kRtlDepthBits, Rgba8{10, 20, 30, 255}, kRtlCoverageSamples,
                    kRtlWboit);
    golden.begin_frame(kW, kH, kRtlDepthBits, Rgba8{10, 20, 30, 255}, kRtlCoverageSamples,
                       kRtlWboit);
  }
  void pass(const RopState& s, const std::vector<Fragment>& f) {
    for (Backend* b : {static_cast<Backend*>(&rtl), static_cast<Backend*>(&golden)}) {
      b->begin_pass(s);
      b->draw(f.data(), f.size());
      b->end_pass();
    }
  }
  void frame_op(const FrameOp& op) {
    rtl.frame_op(op);
    golden.frame_op(op);
  }
  void expect_same_frame() const {
    const Framebuffer &r = rtl.framebuffer(), &g = golden.framebuffer();
    EXPECT_EQ(r.color, g.color);
    EXPECT_EQ(r.depth, g.depth);
    EXPECT_EQ(r.coverage, g.coverage);
    EXPECT_EQ(r.accum, g.accum);
    EXPECT_EQ(r.reveal, g.reveal);
  }
  const TileRun& only_run() const {
    EXPECT_EQ(rtl.tile_runs().size(), 1u) << "the pass ran another tile than tile 0";
    return rtl.tile_runs().at(0);
  }
};

TEST(TilePort, AfterAClearNothingLoadsAndAnUntouchedTileIsNotRun) {
  Both m;
  m.begin_frame();
  const RopState opaque;  // depth test less, depth write, replace
  m.pass(opaque, sparse_in_tile0(100, Rgba8{200, 0, 0, 255}));
  const TileRun& first = m.only_run();
  EXPECT_EQ(first.x0, 0);
  EXPECT_EQ(first.load_beats, 0u) << "a new frame's tile loaded";
  EXPECT_EQ(first.store_beats, kBeats);
  EXPECT_EQ(first.io.clear, kPlaneColor | kPlaneDepth);
  m.expect_same_frame();

  // The stored tile loads in the next pass; tile 1 is still not run.
  m.pass(opaque, sparse_in_tile0(50, Rgba8{0, 200, 0, 255}));
  EXPECT_EQ(m.only_run().load_beats, kBeats);
  EXPECT_EQ(m.only_run().io.clear, 0);
  m.expect_same_frame();

  // Cleared again: fast clear, no load.
  m.frame_op(op(FrameOpKind::kClearColor, Rgba8{1, 2, 3, 4}));
  m.frame_op(op(FrameOpKind::kClearDepth, {}, FrameOp::kFar));
  m.pass(opaque, sparse_in_tile0(70, Rgba8{0, 0, 200, 255}));
  EXPECT_EQ(m.only_run().load_beats, 0u);
  EXPECT_EQ(m.only_run().io.clear_value[0], 0x04030201u);
  m.expect_same_frame();
}

// A fast-cleared plane written in part, stored, then cleared again: the store put every word
// back at the plane's epoch, so the second fast clear makes all of them fresh.
TEST(TilePort, FastClearAfterAFastClearedPass) {
  Both m;
  m.begin_frame();
  m.pass(RopState{}, sparse_in_tile0(100, Rgba8{200, 0, 0, 255}));
  for (int k = 0; k < 3; ++k) {
    m.frame_op(op(FrameOpKind::kClearColor, Rgba8{uint8_t(k), 7, 9, 255}));
    m.frame_op(op(FrameOpKind::kClearDepth, {}, FrameOp::kFar));
    std::vector<Fragment> f = sparse_in_tile0(uint32_t(60 + k), Rgba8{0, 0, 200, 255});
    f.erase(f.begin(), f.begin() + k);  // other pixels each time
    m.pass(RopState{}, f);
    EXPECT_EQ(m.only_run().load_beats, 0u);
    m.expect_same_frame();
  }
}

TEST(TilePort, APassThatWritesNothingStoresNothing) {
  Both m;
  m.begin_frame();
  m.pass(RopState{}, sparse_in_tile0(100, Rgba8{200, 0, 0, 255}));
  RopState test_only;
  test_only.depth_write = false;
  test_only.color_mask = 0;
  m.pass(test_only, sparse_in_tile0(10, Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(m.only_run().store_beats, 0u);
  EXPECT_EQ(m.only_run().load_beats, kBeats) << "the depth test reads the stored depth";
  m.expect_same_frame();
}

// Peeling's frame operations on fast-cleared planes: a peel copied from a cleared depth is
// itself cleared, and the resolve of a cleared colour is one colour.
TEST(TilePort, CopiedAndResolvedPlanesStayCleared) {
  Both m;
  m.begin_frame();
  m.frame_op(op(FrameOpKind::kCopyDepthToPeel));
  m.frame_op(op(FrameOpKind::kResolveUnder, Rgba8{90, 80, 70, 255}));
  RopState peel;
  peel.peel_test = true;
  peel.blend = BlendMode::kUnder;
  m.pass(peel, sparse_in_tile0(200, Rgba8{100, 100, 100, 128}));
  EXPECT_EQ(m.only_run().load_beats, 0u);
  EXPECT_EQ(m.only_run().io.clear, kPlaneColor | kPlaneDepth | kPlanePeel);
  m.expect_same_frame();
}

// The accumulate blend's planes: the accumulation word is fast-cleared to revealage 1.0 and
// stored, the colour plane neither loaded nor stored; the resolve of a cleared accumulation
// leaves a cleared colour cleared (every pixel keeps it), of a stored one makes it words.
TEST(TilePort, AccumulationPlaneClearedStoredAndResolved) {
  Both m;
  m.begin_frame();
  m.frame_op(op(FrameOpKind::kResolveWboit));
  RopState acc;
  acc.depth_write = false;
  acc.blend = BlendMode::kAccumulate;
  m.pass(acc, sparse_in_tile0(300, Rgba8{100, 150, 200, 128}));
  EXPECT_EQ(m.only_run().load_beats, 0u);
  EXPECT_EQ(m.only_run().io.clear, kPlaneDepth | kPlaneAccum);
  EXPECT_EQ(m.only_run().io.accum_clear, accum_clear_word(kRtlWboit));
  EXPECT_EQ(m.only_run().io.store, kPlaneAccum);
  m.expect_same_frame();
  m.pass(acc, sparse_in_tile0(200, Rgba8{10, 20, 30, 255}));
  EXPECT_EQ(m.only_run().io.load, kPlaneAccum) << "the first pass stored the accumulation";
  m.expect_same_frame();
  m.frame_op(op(FrameOpKind::kResolveWboit));
  RopState replace;
  m.pass(replace, sparse_in_tile0(100, Rgba8{1, 2, 3, 255}));
  EXPECT_EQ(m.only_run().io.load, kPlaneColor) << "the resolve made the tile's colour words";
  m.expect_same_frame();
}

// The accumulation word's widths are the Verilated model's: another format is refused, naming
// both.
TEST(TilePort, RefusesAnotherAccumulationFormat) {
  RtlRop rtl;
  WboitFormat other = kRtlWboit;
  other.acc_bits = kRtlWboit.acc_bits == 12 ? 13 : 12;
  try {
    rtl.begin_frame(8, 8, kRtlDepthBits, Rgba8{}, kRtlCoverageSamples, other);
    FAIL() << "begin_frame took another accumulation width";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("accumulation " + std::to_string(other.acc_bits) +
                                         " bits"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("ACC_BITS " + std::to_string(kRtlWboit.acc_bits)),
              std::string::npos)
        << e.what();
  }
}

// Tiles store on several threads at once, so a store allocates nothing: planes the pass did not
// prepare, or a frame replaced under it, are the host's fault (std::logic_error), not a
// mismatch the RTL would be blamed for.
TEST(TileSweep, StoreRefusesPlanesNotPrepared) {
  Framebuffer fb(kW, kH, kRtlDepthBits, Rgba8{0, 0, 0, 255}, kRtlCoverageSamples, kRtlWboit);
  const TileSweep sweep(fb.width, fb.height, 0, 0);
  BeatWords w{};
  w.accum[0] = AccumWord{{1, 2, 3, 4}, 5};
  ASSERT_TRUE(fb.accum.empty());
  EXPECT_THROW(sweep.store(w, kPlaneAccum, fb, 0), std::logic_error);
  EXPECT_TRUE(fb.accum.empty()) << "a store must not allocate the planes";
  RopState accumulate;
  accumulate.blend = BlendMode::kAccumulate;
  prepare_stores(fb, accumulate);
  sweep.store(w, kPlaneAccum, fb, 0);
  EXPECT_EQ(fb.accum_at(0)[0], 1u);
  EXPECT_EQ(fb.reveal_at(0), 5u);
  fb.color.clear();  // the frame replaced under the pass
  EXPECT_THROW(sweep.store(w, kPlaneColor, fb, 0), std::logic_error);
}

TEST(TileStates, PlanesFollowThePassState) {
  RopState s;
  EXPECT_EQ(planes_read(s), kPlaneColor | kPlaneDepth);
  EXPECT_EQ(planes_written(s), kPlaneColor | kPlaneDepth);
  s.depth_test = false;
  s.color_mask = 0;
  EXPECT_EQ(planes_read(s), 0);
  EXPECT_EQ(planes_written(s), 0);
  s.blend = BlendMode::kCoverage;  // coverage mode reads depth (nearer) whatever the test
  EXPECT_EQ(planes_read(s), kPlaneDepth | kPlaneCoverage);
  EXPECT_EQ(planes_written(s), kPlaneCoverage);
  s = RopState{};
  s.peel_test = true;
  s.depth_write = false;
  EXPECT_EQ(planes_read(s), kPlaneColor | kPlaneDepth | kPlanePeel);
  EXPECT_EQ(planes_written(s), kPlaneColor);
  s.blend = BlendMode::kAccumulate;  // the accumulation word instead of the colour
  EXPECT_EQ(planes_read(s), kPlaneAccum | kPlaneDepth | kPlanePeel);
  EXPECT_EQ(planes_written(s), kPlaneAccum);
  s.color_mask = 0;
  EXPECT_EQ(planes_read(s), kPlaneDepth | kPlanePeel);
  EXPECT_EQ(planes_written(s), 0);
  // Beats: rows times beats a row, a partial beat counted whole.
  EXPECT_EQ(tile_beats(64, 64, 8), 512u);
  EXPECT_EQ(tile_beats(9, 2, 8), 4u);
  EXPECT_EQ(tile_beats(0, 5, 8), 0u);
  TileIo io;
  EXPECT_EQ(tile_io_cycles(512, io), 1u);
  io.load = kPlaneDepth;
  io.store = kPlaneColor;
  EXPECT_EQ(tile_io_cycles(512, io), 1025u);
}

// A depth peel's steps on one tile, planned by hand: a pass writing depth, then `layers` - 1
// times a copy of depth to peel, a clear of depth and a pass behind the peel plane writing depth.
std::vector<TileStates::GroupStep> peel_steps(int layers, bool clear_after_copy = true) {
  std::vector<TileStates::GroupStep> steps;
  RopState depth_only;
  depth_only.color_mask = 0;
  auto op = [&](FrameOpKind k) {
    TileStates::GroupStep st;
    st.op = FrameOp{k, Rgba8{}, FrameOp::kFar, false};
    steps.push_back(st);
  };
  auto pass = [&](bool peel) {
    TileStates::GroupStep st;
    st.pass = st.touches = true;
    st.state = depth_only;
    st.state.peel_test = peel;
    steps.push_back(st);
  };
  op(FrameOpKind::kClearDepth);
  pass(false);
  for (int i = 1; i < layers; ++i) {
    op(FrameOpKind::kCopyDepthToPeel);
    if (clear_after_copy) op(FrameOpKind::kClearDepth);
    pass(true);
  }
  return steps;
}

// Per pass after the first: 'c' a copy, 's' a sweep, 'r' a renaming (banks swapped), 'R' both.
std::string before_passes(const TileStates::RunPlan& run) {
  std::string out;
  for (size_t k = 1; k < run.steps.size(); ++k) {
    const auto& st = run.steps[k];
    out += st.copy ? 'c' : st.swap ? (st.sweep ? 'R' : 'r') : st.sweep ? 's' : '-';
  }
  return out;
}

// zb_rop's banks copy before every peel. Renamed with one generation bit, the bank that comes
// back to depth was written since its last fast clear: a sweep before every other peel (the
// sweep writes back both banks' fresh words, so the next one needs none). With two bits it
// takes three fast clears between reads of every beat: a bank's fourth, before the 7th pass,
// needs the first sweep. A copy that no clear of depth follows stays a copy.
TEST(TileStates, RenamedCopiesSweepAsTheGenerationsRunOut) {
  const TileStates frame(64, 64, 64, kRtlDepthBits, Rgba8{0, 0, 0, 255});
  const auto steps = peel_steps(8);
  EXPECT_EQ(before_passes(frame.plan_tile(0, steps.data(), steps.size(), {false, 1})), "ccccccc");
  EXPECT_EQ(before_passes(frame.plan_tile(0, steps.data(), steps.size())), "rrrrrRr");  // zb_rop's
  EXPECT_EQ(before_passes(frame.plan_tile(0, steps.data(), steps.size(), {true, 1})), "rRrRrRr");
  EXPECT_EQ(before_passes(frame.plan_tile(0, steps.data(), steps.size(), {true, 2})), "rrrrrRr");
  EXPECT_EQ(before_passes(frame.plan_tile(0, steps.data(), steps.size(), {true, 3})), "rrrrrrr");
  const TileStates::RunPlan run = frame.plan_tile(0, steps.data(), steps.size(), {true, 3});
  EXPECT_EQ(run.store, kPlaneDepth | kPlanePeel);
  EXPECT_FALSE(run.copy_after || run.sweep_after);
  const auto kept = peel_steps(3, false);
  EXPECT_EQ(before_passes(frame.plan_tile(0, kept.data(), kept.size(), {true, 3})), "cc");
  // A run that ends on a renamed copy trades the banks in a cycle of its own before the store,
  // clearing depth to the far value; a pass that needs no depth takes the trade's clear of it.
  auto ends = peel_steps(2);
  ends.push_back(ends[2]);  // copy
  ends.push_back(ends[3]);  // clear depth
  const TileStates::RunPlan last = frame.plan_tile(0, ends.data(), ends.size());
  EXPECT_TRUE(last.swap_after);
  EXPECT_EQ(last.swap_after_depth, depth_max(kRtlDepthBits));
  EXPECT_EQ(last.store, kPlanePeel) << "the depth the second pass wrote is cleared after it";
  auto colour = peel_steps(2);
  colour.back().state = RopState{};
  colour.back().state.depth_test = false;  // colour only: no depth
  const TileStates::RunPlan c = frame.plan_tile(0, colour.data(), colour.size());
  ASSERT_EQ(c.steps.size(), 2u);
  EXPECT_TRUE(c.steps[1].swap);
  EXPECT_EQ(c.steps[1].io.clear & kPlaneDepth, kPlaneDepth);
  EXPECT_EQ(c.steps[1].io.clear_value[1], depth_max(kRtlDepthBits));
}

// The resolve of the accumulation runs on the store's reads (docs/rtl.md "Tile operations"): it
// needs colour (C0) and the accumulation resident. An accumulate pass neither reads nor writes
// colour, so a cleared colour is fast-cleared in a closing setup cycle and stored, resolved; a
// stored one is loaded after the last pass. A pass that wrote colour leaves it resident.
TEST(TileStates, ResolveOfTheAccumulationOnTheStore) {
  const Rgba8 bg{10, 20, 30, 255};
  TileStates frame(64, 64, 64, kRtlDepthBits, bg);
  TileStates::GroupStep accumulate;
  accumulate.pass = accumulate.touches = true;
  accumulate.state.depth_write = false;
  accumulate.state.blend = BlendMode::kAccumulate;
  TileStates::GroupStep resolve;
  resolve.op = FrameOp{FrameOpKind::kResolveWboit, Rgba8{}, 0, false};
  const std::vector<TileStates::GroupStep> steps = {accumulate, resolve};
  const TileStates::RunPlan cleared = frame.plan_tile(0, steps.data(), steps.size());
  EXPECT_EQ(cleared.resolve, StoreResolve::kWboit);
  EXPECT_TRUE(cleared.closing_setup());
  EXPECT_EQ(cleared.clear_after.clear, kPlaneColor);
  EXPECT_EQ(cleared.clear_after.clear_value[0], pack_rgba(bg));
  EXPECT_EQ(cleared.preload_after, 0);
  EXPECT_EQ(cleared.store, kPlaneColor | kPlaneAccum);
  frame.stored(0, kPlaneColor);  // colour words in the frame now: loaded, not cleared
  const TileStates::RunPlan stored = frame.plan_tile(0, steps.data(), steps.size());
  EXPECT_EQ(stored.preload_after, kPlaneColor);
  EXPECT_FALSE(stored.closing_setup());
  EXPECT_EQ(stored.store, kPlaneColor | kPlaneAccum);
  TileStates::GroupStep opaque;
  opaque.pass = opaque.touches = true;
  const std::vector<TileStates::GroupStep> both = {opaque, accumulate, resolve};
  const TileStates::RunPlan resident = frame.plan_tile(0, both.data(), both.size());
  EXPECT_EQ(resident.preload_after, 0);
  EXPECT_FALSE(resident.closing_setup());
}

// mlab-K's layers never cross the port: a layers pass fast-clears them (empty: no clear value,
// the four word planes' values untouched), has the colour resident for its resolve, and its
// group stores the colour the resolve makes, never the layers.
TEST(TileStates, LayersStayOnTheTile) {
  const Rgba8 bg{10, 20, 30, 255};
  TileStates frame(64, 64, 64, kRtlDepthBits, bg);
  TileStates::GroupStep layers;
  layers.pass = layers.touches = true;
  layers.state.depth_write = false;
  layers.state.blend = BlendMode::kLayers;
  layers.state.layers = 4;
  EXPECT_EQ(planes_read(layers.state), kPlaneLayers | kPlaneColor | kPlaneDepth);
  EXPECT_EQ(planes_written(layers.state), kPlaneLayers);
  const TileIo io = frame.plan(0, layers.state);
  EXPECT_EQ(io.clear, kPlaneColor | kPlaneDepth | kPlaneLayers);
  EXPECT_EQ(io.clear_value[0], pack_rgba(bg));
  EXPECT_EQ(io.clear_value[1], depth_max(kRtlDepthBits));
  EXPECT_EQ(io.clear_value[2], 0u);
  EXPECT_EQ(io.clear_value[3], 0u);
  EXPECT_EQ(io.accum_clear, AccumWord{});  // the accumulation is not cleared: untouched
  TileStates::GroupStep resolve;
  resolve.op = FrameOp{FrameOpKind::kResolveLayers, Rgba8{}, 0, false};
  const std::vector<TileStates::GroupStep> steps = {layers, resolve};
  const TileStates::RunPlan run = frame.plan_tile(0, steps.data(), steps.size());
  EXPECT_EQ(run.resolve, StoreResolve::kLayers);
  EXPECT_EQ(run.store, kPlaneColor);
  EXPECT_EQ(run.steps.at(0).io.clear, kPlaneColor | kPlaneDepth | kPlaneLayers);
  EXPECT_FALSE(run.closing_setup());
  frame.stored(0, kPlaneColor | kPlaneDepth | kPlaneLayers);  // the layers stay cleared
  const TileIo after = frame.plan(0, layers.state);
  EXPECT_EQ(after.load, kPlaneColor | kPlaneDepth);
  EXPECT_EQ(after.clear, kPlaneLayers);
  EXPECT_EQ(port_planes(after.clear), 0);  // tile_mlab_i carries it, not tile_planes_i
}

// The resolve under the background is a step as well: it closes the group and the store
// applies it; nothing needs to be resident for it but the colour the group made.
TEST(TileStates, ResolveUnderTheBackgroundClosesTheGroup) {
  TileStates frame(64, 64, 64, kRtlDepthBits, Rgba8{0, 0, 0, 0});
  TileStates::GroupStep opaque;
  opaque.pass = opaque.touches = true;
  TileStates::GroupStep under;
  under.op = FrameOp{FrameOpKind::kResolveUnder, Rgba8{1, 2, 3, 4}, 0, false};
  std::vector<TileStates::GroupStep> steps = {opaque};
  EXPECT_FALSE(TileStates::closed(steps));
  EXPECT_EQ(frame.plan_tile(0, steps.data(), steps.size()).resolve, StoreResolve::kNone);
  steps.push_back(under);
  EXPECT_TRUE(TileStates::closed(steps));
  const TileStates::RunPlan run = frame.plan_tile(0, steps.data(), steps.size());
  EXPECT_EQ(run.resolve, StoreResolve::kUnder);
  EXPECT_FALSE(run.closing_setup());
  EXPECT_EQ(run.preload_after, 0);
  EXPECT_EQ(run.store, kPlaneColor | kPlaneDepth);
}

// zb_resolve_wboit divides by one = 2^R - 1 as (x + 1 + (x >> R)) >> R: exact for every x the
// resolve makes (x < 256 * one) at every R zb_rop allows (REV_BITS 8..16).
TEST(ZbResolveWboit, DivisionByOneIsAShiftedSum) {
  for (uint32_t bits = 8; bits <= 16; ++bits) {
    const uint64_t one = (uint64_t{1} << bits) - 1;
    uint64_t wrong = 0;
    for (uint64_t x = 0; x < 256 * one; ++x) wrong += ((x + 1 + (x >> bits)) >> bits) != x / one;
    EXPECT_EQ(wrong, 0u) << "REV_BITS " << bits;
  }
}

}  // namespace
}  // namespace zb
