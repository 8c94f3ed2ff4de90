// The cost model (app/lab/sizing_cost.h, behind `zblend plan`) against the RTL itself: on every
// built-in scene x every pass plan, under both schedules, the streaming and tile cycles it
// predicts at the RTL's tile size are the ones the Verilated zb_rop takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rtl_params.h"
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

}  // namespace
}  // namespace zb
