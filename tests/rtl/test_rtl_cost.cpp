// The cost model (app/lab/sizing_cost.h, behind `zblend plan`) against the RTL itself: on every
// built-in scene x every pass plan, under both schedules, the streaming and tile cycles it
// predicts at the RTL's tile size are the ones the Verilated zb_rop takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/trace.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rtl_params.h"
#include "rop/rop.h"
#include "rtl_rop.h"
#include "metrics/scene_analysis.h"
#include "scene/builtin_scenes.h"
#include "sizing_cost.h"

namespace zb {
namespace {

// Any build's tile size is costed (a lab run on a 128 x 128 build needs its own), once.
TEST(CostModel, CountsTheAnalysedSizesAndTheBuiltOne) {
  const std::vector<int> sizes = cost_tile_sizes();
  for (const int size : kAnalysisTileSizes)
    EXPECT_EQ(std::count(sizes.begin(), sizes.end(), size), 1) << size;
  EXPECT_EQ(std::count(sizes.begin(), sizes.end(), kRtlTileW), 1);
}

TEST(CostModel, EqualsTheRtlOnEveryBuiltinSceneAndMethod) {
  for (const SceneInfo& info : builtin_scenes()) {
    const RasterizedScene rs =
        rasterize_scene(*builtin_scene(info.name), Viewport{160, 120, kRtlDepthBits});
    for (const PassPlan& plan : pass_plans())
      for (const TileSchedule sched : {TileSchedule::kPass, TileSchedule::kTile}) {
        RtlOptions o;
        o.schedule = sched;
        RtlRop rtl(o);
        CostCounter counter(rtl);
        const uint64_t start = rtl.total_cycles();  // reset and the first sweep
        const RenderResult r = render(rs, plan, counter);
        uint64_t stream = 0;
        for (const PassStats& s : r.passes) stream += s.cycles;
        const TileCost& c = counter.cost().at(kRtlTileW);
        const std::string what =
            std::string(info.name) + " x " + plan.name + " under the " + to_string(sched) + " schedule";
        EXPECT_EQ(c.stream_cycles, stream) << what << ": streaming cycles";
        EXPECT_EQ(c.io_cycles(sched), rtl.tile_io_cycles()) << what << ": tile cycles";
        EXPECT_EQ(stream + rtl.tile_io_cycles(), rtl.total_cycles() - start)
            << what << ": every cycle is a stream's or the tile port's";
        // Two buffers (the proposed design) hide port cycles, never streaming ones, and never
        // add any: between the streams alone and the one-buffer run.
        if (sched == TileSchedule::kTile) {
          EXPECT_GE(c.resident.two_buffer_cycles, stream) << what << ": two buffers";
          EXPECT_LE(c.resident.two_buffer_cycles, stream + c.resident.io_cycles) << what << ": two buffers";
        }
      }
  }
}

// A tile's worth of a pattern: colour by position, depth mid-range so that depth tests go
// both ways against it.
RegionLoad pattern_region(int x0, int y0, int w, int h, bool depth) {
  RegionLoad r;
  r.x0 = x0, r.y0 = y0, r.width = w, r.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      r.color.push_back(Rgba8{uint8_t(x * 3), uint8_t(y * 5), 77, uint8_t(128 + x)});
      if (depth) r.depth.push_back(uint32_t(depth_max(kRtlDepthBits) / 2 + uint32_t(x * y * 97)));
    }
  return r;
}

// `t` replayed with region loads (the virtual platform's TILE_LOAD): a tile of colour and
// depth before the first pass, the frame's last (clipped) tile's colour after the first pass
// when `mid`.
void replay_with_loads(const Trace& t, Backend& b, bool mid) {
  b.begin_frame(t.width, t.height, t.depth_bits, t.clear_color, t.coverage_samples, t.wboit);
  b.load_region(pattern_region(kRtlTileW, 0, std::min(kRtlTileW, t.width - kRtlTileW),
                               std::min(kRtlTileH, t.height), true));
  std::vector<PassStats> stats;
  for (size_t k = 0; k < t.passes.size(); ++k) {
    const TracePass& p = t.passes[k];
    for (const FrameOp& op : p.frame_ops) b.frame_op(op);
    b.begin_pass(p.state);
    b.draw(p.fragments);
    stats.push_back(b.end_pass());
    if (k == 0 && mid) {
      const int x0 = (t.width - 1) / kRtlTileW * kRtlTileW, y0 = (t.height - 1) / kRtlTileH * kRtlTileH;
      b.load_region(pattern_region(x0, y0, t.width - x0, t.height - y0, false));
    }
  }
  for (const FrameOp& op : t.final_ops) b.frame_op(op);
  b.finish_frame(stats);
}

// Region loads between passes: the golden model and the RTL make the same frame, and the cost
// model counts the RTL's cycles (a loaded tile's planes are loaded at its next pass).
TEST(CostModel, EqualsTheRtlWithRegionLoads) {
  int runs = 0;
  for (const char* scene : {"cad", "parts"}) {
    const RasterizedScene rs =
        rasterize_scene(*builtin_scene(scene), Viewport{160, 120, kRtlDepthBits});
    ASSERT_GT(rs.viewport.width, kRtlTileW) << "two tiles across at least";
    for (const PassPlan& plan : pass_plans()) {
      const Trace t = make_trace(rs, plan);
      // The RTL's layers never leave the tile before their resolve: no load between.
      bool layers = false;
      for (const TracePass& p : t.passes) layers |= p.state.blend == BlendMode::kLayers;
      GoldenRop golden;
      replay_with_loads(t, golden, !layers);
      for (const TileSchedule sched : {TileSchedule::kPass, TileSchedule::kTile}) {
        RtlOptions o;
        o.schedule = sched;
        RtlRop rtl(o);
        CostCounter counter(rtl);
        const uint64_t start = rtl.total_cycles();
        replay_with_loads(t, counter, !layers);
        const std::string what =
            std::string(scene) + " x " + plan.name + " under the " + to_string(sched) + " schedule";
        const TileCost& c = counter.cost().at(kRtlTileW);
        EXPECT_EQ(c.stream_cycles + c.io_cycles(sched), rtl.total_cycles() - start) << what;
        EXPECT_EQ(c.io_cycles(sched), rtl.tile_io_cycles()) << what << ": tile cycles";
        EXPECT_TRUE(rtl.framebuffer().color == golden.framebuffer().color &&
                    rtl.framebuffer().depth == golden.framebuffer().depth)
            << what << ": the frame differs from the golden model's";
        ++runs;
      }
    }
  }
  EXPECT_GT(runs, 0);
}

}  // namespace
}  // namespace zb
