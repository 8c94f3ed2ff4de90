// The lock-step monitor and scoreboard on hand-made retire-port cycles (no RTL): which fragment
// each retire names, extra and missing retires, and what the scoreboard keeps.
#include <gtest/gtest.h>

#include <vector>

#include "retire_monitor.h"
#include "scoreboard.h"

namespace zb {
namespace {

struct Recorder final : RetireSink {
  std::vector<Retire> seen;
  bool retire(const Retire& r) override {
    seen.push_back(r);
    return r.kind == Retire::Kind::kRetired;
  }
  bool store(const StoreBeat&) override { return true; }
};

RetirePort x4(uint32_t addr, bool dwe = false, uint32_t z = 0) {
  RetirePort p;
  p.x4_valid = true;
  p.x4_addr = addr;
  p.dwe = dwe;
  p.wdepth = z;
  return p;
}
RetirePort x11(uint32_t addr, bool cwe = false, uint32_t rgba = 0) {
  RetirePort p;
  p.x11_valid = true;
  p.x11_addr = addr;
  p.cwe = cwe;
  p.wcolor = rgba;
  return p;
}

// Three fragments, two to word 5 and one to word 9 (tile origin (32, 64)), pass indices 10..12.
struct Stream {
  std::vector<uint32_t> addr{5, 9, 5}, index{10, 11, 12};
};

TEST(RetireMonitor, KthRetireAtAPixelIsItsKthFragment) {
  Recorder sink;
  RetireMonitor m(sink);
  Stream s;
  m.begin_tile(32, 64, s.addr.data(), s.index.data(), 3);
  EXPECT_TRUE(m.observe(x4(9, true, 7), 10, 3));  // past the older fragment to word 5
  EXPECT_TRUE(m.observe(x4(5), 11, 3));
  EXPECT_TRUE(m.observe(x4(5), 12, 3));
  ASSERT_EQ(sink.seen.size(), 3u);
  EXPECT_EQ(sink.seen[0].fragment, 11u);
  EXPECT_EQ(sink.seen[0].x, 32 + 9 % kRtlTileW);
  EXPECT_EQ(sink.seen[0].y, 64 + 9 / kRtlTileW);
  EXPECT_TRUE(sink.seen[0].writes.depth);
  EXPECT_EQ(sink.seen[0].writes.z, 7u);
  EXPECT_EQ(sink.seen[0].tile_cycle, 10u);
  EXPECT_EQ(sink.seen[1].fragment, 10u);
  EXPECT_EQ(sink.seen[2].fragment, 12u);
  // X11 keeps its own order: its first retire at word 5 is fragment 10 again.
  EXPECT_TRUE(m.observe(x11(5, true, 0x04030201), 13, 3));
  EXPECT_EQ(sink.seen.back().fragment, 10u);
  EXPECT_EQ(sink.seen.back().stage, RetireStage::kX11);
  EXPECT_EQ(sink.seen.back().writes.rgba.g, 2);
}

TEST(RetireMonitor, RetireOfAFragmentNotYetAcceptedIsExtra) {
  Recorder sink;
  RetireMonitor m(sink);
  Stream s;
  m.begin_tile(0, 0, s.addr.data(), s.index.data(), 3);
  EXPECT_TRUE(m.observe(x4(5), 1, 1));      // fragment 10, accepted
  EXPECT_FALSE(m.observe(x4(5), 2, 2));     // fragment 12 is the third: not accepted yet
  EXPECT_EQ(sink.seen.back().kind, Retire::Kind::kExtra);
  EXPECT_FALSE(m.observe(x4(9), 3, 3));     // the sink said stop: nothing more goes to it
  EXPECT_EQ(sink.seen.size(), 2u);
}

TEST(RetireMonitor, WriteWithoutAFragmentOrAtAnEmptyPixelIsExtra) {
  for (const RetirePort& p : {x4(17), [] {
                                RetirePort q;  // a depth write with X4 empty
                                q.dwe = true;
                                q.x4_addr = 5;
                                return q;
                              }()}) {
    Recorder sink;
    RetireMonitor m(sink);
    Stream s;
    m.begin_tile(0, 0, s.addr.data(), s.index.data(), 3);
    EXPECT_FALSE(m.observe(p, 1, 3));
    ASSERT_EQ(sink.seen.size(), 1u);
    EXPECT_EQ(sink.seen[0].kind, Retire::Kind::kExtra);
    EXPECT_EQ(sink.seen[0].fragment, Retire::kNoFragment);
  }
}

TEST(RetireMonitor, FragmentNotRetiredByTheDrainIsMissing) {
  Recorder sink;
  RetireMonitor m(sink);
  Stream s;
  m.begin_tile(0, 0, s.addr.data(), s.index.data(), 3);
  for (uint32_t a : {5u, 9u, 5u}) EXPECT_TRUE(m.observe(x4(a), 1, 3));
  EXPECT_TRUE(m.observe(x11(5), 2, 3));
  EXPECT_FALSE(m.end_tile(40));
  ASSERT_EQ(sink.seen.size(), 5u);
  EXPECT_EQ(sink.seen[4].kind, Retire::Kind::kMissing);
  EXPECT_EQ(sink.seen[4].stage, RetireStage::kX11);
  EXPECT_EQ(sink.seen[4].fragment, 11u);  // the first one in stream order not retired at X11
  EXPECT_EQ(sink.seen[4].tile_cycle, 40u);
}

TEST(RetireMonitor, CleanTileEndsQuietly) {
  Recorder sink;
  RetireMonitor m(sink);
  Stream s;
  m.begin_tile(0, 0, s.addr.data(), s.index.data(), 3);
  for (uint32_t a : {5u, 9u, 5u}) EXPECT_TRUE(m.observe(x4(a), 1, 3));
  for (uint32_t a : {9u, 5u, 5u}) EXPECT_TRUE(m.observe(x11(a), 2, 3));
  EXPECT_TRUE(m.end_tile(9));
  EXPECT_EQ(sink.seen.size(), 6u);
}

Retire retired(uint32_t fragment, RetireStage stage, PixelWrites w, int tile_x0, uint64_t cycle) {
  Retire r;
  r.fragment = fragment;
  r.stage = stage;
  r.writes = w;
  r.tile_x0 = tile_x0;
  r.tile_cycle = cycle;
  return r;
}

TEST(Scoreboard, ComparesOnlyTheStagesPlanesAndKeepsTheEarliest) {
  Scoreboard sb;
  sb.begin_pass();
  PixelWrites g;
  g.depth = true;
  g.z = 0x123;
  g.color = true;
  g.rgba = {1, 2, 3, 4};
  sb.expect(g);
  sb.expect(g);
  Framebuffer fb(8, 8, 24, Rgba8{0, 0, 0, 255}, 16);
  sb.arm(fb);
  PixelWrites x4w;
  x4w.depth = true;
  x4w.z = 0x123;
  EXPECT_TRUE(sb.retire(retired(0, RetireStage::kX4, x4w, 0, 5)));  // colour is X11's
  EXPECT_FALSE(sb.first());
  PixelWrites bad = x4w;
  bad.z = 0x124;
  EXPECT_FALSE(sb.retire(retired(1, RetireStage::kX4, bad, 32, 3)));  // a later tile
  ASSERT_TRUE(sb.first());
  EXPECT_NE(sb.first()->what.find("rtl wrote depth 0x000124, no coverage; golden depth 0x000123, no coverage"),
            std::string::npos)
      << sb.first()->what;
  PixelWrites none;  // X11 wrote nothing where the golden model wrote colour
  EXPECT_FALSE(sb.retire(retired(0, RetireStage::kX11, none, 0, 12)));
  EXPECT_EQ(sb.first()->retire.tile_x0, 0);  // tile 0 runs first in one model's time
  EXPECT_EQ(sb.first()->retire.fragment, 0u);
  EXPECT_NE(sb.first()->what.find("rtl wrote no colour; golden colour rgba(1,2,3,4)"),
            std::string::npos)
      << sb.first()->what;
  EXPECT_EQ(sb.rtl()[0].cycle[0], 5u);
}

TEST(Scoreboard, StoredBeatAgainstTheGoldenFrameWithinTheFrameOnly) {
  Scoreboard sb;
  sb.begin_pass();
  const int w = kRtlBeat + 1;  // the second beat of the row has one lane in the frame
  Framebuffer fb(w, 2, 24, Rgba8{9, 9, 9, 255}, 16);
  sb.arm(fb);
  const TileSweep sweep(fb.width, fb.height, 0, 0);
  BeatWords words = sweep.load(fb, 1);
  words[0][1] = 0xdeadbeef;  // beyond the frame's edge: not compared
  EXPECT_TRUE(sb.store(StoreBeat{0, 0, 1, kPlaneColor | kPlaneDepth, 30, &words}));
  words[1][0] ^= 1;  // lane 0's depth
  EXPECT_FALSE(sb.store(StoreBeat{0, 0, 1, kPlaneColor | kPlaneDepth, 31, &words}));
  ASSERT_TRUE(sb.first());
  EXPECT_TRUE(sb.first()->store);
  EXPECT_EQ(sb.first()->retire.x, kRtlBeat);
  EXPECT_EQ(sb.first()->retire.y, 0);
  EXPECT_NE(sb.first()->what.find("depth"), std::string::npos) << sb.first()->what;
}

}  // namespace
}  // namespace zb
