// zb_rop's timing facts, the one source the cost model (lab/sizing_cost.h) and the SystemC
// golden module (systemc/) take them from. The RTL states the same numbers (zb_rop.sv: Span,
// the X stages, the drain); tests/rtl/test_rtl_timing.cpp fails when the two disagree, by
// reading Span from the Verilated model and measuring first issue, span and drain.
#pragma once

#include <cstdint>

namespace zb {

// zb_rop's streaming timing (docs/rtl.md "Pipeline" and "Interlock"), fragments offered every
// cycle from the tile's first streaming cycle (cycle 0): the first issues in cycle
// kRtlFirstIssue; each later one in max(the previous one's cycle + 1, the cycle of the
// previous fragment to its pixel + kRtlIssueSpan); busy_o falls kRtlDrain cycles after the
// last issue. So a tile streams last issue + kRtlDrain cycles: its fragments + 13 when no
// fragment waits.
constexpr uint64_t kRtlFirstIssue = 2;
constexpr uint64_t kRtlIssueSpan = 4;
constexpr uint64_t kRtlDrain = 12;

// The cycle a fragment issues in, by that rule: `first` for the tile's first fragment, else
// `previous` is the tile's previous issue; `pixel_seen` when an earlier fragment of this
// tile's run hit the same pixel, issued in `pixel_previous`.
constexpr uint64_t rtl_issue_cycle(bool first, uint64_t previous, bool pixel_seen,
                                   uint64_t pixel_previous) {
  const uint64_t issue = first ? kRtlFirstIssue : previous + 1;
  return pixel_seen && pixel_previous + kRtlIssueSpan > issue ? pixel_previous + kRtlIssueSpan
                                                              : issue;
}

}  // namespace zb
