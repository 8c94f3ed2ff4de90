// The suite's reach on the golden model (conformance/reach.h) on streams worked by hand, and the
// generator's claims held to it.
#include <gtest/gtest.h>

#include <set>

#include "generate.h"
#include "reach.h"
#include "suite.h"

namespace zb::conformance {
namespace {

RopState alpha_less() {
  RopState s;
  s.depth_test = true;
  s.depth_func = DepthFunc::kLess;
  s.depth_write = true;
  s.blend = BlendMode::kAlpha;
  s.color_mask = kMaskRgba;
  return s;
}

Fragment at(int x, int y, uint32_t z, Rgba8 c = {200, 100, 50, 128}) {
  Fragment f;
  f.x = uint16_t(x);
  f.y = uint16_t(y);
  f.z = z;
  f.color = c;
  return f;
}

// A 4 x 4 frame, one alpha pass: (1,1) at depth 100, (1,1) again nearer, (2,2) at the far depth.
Trace small() {
  Trace t;
  t.width = 4;
  t.height = 4;
  t.depth_bits = 24;
  t.coverage_samples = 16;
  t.clear_color = {10, 20, 30, 40};
  t.passes.push_back({"p", {}, alpha_less(), {at(1, 1, 100), at(1, 1, 50), at(2, 2, 0xffffff)}});
  return t;
}

uint64_t get(const BinCounts& b, const std::string& name) {
  const auto it = b.find(name);
  return it == b.end() ? 0 : it->second;
}

TEST(Reach, HandWorkedStream) {
  const BinCounts b = trace_reach(small(), DutShape{});
  EXPECT_EQ(get(b, "pass_state[depth=less,write=1,blend=alpha,mask=f,peel=0]"), 3u);
  // Stored far depth, then 100: less, less; the far depth against itself: equal.
  EXPECT_EQ(get(b, "depth_compare[func=less,relation=less]"), 2u);
  EXPECT_EQ(get(b, "depth_compare[func=less,relation=equal]"), 1u);
  EXPECT_EQ(get(b, "frag_depth.max"), 1u);
  EXPECT_EQ(get(b, "frag_depth.zero"), 0u);
  EXPECT_EQ(get(b, "same_pixel[distance=1,between=Calm]"), 1u);
  EXPECT_EQ(get(b, "frag_in_tile[row=inside,col=inside]"), 3u);  // a 64 x 64 tile
  EXPECT_EQ(get(b, "tile_origin.first"), 3u);
  EXPECT_EQ(get(b, "frame_ops.state_write"), 1u);  // one tile loaded
  EXPECT_EQ(get(b, "goal.same_pixel_rmw[blend=alpha,distance=1]"), 1u);
  // The alpha blend of (200,100,50,128) onto (10,20,30,40) changes every channel.
  EXPECT_EQ(get(b, "goal.state_relation[depth=less,write=1,blend=alpha,mask=f,peel=0,relation=less]"), 2u);
}

TEST(Reach, TileShapeMovesPositionsAndOrigins) {
  DutShape two;
  two.tile_w = two.tile_h = 2;
  const BinCounts b = trace_reach(small(), two);
  EXPECT_EQ(get(b, "frag_in_tile[row=bottom,col=right]"), 2u);  // (1,1) in the tile at (0,0)
  EXPECT_EQ(get(b, "frag_in_tile[row=top,col=left]"), 1u);      // (2,2) in the tile at (2,2)
  EXPECT_EQ(get(b, "tile_origin.first"), 2u);
  EXPECT_EQ(get(b, "tile_origin.inner"), 1u);
  EXPECT_EQ(get(b, "frame_ops.state_write"), 2u);  // two tiles loaded
  // A new tile is loaded between them: the gap of a load.
  EXPECT_EQ(get(b, "goal.tile_position[tile=16,row=inside,col=inside]"), 3u);
}

TEST(Reach, GapsMoveDistancesBetweenCalmAndGapOnly) {
  const Trace t = states_trace(BlendMode::kAlpha, false, 24, 16);
  const Trace runs = same_pixel_trace(BlendMode::kAdditive, 24, 16);
  for (const Trace* tr : {&t, &runs}) {
    DutShape calm, gaps;
    gaps.gap_pct = 40;
    const BinCounts a = trace_reach(*tr, calm), g = trace_reach(*tr, gaps);
    uint64_t calm_gap = 0, any_gap = 0;
    for (int d = 1; d <= 9; ++d) {
      const std::string p = "same_pixel[distance=" + std::to_string(d) + ",between=";
      EXPECT_EQ(get(a, p + "Calm]") + get(a, p + "Gap]"), get(g, p + "Calm]") + get(g, p + "Gap]"));
      calm_gap += get(a, p + "Gap]");
      any_gap += get(g, p + "Gap]");
    }
    EXPECT_GE(any_gap, calm_gap);
    // Everything the stream decides stays.
    for (const auto& [bin, n] : a) {
      if (bin.rfind("same_pixel", 0) != 0 && bin.rfind("goal.same_pixel", 0) != 0) {
        EXPECT_EQ(get(g, bin), n) << bin;
      }
    }
  }
  // The runs' 40 % gaps do break some: fewer back-to-back same-pixel runs than with none.
  DutShape gaps;
  gaps.gap_pct = 40;
  EXPECT_LT(get(trace_reach(runs, gaps), "goal.same_pixel_rmw[blend=additive,distance=16]"),
            get(trace_reach(runs, DutShape{}), "goal.same_pixel_rmw[blend=additive,distance=16]"));
}

TEST(Reach, ResidentScheduleKeepsTheStreamsBins) {
  const Trace t = tiles_trace(24, 16);
  DutShape pass, resident;
  resident.resident = true;
  pass.tile_w = pass.tile_h = resident.tile_w = resident.tile_h = 32;
  const BinCounts a = trace_reach(t, pass), b = trace_reach(t, resident);
  for (const auto& [bin, n] : a) {
    if (bin.find("same_pixel") == std::string::npos && bin != "frame_ops.state_write" &&
        bin.rfind("store.", 0) != 0 && bin.rfind("plane_ops", 0) != 0) {
      EXPECT_EQ(get(b, bin), n) << bin;
    }
  }
  // One load a tile instead of one a pass and tile: half the state writes' tiles.
  EXPECT_EQ(get(a, "store.first_beat"), 2 * get(b, "store.first_beat"));
  // The second pass's state written on each resident tile: a pass boundary there, never under
  // the pass schedule (a load before every pass's first fragment).
  EXPECT_EQ(get(a, "pass_resident.boundary"), 0u);
  EXPECT_EQ(get(b, "pass_resident.boundary"), get(b, "store.first_beat"));
}

TEST(Reach, Visibility) {
  StoredPixel p;
  p.color = {10, 20, 30, 40};
  p.depth = 1000;
  p.reveal = 255;
  RopState s = alpha_less();
  EXPECT_TRUE(visible(s, at(0, 0, 10), p, 24, 16, {}));
  // Alpha 0 leaves the pixel as it was: a mask or a blend defect cannot show.
  EXPECT_FALSE(visible(s, at(0, 0, 10, {200, 100, 50, 0}), p, 24, 16, {}));
  s.blend = BlendMode::kReplace;
  EXPECT_TRUE(visible(s, at(0, 0, 10, {200, 100, 50, 0}), p, 24, 16, {}));
  EXPECT_FALSE(visible(s, at(0, 0, 10, {10, 100, 50, 0}), p, 24, 16, {}));  // red unchanged
  s.blend = BlendMode::kAccumulate;
  EXPECT_TRUE(visible(s, at(0, 0, 10, {200, 100, 50, 128}), p, 24, 16, {}));
  EXPECT_FALSE(visible(s, at(0, 0, 10, {0, 100, 50, 128}), p, 24, 16, {}));  // red adds nothing
}

TEST(Reach, GeneratorMeetsItsGoals) {
  // Every state of a family meets all three relations, visibly.
  for (unsigned b = 0; b < kCoreBlendModes; ++b)
    for (bool peel : {false, true}) {
      const BinCounts r = trace_reach(states_trace(BlendMode(b), peel, 24, 16), DutShape{});
      size_t goals = 0;
      for (const auto& [bin, n] : r)
        goals += bin.rfind("goal.state_relation[", 0) == 0 &&
                 bin.find(std::string("blend=") + to_string(BlendMode(b)) + ",") != std::string::npos &&
                 bin.find(peel ? "peel=1" : "peel=0") != std::string::npos;
      EXPECT_EQ(goals, 288u * 3) << to_string(BlendMode(b)) << " peel " << peel;
    }
  for (int bits : {16, 24, 32}) {
    const BinCounts r = trace_reach(depth_bits_trace(bits, 16), DutShape{});
    size_t n = 0;
    for (const auto& [bin, c] : r) n += bin.rfind("goal.depth_bit[", 0) == 0;
    EXPECT_EQ(n, size_t(2 * bits)) << bits;
  }
}

TEST(Reach, BinListsAndRanking) {
  const BinList l = reach_bins(DutShape{});
  // The plan's kit-reachable bins (with pass_resident.boundary and the layers unit's 23).
  EXPECT_EQ(l.plan.size(), 3577u);
  EXPECT_EQ(std::set<std::string>(l.plan.begin(), l.plan.end()).size(), l.plan.size());
  EXPECT_EQ(std::set<std::string>(l.goals.begin(), l.goals.end()).size(), l.goals.size());
  DutShape w4;
  w4.window = 4;
  EXPECT_EQ(reach_bins(w4).plan.size(), 3577u - 2 * 4);  // distances 1..5, not 1..9
  // Test 1 holds all that 0 has and more; 2 adds one: 1, then 2, and 0 adds nothing.
  const std::vector<BinCounts> r = {{{"a", 1}}, {{"a", 1}, {"b", 3}}, {{"c", 1}}};
  const auto order = rank_tests(r, {"a", "b", "c"});
  ASSERT_EQ(order.size(), 2u);
  EXPECT_EQ(order[0], std::make_pair(size_t(1), size_t(2)));
  EXPECT_EQ(order[1], std::make_pair(size_t(2), size_t(1)));
}

}  // namespace
}  // namespace zb::conformance
