// zb_rop's timing facts (rtlmodel/rtl_timing.h), the source of the cost model and the SystemC
// golden module, against the RTL itself: the constants zb_rop.sv declares, read from the
// Verilated model, and the cycles a tile's stream takes, measured.
#include <gtest/gtest.h>

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

// The same by rtl_timing.h's rule.
uint64_t predicted_cycles(const std::vector<Fragment>& fragments) {
  std::vector<uint64_t> last(size_t(kRtlTileW) * kRtlTileH, 0);
  std::vector<bool> seen(last.size(), false);
  uint64_t issue = 0;
  for (size_t i = 0; i < fragments.size(); ++i) {
    const size_t p = size_t(fragments[i].y) * kRtlTileW + fragments[i].x;
    issue = rtl_issue_cycle(i == 0, issue, seen[p], last[p]);
    seen[p] = true;
    last[p] = issue;
  }
  return issue + kRtlDrain;
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

TEST(RtlTiming, MixedStreamFollowsTheIssueRule) {
  const std::vector<Fragment> f = {at(0, 0), at(1, 0), at(0, 0), at(2, 0), at(2, 0),
                                   at(3, 0), at(0, 0), at(1, 0), at(1, 0), at(4, 0)};
  EXPECT_EQ(stream_cycles(f), predicted_cycles(f));
}

}  // namespace
}  // namespace zb
