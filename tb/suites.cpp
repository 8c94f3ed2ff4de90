// The suites' framework: the registry, one iteration on a fresh Cosim, a failure's reproduce
// command; see suites.h. Each suite is in suite_<name>.cpp.
#include "suites.h"

#include <fmt/core.h>

#include <cstdio>
#include <functional>

namespace zb::tb {

CosimOptions cosim_options(const Config& c, uint64_t seed) {
  CosimOptions o = c.cosim;
  o.rtl.seed = seed;
  return o;
}

// The failure's last lines: the iteration, and the one command that runs it again alone with
// the whole run's waveform and its save file (docs/testbench.md "Waves").
void report_failure(const char* suite, const Config& c, uint64_t seed) {
  std::printf("FAIL suite %s iteration seed %llu\n", suite, (unsigned long long)seed);
  const std::string fst = fmt::format("out/waves/{}-{}.fst", suite, seed);
  std::printf("reproduce with waves: %s --suite %s --seed %llu --iterations 1 --waves %s\n",
              c.command.empty() ? "zblend_tb" : c.command.c_str(), suite,
              (unsigned long long)seed, fst.c_str());
}

bool run_iteration(const char* suite, const Config& c, uint64_t seed, Tally& t,
                   const std::function<void(Cosim&)>& body) {
  Cosim cosim(cosim_options(c, seed));
  bool ok = true;
  try {
    body(cosim);
    std::vector<PassStats> passes;  // the tile schedule's last group runs here
    cosim.finish_frame(passes);
  } catch (const MismatchError& e) {
    std::printf("%s", e.what());
    report_failure(suite, c, seed);
    t.failed = true;
    ok = false;
    if (cosim.mismatches() == 0) ++t.mismatches;  // a counter mismatch
  } catch (const std::runtime_error& e) {  // a check of the driver's: counts, port, timing
    std::printf("suite %s: error: %s\n", suite, e.what());
    report_failure(suite, c, seed);
    t.failed = true;
    ok = false;
  }
  ++t.iterations;
  t.fragments += cosim.fragments();
  t.pixels += cosim.pixels_compared();
  t.mismatches += cosim.mismatches();
  t.io_cycles += cosim.rtl().tile_io_cycles();
  t.stream_cycles += cosim.rtl().total_cycles() - cosim.rtl().tile_io_cycles();
  if (c.verbose) std::printf("  %s seed %llu: %llu fragments\n", suite, (unsigned long long)seed,
                             (unsigned long long)cosim.fragments());
  return ok;
}

void draw_pass(Cosim& cs, const std::string& name, const RopState& st,
               const std::vector<Fragment>& f) {
  cs.label_pass(name);
  cs.begin_pass(st);
  cs.draw(f);
  cs.end_pass();
}

const std::vector<Suite>& suites() {
  static const std::vector<Suite> kSuites = {
      {"scenes", "every built-in scene x every pass plan at 96x72", suite_scenes},
      {"random", "constrained-random states and streams, small frames, several passes",
       suite_random},
      {"hazard", "runs of fragments on 1-4 pixels mixed with random ones; fragments per clock",
       suite_hazard},
      {"window",
       "directed issue-window streams: one pixel filling it, two alternating, rings, gaps",
       suite_window},
      {"tiles",
       "fast-clear bookkeeping: passes that write nothing between clears, one or two tiles",
       suite_tiles},
      {"clears",
       "a store's last write-back meeting the next fast clear, then clears with no store "
       "between, probed at every pixel",
       suite_clears},
      {"accum",
       "accumulate passes (weighted blended OIT) with same-pixel fragments at issue distances "
       "4 to 7 (bypass, forwarding), runs and random ones; resolves between",
       suite_accum},
      {"layers",
       "layers passes (mlab-K, K = 1 to LAYERS) with same-pixel fragments at issue distances 4 "
       "to 7, runs that fill and merge a pixel's layers, equal depths and colour words; each "
       "resolved on the tile's store",
       suite_layers},
      {"blend",
       "alpha and additive over all 2^24 (s, a, d), 2^16 (a, d) on A; coverage over all "
       "(k, s, d)",
       suite_blend},
      {"port",
       "the tile port alone, stressed: random fast clears, loads, reads (copies, resolves under "
       "any background) and counter clears in orders the driver never makes, against a model of "
       "the planes",
       suite_port},
      {"states",
       "every pass state: depth test off or each function x depth write x blend x colour mask "
       "x peel test, a short pass each",
       suite_states},
  };
  return kSuites;
}

const Suite* find_suite(const std::string& name) {
  for (const Suite& s : suites())
    if (name == s.name) return &s;
  return nullptr;
}

}  // namespace zb::tb
