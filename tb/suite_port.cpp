// port: the port stress mode (tb/rtlmodel/port_stress.h, docs/testbench.md "Port stress"). No
// golden model runs: each iteration drives one fresh model's tile port with --fragments random
// operations (default 20000) and checks every read beat and the tile counters against a model
// of the planes. Its words compared count as pixels.
#include <cstdio>

#include "port_stress.h"
#include "suites.h"

namespace zb::tb {

Tally suite_port(const Config& c) {
  Tally t;
  t.port_only = true;
  const int iters = c.iterations ? c.iterations : 8;
  const uint64_t ops = c.fragments ? c.fragments : 20000;
  WorkCounter progress(c, uint64_t(iters));
  uint64_t reads = 0, renames = 0, deep = 0;
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + uint64_t(it);
    const PortStressResult r = run_port_stress(cosim_options(c, seed).rtl, seed, ops);
    ++t.iterations;
    t.pixels += r.words;
    t.io_cycles += r.cycles;
    reads += r.reads;
    renames += r.renames;
    deep += r.deep_clears;
    if (!r.mismatch.empty()) {
      std::printf("port stress: mismatch at %s\n", r.mismatch.c_str());
      report_failure("port", c, seed);
      t.failed = true;
      ++t.mismatches;
      break;
    }
    progress.add();
  }
  t.note = "reads " + std::to_string(reads) + ", renamed copies " + std::to_string(renames) +
           ", fast clears of a depth bank one generation bit refuses " + std::to_string(deep);
  return t;
}

}  // namespace zb::tb
