// The suite's reach, measured on the golden model (docs/conformance.md "What the suite reaches"):
// which bins a DUT meets through the kit's ports, computed from a test's stream, the golden
// model's own decisions and the testbench's schedule, with no RTL. Two kinds of bin:
//  - the coverage plan's bins a DUT can reach through the kit (tb/cov/coverage_plan.json, named
//    as scripts/coverage_report.py names them: "pass_state[depth=less,write=1,...]"), which
//    conformance/kit_bins.json lists with the plan's other bins and why those stay out of reach;
//  - the suite's own goals ("goal.*"): each pass state meeting each depth relation where the
//    blend, the mask and the depth write show in the planes, depth pairs differing in one bit at
//    each width, colour and alpha corners under each mask, coverage corners at each depth relation (the
//    coverage blend's cases), tile positions at
//    each tile size, same-pixel runs at distances 1 to 16 under every read-modify-write blend.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "io/trace.h"

namespace zb::conformance {

// What the reach depends on besides the stream: the DUT's tile (the testbench bins fragments
// by it) and the issue window the plan's same-pixel distances are counted to (1 .. window + 1).
// The testbench's fragment gaps (+gap, +seed, tight timing) are modelled draw for draw, so the
// plan's "Gap" distances are counted as a run with those options meets them.
struct DutShape {
  int tile_w = 64, tile_h = 64;
  int window = 8;
  int gap_pct = 0;
  uint32_t seed = 1;
  bool resident = false;  // the resident-tile schedule (conformance.py --schedule resident)
};

// Bins hit, by name, with the count of fragments (or events) that hit each.
using BinCounts = std::map<std::string, uint64_t>;

// The bins a trace reaches, run as the testbench runs it (zb_conf_tb's schedule: pass by pass or
// on resident tiles; the same-pixel distances and gaps follow that order; per pixel the order is
// the stream's either way, so the golden decisions are too).
BinCounts trace_reach(const Trace& trace, const DutShape& shape);

// Every bin the reach can count for a suite of these depth widths and sample counts, at
// `shape`: the kit-reachable plan bins at the plan's default parameters, then the goals.
struct BinList {
  std::vector<std::string> plan, goals;
};
BinList reach_bins(const DutShape& shape);

// The visibility a pass-state goal asks for: the fragment (z, colour c, coverage k) onto the
// stored pixel (depth d, colour s, coverage cs, accumulation acc and revealage r) under
// `state` would change every colour channel (so a mask that keeps a channel shows), differ from
// a plain replace in a colour blend (so a blend taken for replace shows), and in accumulate mode
// change all four accumulation channels. Whether the fragment passes is not asked: a killed
// fragment that would have shown is as telling.
struct StoredPixel {
  uint32_t depth = 0;
  Rgba8 color;
  int coverage = 0;
  std::array<uint32_t, 4> acc{};
  uint32_t reveal = 0;
};
bool visible(const RopState& state, const Fragment& f, const StoredPixel& p, int depth_bits,
             int samples, const WboitFormat& wboit);

// Every pass state of the plan (3456), in zb_rop_cov's order: depth off or each function, x
// write, x blend, x mask, x peel.
std::vector<RopState> pass_states();

}  // namespace zb::conformance

namespace zb::conformance {

struct TestSpec;

// Each test's bins at `shape`, in the tests' order (the tests run on the thread pool; the
// result does not depend on the thread count).
std::vector<BinCounts> tests_reach(const std::vector<TestSpec>& tests, const DutShape& shape);

// The greedy ranking: at each step the test adding the most bins not yet hit (ties: the
// earlier test), until no test adds one. Returns (test index, bins it added) in that order.
std::vector<std::pair<size_t, size_t>> rank_tests(const std::vector<BinCounts>& reach,
                                                  const std::vector<std::string>& bins);

}  // namespace zb::conformance
