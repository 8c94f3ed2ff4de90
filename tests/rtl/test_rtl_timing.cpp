// zb_rop's timing facts (tb/rtlmodel/rtl_timing.h), the source of the cost model and the SystemC
// golden module, against the RTL itself: the constants zb_rop.sv declares, read from the
// Verilated model, and the cycles a tile's stream takes, measured.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "Vzb_rop.h"
#include "Vzb_rop_zb_rop.h"
#include "rtl_rop.h"
#include "rtl_timing.h"

namespace zb {
namespace {

// Span: the same-pixel issue distance; Last: the X stage the write leaves from, so busy_o
// falls Last + 1 cycles after an issue.
TEST(RtlTiming, ConstantsAreTheRtls) {
  EXPECT_EQ(uint64_t{Vzb_rop_zb_rop::Span}, kRtlIssueSpan) << "zb_rop.sv Span";
  EXPECT_EQ(uint64_t{Vzb_rop_zb_rop::Last} + 1, kRtlDrain) << "zb_rop.sv Last (the drain)";
  EXPECT_EQ(unsigned{Vzb_rop_zb_rop::WINDOW}, kRtlWindow) << "zb_rop.sv WINDOW";
}

// The streaming cycles of one pass of `fragments` on one tile, as the RTL counts them.
uint64_t stream_cycles(const std::vector<Fragment>& fragments) {
  RtlRop rtl;
  rtl.begin_frame(kRtlTileW, kRtlTileH, kRtlDepthBits, Rgba8{0, 0, 0, 0});
  RopState state;
  state.depth_test = false;
  rtl.begin_pass(state);
  rtl.draw(fragments);
  return rtl.end_pass().cycles;
}

// The same by rtl_timing.h's schedule.
uint64_t predicted_cycles(const std::vector<Fragment>& fragments) {
  std::vector<uint32_t> pixels;
  for (const Fragment& f : fragments) pixels.push_back(uint32_t(f.y) * kRtlTileW + f.x);
  IssueSchedule schedule;
  return schedule.run(pixels.data(), pixels.size());
}

// The schedule by hand: A A B C to pixels 0 0 1 2. Fragment k reaches the window in cycle
// k + 2 and issues two cycles after its pick; the second A waits the span, B and C pass it.
// With two slots, C finds A and B in the window and enters only as B leaves; then the
// older A goes first.
TEST(IssueSchedule, IssueCyclesByHand) {
  const uint32_t pixels[] = {0, 0, 1, 2};
  uint64_t issue[4] = {};
  IssueSchedule two(2);
  EXPECT_EQ(two.run(pixels, 4, issue), 9 + kRtlDrain);
  EXPECT_EQ(issue[1], 8u);
  EXPECT_EQ(issue[2], 6u);
  EXPECT_EQ(issue[3], 9u);
  IssueSchedule schedule(4);
  EXPECT_EQ(schedule.run(pixels, 4, issue), 8 + kRtlDrain);
  EXPECT_EQ(issue[0], kRtlFirstIssue);
  EXPECT_EQ(issue[1], kRtlFirstIssue + kRtlIssueSpan);
  EXPECT_EQ(issue[2], kRtlFirstIssue + 2);
  EXPECT_EQ(issue[3], kRtlFirstIssue + 3);
}

// Under back-pressure, by hand: a fragment enters the window no earlier than the cycle after
// its accept. Pixels 0, 1, 0 accepted in cycles 0, 5, 6: the first issues at 4; the second is
// taken at 6, picked at 7, issues at 9; the third is taken at 7 and, its pixel last issued at
// 4, may be picked from 6: picked at 8, issues at 10. Accepts in cycles 0, 1, 2 give the
// schedule without gaps.
TEST(IssueSchedule, AcceptCyclesByHand) {
  const uint32_t pixels[] = {0, 1, 0};
  const uint64_t late[] = {0, 5, 6}, every[] = {0, 1, 2};
  uint64_t issue[3] = {}, plain[3] = {};
  IssueSchedule schedule;
  EXPECT_EQ(schedule.run(pixels, 3, issue, late), 10 + kRtlDrain);
  EXPECT_EQ(issue[0], kRtlFirstIssue);
  EXPECT_EQ(issue[1], 9u);
  EXPECT_EQ(issue[2], 10u);
  const uint64_t cycles = schedule.run(pixels, 3, plain);
  EXPECT_EQ(schedule.run(pixels, 3, issue, every), cycles);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(issue[k], plain[k]) << "fragment " << k;
}

// One pixel: the bound is the span, whatever the window.
TEST(IssueSchedule, OnePixelRunsAtTheSpan) {
  const std::vector<uint32_t> pixels(100, 3);
  for (const unsigned w : {2u, 8u, 16u})
    EXPECT_EQ(IssueSchedule(w).run(pixels.data(), pixels.size()),
              kRtlFirstIssue + 99 * kRtlIssueSpan + kRtlDrain);
}

// Two tile buffers (the proposed design, docs/rtl.md "A second tile buffer"), by hand: two
// tiles of one fragment each, 5 port cycles of setup and load and 3 of store. Load 0 ends at
// 5 and load 1 at 10. Tile 0's fragment is taken at 6, picked at 7, issues at 9: drained at
// 21, stored by 24. Tile 1's is taken at 11, issues at 14, drains at 26, is stored by 29.
// One buffer: each tile 5 + 16 + 3.
TEST(TwoBuffers, PortBoundByHand) {
  const uint32_t a = 0, b = 1;
  const std::vector<TileStream> tiles{{&a, 1, 5, 3}, {&b, 1, 5, 3}};
  IssueSchedule schedule;
  const OverlapCycles c = schedule.run_two_buffers(tiles);
  EXPECT_EQ(c.total, 29u);
  EXPECT_EQ(c.stream, 26u - 5u);
  EXPECT_EQ(2 * (5 + schedule.run(&a, 1) + 3), 48u);
}

// A buffer is loaded only once the tile before it there is stored: with three tiles, tile 2's
// load waits for tile 0's store, which waits for tile 0's drain, so tile 2's fragment is
// offered after that, not behind tile 1's.
TEST(TwoBuffers, ThirdTileWaitsForTheFirstsStore) {
  const uint32_t k[3] = {0, 1, 2};
  const std::vector<TileStream> tiles{{&k[0], 1, 1, 4}, {&k[1], 1, 1, 4}, {&k[2], 1, 1, 4}};
  IssueSchedule schedule;
  // Load 0 [0,1), load 1 [1,2). Tile 0 taken 2, issues 5, drains 17; tile 1 taken 3, issues
  // 6, drains 18. Store 0 [17,21), load 2 [21,22): tile 2 taken 23, issues 26, drains 38.
  // Store 1 [22,26), store 2 [38,42).
  const OverlapCycles c = schedule.run_two_buffers(tiles);
  EXPECT_EQ(c.stream, 38u - 1u);
  EXPECT_EQ(c.total, 42u);
}

// Tiles whose port work fits under the stream run as one stream: the fill and drain once per
// pass, the window shared across tile edges, as one run over all their fragments.
TEST(TwoBuffers, FillAndDrainOncePerPass) {
  std::mt19937 rng(3);
  std::vector<std::vector<uint32_t>> keys(6);
  std::vector<uint32_t> all;
  std::vector<TileStream> tiles;
  for (size_t t = 0; t < keys.size(); ++t) {
    for (int i = 0; i < 300; ++i) keys[t].push_back(uint32_t(t * 64 + rng() % 64));
    all.insert(all.end(), keys[t].begin(), keys[t].end());
  }
  for (auto& k : keys) tiles.push_back({k.data(), k.size(), 9, 8});
  IssueSchedule schedule;
  const OverlapCycles c = schedule.run_two_buffers(tiles);
  EXPECT_EQ(c.stream, schedule.run(all.data(), all.size()));
  EXPECT_EQ(c.total, 9 + c.stream + 8);
  uint64_t one_buffer = 0;
  for (auto& k : keys) one_buffer += 9 + schedule.run(k.data(), k.size()) + 8;
  EXPECT_LT(c.total + 5 * (kRtlFirstIssue + kRtlDrain - 1), one_buffer + 1);
}

TEST(TwoBuffers, OneTileIsTheOneBufferRun) {
  const uint32_t k[4] = {5, 5, 6, 5};
  IssueSchedule schedule;
  const OverlapCycles c = schedule.run_two_buffers({{k, 4, 7, 2}});
  EXPECT_EQ(c.stream, schedule.run(k, 4));
  EXPECT_EQ(c.total, 7 + c.stream + 2);
  EXPECT_EQ(schedule.run_two_buffers({}).total, 0u);
  EXPECT_THROW(schedule.run_two_buffers({{k, 0, 1, 0}}), std::invalid_argument);
}

// The tile schedule's group with two buffers, by hand: three runs, each 4 port cycles of load,
// 10 of work, 3 of store. Load 0 [0,4), load 1 [4,8); work 0 [4,14), store 0 [14,17); load 2
// [17,21) (its buffer is free once run 0 is stored); work 1 [14,24), store 1 [24,27); work 2
// [24,34) (after run 1's), store 2 [34,37). One buffer: 3 * 17 = 51.
TEST(TwoBuffers, TileScheduleGroupByHand) {
  EXPECT_EQ(two_buffer_group({{4, 10, 3}, {4, 10, 3}, {4, 10, 3}}), 37u);
  // A port-bound group: work 1 each, so each run waits for its load, and run 2's load for
  // run 0's store. Load 0 [0,6), load 1 [6,12); work 0 [6,7), store 0 [12,17); load 2 [17,23);
  // work 1 [12,13), store 1 [23,28); work 2 [23,24), store 2 [28,33).
  EXPECT_EQ(two_buffer_group({{6, 1, 5}, {6, 1, 5}, {6, 1, 5}}), 33u);
  // One run is the one-buffer run; none is nothing; no load or store is the work alone.
  EXPECT_EQ(two_buffer_group({{4, 10, 3}}), 17u);
  EXPECT_EQ(two_buffer_group({}), 0u);
  EXPECT_EQ(two_buffer_group({{0, 5, 0}, {0, 7, 0}}), 12u);
}

Fragment at(int x, int y) {
  Fragment f;
  f.x = static_cast<uint16_t>(x);
  f.y = static_cast<uint16_t>(y);
  f.color = {10, 20, 30, 255};
  return f;
}

TEST(RtlTiming, DistinctPixelsIssueEveryCycle) {
  std::vector<Fragment> f;
  for (int i = 0; i < 20; ++i) f.push_back(at(i % kRtlTileW, i / kRtlTileW));
  EXPECT_EQ(stream_cycles(f), kRtlFirstIssue + (f.size() - 1) + kRtlDrain);
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

TEST(RtlTiming, SamePixelWaitsTheSpan) {
  const std::vector<Fragment> f(6, at(1, 1));
  EXPECT_EQ(stream_cycles(f), kRtlFirstIssue + (f.size() - 1) * kRtlIssueSpan + kRtlDrain);
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

TEST(RtlTiming, MixedStreamFollowsTheSchedule) {
  const std::vector<Fragment> f = {at(0, 0), at(1, 0), at(0, 0), at(2, 0), at(2, 0),
                                   at(3, 0), at(0, 0), at(1, 0), at(1, 0), at(4, 0)};
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

// A fragment that waits for its pixel lets the ones behind it pass: with a window of three or
// more, A A B C issues B and C while the second A waits, so the stream ends when the second A
// issues, Span after the first.
TEST(RtlTiming, FragmentsPassOneThatWaits) {
  if (kRtlWindow < 3) GTEST_SKIP() << "two slots: C enters only as B leaves";
  const std::vector<Fragment> f = {at(0, 0), at(0, 0), at(1, 0), at(2, 0)};
  EXPECT_EQ(stream_cycles(f), kRtlFirstIssue + kRtlIssueSpan + kRtlDrain);
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

// One pixel fills the window: the fragments behind it wait for a free slot, so a stream of
// WINDOW + 2 fragments to one pixel and then others runs at the span until the window drains.
TEST(RtlTiming, OnePixelFillsTheWindow) {
  std::vector<Fragment> f(kRtlWindow + 2, at(5, 5));
  for (int i = 0; i < 12; ++i) f.push_back(at(i, 1));
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

// Two pixels alternating: each waits the span for itself, so two issue per span.
TEST(RtlTiming, TwoPixelsAlternate) {
  std::vector<Fragment> f;
  for (int i = 0; i < 24; ++i) f.push_back(at(i % 2, 0));
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

// Random streams over few pixels (many waits, many reorders): the RTL's cycles are the
// schedule's, stream after stream.
TEST(RtlTiming, RandomStreamsFollowTheSchedule) {
  std::mt19937 rng(7);
  for (const int pixels : {2, 3, 5, 9, 17, 64}) {
    std::uniform_int_distribution<int> pick(0, pixels - 1);
    std::vector<Fragment> f;
    for (int i = 0; i < 300; ++i) {
      const int p = pick(rng);
      f.push_back(at(p % kRtlTileW, (p / kRtlTileW) % kRtlTileH));
    }
    EXPECT_EQ(stream_cycles(f), predicted_cycles(f)) << pixels << " pixels";
  }
}

}  // namespace
}  // namespace zb
