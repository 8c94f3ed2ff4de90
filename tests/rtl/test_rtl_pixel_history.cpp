// A pixel's history beside the RTL (tb/rtlmodel/pixel_retires.h, zblend pixel --backend rtl): on
// zb_rop every fragment at every pixel of small frames retires once at X4 and once at X11, after
// it was accepted, with the golden model's writes, and the RTL's final value is the golden
// model's. Built against the bug build (ZB_DEFECT: red bit 0 flipped on alpha blends with an odd
// source alpha) the same histories name the defect's writes as mismatches.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "history/history_report.h"
#include "history/pixel_history.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "pixel_retires.h"
#include "rtl_params.h"
#include "scene/builtin_scenes.h"

namespace zb {
namespace {

struct Tally {
  size_t fragments = 0, retires = 0, mismatches = 0, odd = 0;
};

Tally run(const char* scene, const char* method, TileSchedule schedule) {
  const RasterizedScene rs = rasterize_scene(*builtin_scene(scene), Viewport{48, 36, kRtlDepthBits});
  std::vector<std::pair<int, int>> all;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 48; ++x) all.emplace_back(x, y);
  const PassPlan& plan = *find_plan(method);
  FrameHistory f = record_history(rs, plan, all);
  RtlOptions o;
  o.schedule = schedule;
  add_rtl_retires(f, o, [&](Backend& b) { render(rs, plan, b); });
  Tally t;
  for (const PixelHistory& h : f.pixels) {
    EXPECT_TRUE(h.rtl_ran);
    for (const RetireRecord& r : h.rtl) EXPECT_FALSE(r.extra || r.missing) << h.x << "," << h.y;
    t.retires += h.rtl.size();
    t.odd += h.rtl_final != h.final_value;
    for (const HistoryEvent& e : h.events) {
      if (e.kind != HistoryEvent::Kind::kFragment) continue;
      ++t.fragments;
      int stages[2] = {0, 0};
      for (const RetireRecord& r : h.rtl) {
        if (r.pass != e.pass || r.index != e.fragment.index) continue;
        ++stages[r.x11];
        EXPECT_GT(r.cycle, r.accepted);
        if (!same_stage_writes(r, e.fragment.writes)) {
          ++t.mismatches;
          EXPECT_NE(history_text(f, h).find("MISMATCH: the RTL wrote"), std::string::npos);
        }
      }
      EXPECT_EQ(stages[0], 1) << scene << " " << method << " (" << h.x << ", " << h.y << ")";
      EXPECT_EQ(stages[1], 1) << scene << " " << method << " (" << h.x << ", " << h.y << ")";
    }
  }
  return t;
}

#ifndef ZB_DEFECT
TEST(RtlPixelHistory, EveryFragmentRetiresOnceAtEachStageWithTheGoldenWrites) {
  for (const TileSchedule s : {TileSchedule::kTile, TileSchedule::kPass})
    for (const char* method : {"three-pass", "depth-peel-2", "wboit", "coverage-aa", "hidden-line"}) {
      const Tally t = run("cad", method, s);
      EXPECT_GT(t.fragments, 500u) << method;
      EXPECT_EQ(t.retires, 2 * t.fragments) << method;
      EXPECT_EQ(t.mismatches, 0u) << method;
      EXPECT_EQ(t.odd, 0u) << method;  // the RTL's final planes are the golden model's
    }
}
#else
TEST(RtlPixelHistory, TheBugBuildsBlendDefectShowsAsMismatches) {
  const Tally t = run("cad", "three-pass", TileSchedule::kTile);
  EXPECT_GT(t.mismatches, 10u) << t.fragments << " fragments";
  EXPECT_GT(t.odd, 10u);
  EXPECT_LT(t.mismatches, t.fragments / 2);  // only the defect's case: odd-alpha alpha blends
}
#endif

}  // namespace
}  // namespace zb
