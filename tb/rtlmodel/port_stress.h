// The port stress mode (docs/testbench.md "Port stress"): zb_rop's tile port driven, with no
// fragment, by random sequences of the operations its contract allows (docs/rtl.md "Port
// timing") in orders the RTL driver never makes: fast clears of any planes to any value next to
// reads and loads, loads and reads of any beat in any order, stores read twice, copies and
// resolves (under any background, of any accumulation word), counters cleared at any cycle.
// Every read beat and the tile counters are checked against a model of the planes a beat at a
// time.
#pragma once

#include <cstdint>
#include <string>

#include "rtl_rop.h"

namespace zb {

struct PortStressResult {
  uint64_t ops = 0, reads = 0, cycles = 0;
  uint64_t words = 0;    // words compared
  uint64_t renames = 0;  // renamed copies (a clear of depth with tile_copy_i)
  uint64_t deep_clears = 0;  // fast clears of a depth bank that one generation bit would refuse
  std::string mismatch;  // the first difference from the model, with the beat's history; empty: none
};

// `ops` random operations (seed `seed`) on one model made with `o` (plusargs, trace, assertions;
// the schedule and back-pressure do not apply). Stops at the first mismatch.
PortStressResult run_port_stress(const RtlOptions& o, uint64_t seed, uint64_t ops);

}  // namespace zb
