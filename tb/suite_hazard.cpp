// hazard: long runs on 1-4 pixels, mixed with random ones, one tile; fragments per clock.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "suites.h"

namespace zb::tb {

Tally suite_hazard(const Config& c) {
  Tally t;
  const uint64_t total = c.fragments ? c.fragments : 400000;
  const int iters = c.iterations ? c.iterations : 2;
  const size_t per_iter = std::max<uint64_t>(1, total / iters);
  uint64_t frags = 0, cycles = 0;
  double rtl_sec = 0;
  WorkCounter progress(c, iters);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("hazard", c, seed, t, [&](Cosim& cs) {
      HazardStimulus stim(seed);
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{10, 20, 30, 40});
      const int passes = 4;
      std::vector<PassStats> stats;
      for (int p = 0; p < passes; ++p) {
        const RopState st = stim.next_state();
        cs.label_pass("hazard-" + std::to_string(p + 1));
        cs.begin_pass(st);
        cs.draw(stim.next_fragments(per_iter / passes));
        const auto t0 = std::chrono::steady_clock::now();
        stats.push_back(cs.end_pass());  // the RTL simulation (the golden ran in draw)
        if (p + 1 == passes) cs.finish_frame(stats);  // the tile schedule's, all passes
        rtl_sec += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      for (const PassStats& s : stats) {
        frags += s.fragments_in;
        cycles += s.cycles;
      }
    });
    if (!ok) break;
    progress.add();
  }
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "fragments per clock %.4f (%llu fragments / %llu streaming cycles); RTL "
                "simulation %.3g fragments/s",
                cycles ? double(frags) / double(cycles) : 0.0, (unsigned long long)frags,
                (unsigned long long)cycles, rtl_sec > 0 ? double(frags) / rtl_sec : 0.0);
  t.note = buf;
  return t;
}

}  // namespace zb::tb
