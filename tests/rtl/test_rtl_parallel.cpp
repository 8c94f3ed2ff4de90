// Tile-parallel RTL runs (RtlOptions::threads): 1, 2 and 3 models give the same planes, pass
// counters, cycles, accept cycles and tile runs, with back-pressure, on multi-pass methods with
// frame operations between passes.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rtl_params.h"
#include "rtl_rop.h"
#include "scene/builtin_scenes.h"

namespace zb {
namespace {

struct ModelRun {
  Framebuffer fb;
  std::vector<PassStats> passes;
  uint64_t total = 0, io = 0, stalls = 0;
  std::vector<uint64_t> accepted;  // the last pass's
  std::vector<TileRun> tiles;      // the last pass's
};

ModelRun render_on(const RasterizedScene& rs, const PassPlan& plan, int threads) {
  RtlOptions o;
  o.threads = threads;
  o.backpressure = 0.2;
  o.seed = 7;
  RtlRop rtl(o);
  ModelRun r;
  r.passes = render(rs, plan, rtl).passes;
  r.fb = rtl.framebuffer();
  r.total = rtl.total_cycles();
  r.io = rtl.tile_io_cycles();
  r.stalls = rtl.stall_cycles();
  r.accepted = rtl.accept_cycles();
  r.tiles = rtl.tile_runs();
  return r;
}

void expect_same(const ModelRun& a, const ModelRun& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.fb.color, b.fb.color);
  EXPECT_EQ(a.fb.depth, b.fb.depth);
  EXPECT_EQ(a.fb.coverage, b.fb.coverage);
  EXPECT_EQ(a.fb.peel, b.fb.peel);
  EXPECT_EQ(a.fb.accum, b.fb.accum);
  EXPECT_EQ(a.fb.reveal, b.fb.reveal);
  ASSERT_EQ(a.passes.size(), b.passes.size());
  for (size_t p = 0; p < a.passes.size(); ++p) {
    EXPECT_EQ(a.passes[p].fragments_in, b.passes[p].fragments_in) << "pass " << p;
    EXPECT_EQ(a.passes[p].fragments_passed, b.passes[p].fragments_passed) << "pass " << p;
    EXPECT_EQ(a.passes[p].color_reads, b.passes[p].color_reads) << "pass " << p;
    EXPECT_EQ(a.passes[p].color_writes, b.passes[p].color_writes) << "pass " << p;
    EXPECT_EQ(a.passes[p].depth_reads, b.passes[p].depth_reads) << "pass " << p;
    EXPECT_EQ(a.passes[p].depth_writes, b.passes[p].depth_writes) << "pass " << p;
    EXPECT_EQ(a.passes[p].cycles, b.passes[p].cycles) << "pass " << p;
  }
  EXPECT_EQ(a.total, b.total);
  EXPECT_EQ(a.io, b.io);
  EXPECT_EQ(a.stalls, b.stalls);
  EXPECT_EQ(a.accepted, b.accepted);
  ASSERT_EQ(a.tiles.size(), b.tiles.size());
  for (size_t t = 0; t < a.tiles.size(); ++t) {
    const TileRun &x = a.tiles[t], &y = b.tiles[t];
    EXPECT_EQ(x.x0, y.x0);
    EXPECT_EQ(x.y0, y.y0);
    EXPECT_EQ(x.load_begin, y.load_begin) << "tile " << t;
    EXPECT_EQ(x.stream_begin, y.stream_begin) << "tile " << t;
    EXPECT_EQ(x.stream_end, y.stream_end) << "tile " << t;
    EXPECT_EQ(x.store_end, y.store_end) << "tile " << t;
    EXPECT_EQ(x.stall_cycles, y.stall_cycles) << "tile " << t;
    EXPECT_EQ(x.load_beats, y.load_beats) << "tile " << t;
    EXPECT_EQ(x.store_beats, y.store_beats) << "tile " << t;
  }
}

struct Method {
  const char* name;
  size_t last_pass_tiles;  // at least this many tiles in the last pass (depth-peel-2's is small)
};

void PrintTo(const Method& m, std::ostream* os) { *os << m.name; }

class RtlParallel : public ::testing::TestWithParam<Method> {};

TEST_P(RtlParallel, OneTwoThreeModelsAgree) {
  // Several tiles in each direction, the last row and column clipped by the frame.
  const RasterizedScene rs = rasterize_scene(
      *builtin_scene("cad"), Viewport{5 * kRtlTileW / 2, 3 * kRtlTileH / 2, kRtlDepthBits});
  const PassPlan* plan = find_plan(GetParam().name);
  ASSERT_NE(plan, nullptr);
  const ModelRun one = render_on(rs, *plan, 1);
  ASSERT_GE(one.tiles.size(), GetParam().last_pass_tiles) << "more tiles than models, to share";
  // Cycles are one model's: every tile back to back after reset and the first sweep.
  uint64_t last = 0;
  for (const TileRun& t : one.tiles) {
    if (last) {
      EXPECT_EQ(t.load_begin, last);
    }
    last = t.store_end;
  }
  EXPECT_EQ(one.total, last);
  expect_same(one, render_on(rs, *plan, 2), "2 models");
  expect_same(one, render_on(rs, *plan, 3), "3 models");
}

INSTANTIATE_TEST_SUITE_P(Methods, RtlParallel,
                         ::testing::Values(Method{"three-pass", 4}, Method{"depth-peel-2", 1},
                                           Method{"hidden-line-dim", 4},
                                           Method{"wboit", 4}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace zb
