// zblend_tb: the Verilator testbench's command line. The named suites (tb/suites.cpp) run the
// golden model and the RTL in lockstep (zb::Cosim) and compare every colour and depth bit after
// every pass; --replay runs a trace file the same way.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "code_coverage.h"
#include "suites.h"
#include "io/trace.h"

using namespace zb;
using namespace zb::tb;

namespace {

// Replays a trace file (zblend trace) through the cosim. Returns the exit code.
int run_replay(const Config& c, const std::string& path) {
  try {
    const Trace tr = read_trace(path);
    Cosim cs(cosim_options(c, c.seed));
    replay_trace(tr, cs);  // frame operations included, as the render that wrote it
    std::printf("replay %s: %llu passes, %llu fragments, %llu pixels compared, 0 mismatches\n",
                path.c_str(), (unsigned long long)cs.passes(), (unsigned long long)cs.fragments(),
                (unsigned long long)cs.pixels_compared());
    const std::string w = cs.nothing_checked_warning();
    if (!w.empty()) {
      std::printf("%s\n", w.c_str());
      return 1;
    }
    return 0;
  } catch (const MismatchError& e) {
    std::printf("%sreplay %s: FAILED\n", e.what(), path.c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "zblend_tb: %s\n", e.what());
    return 2;
  }
}

// Runs the suites, one summary line each. Returns the exit code.
int run_suites(const Config& c, const std::vector<const Suite*>& chosen) {
  int passed = 0, failed = 0;
  for (const Suite* s : chosen) {
    const auto t0 = std::chrono::steady_clock::now();
    Tally t;
    try {
      t = s->run(c);
    } catch (const std::exception& e) {
      std::printf("suite %s: error: %s\n", s->name, e.what());
      t.failed = true;
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool nothing = t.fragments == 0 || t.pixels == 0;
    if (nothing) std::printf("warning: suite %s checked nothing\n", s->name);
    const bool ok = !t.failed && !nothing;
    std::printf("suite %-7s %s  iterations %llu  fragments %llu  pixels compared %llu  "
                "mismatches %llu  %.2f s  %.3g fragments/s (cosim)  cycles %llu stream + %llu "
                "tile io\n",
                s->name, ok ? "PASS" : "FAIL", (unsigned long long)t.iterations,
                (unsigned long long)t.fragments, (unsigned long long)t.pixels,
                (unsigned long long)t.mismatches, sec, sec > 0 ? double(t.fragments) / sec : 0.0,
                (unsigned long long)t.stream_cycles, (unsigned long long)t.io_cycles);
    if (!t.note.empty()) std::printf("  %s: %s\n", s->name, t.note.c_str());
    std::fflush(stdout);
    (ok ? passed : failed)++;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Verilator-style plusargs: +trace dumps the whole run to out/tb_trace.fst.
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "+trace") {
      args.emplace_back("--trace");
      args.emplace_back("out/tb_trace.fst");
    } else {
      args.push_back(a);
    }
  }
  std::vector<const char*> cargv;
  for (const std::string& a : args) cargv.push_back(a.c_str());

  Config c;
  std::vector<std::string> suite_names;
  std::string replay, coverage_out;
  bool list = false;
  CLI::App app{"zblend_tb: the RTL (Verilated zb_rop) against the golden model, bit for bit"};
  app.add_option("--suite", suite_names,
                 "suite(s) to run, repeatable or comma-separated (default all)")
      ->delimiter(',');
  app.add_flag("--list-suites", list, "list the suites and exit");
  app.add_option("--seed", c.seed, "base seed; iteration i uses seed+i (printed on failure)");
  app.add_option("--iterations", c.iterations, "iterations per suite (default: the suite's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--fragments", c.fragments,
                 "scale: about this many fragments (random, hazard; blend: a sample)");
  app.add_option("--backpressure", c.backpressure, "probability of stall and of a valid gap")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--trace", c.trace, "FST of the whole run (also +trace)");
  app.add_option("--mismatch-fst", c.mismatch_fst, "FST written around the first mismatch");
  app.add_option("--replay", replay, "replay a trace file (zblend trace) through the cosim");
  app.add_flag("-v,--verbose", c.verbose, "one line per iteration");
#if defined(VM_COVERAGE) && VM_COVERAGE  // only the coverage build (ZBLEND_RTL_COVERAGE)
  app.add_option("--coverage-out", coverage_out,
                 "write the RTL line and toggle coverage of the run here at exit "
                 "(verilator_coverage format)");
#endif
  try {
    app.parse(int(cargv.size()), cargv.data());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "zblend_tb: error: %s (see --help)\n", e.what());
    return 2;
  }

  if (list) {
    for (const Suite& s : suites()) std::printf("%-8s %s\n", s.name, s.about);
    return 0;
  }

  CoverageTotals coverage;
  if (!coverage_out.empty()) {
    const std::filesystem::path p(coverage_out);
    std::error_code ec;
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
    coverage = CoverageTotals(coverage_out + ".part");
    c.coverage = &coverage;
  }
  int rc;
  if (!replay.empty()) {
    rc = run_replay(c, replay);
  } else {
    std::vector<const Suite*> chosen;
    if (suite_names.empty()) {
      for (const Suite& s : suites()) chosen.push_back(&s);
    } else {
      for (const std::string& n : suite_names) {
        const Suite* found = find_suite(n);
        if (!found) {
          std::fprintf(stderr, "zblend_tb: unknown suite '%s' (see --list-suites)\n",
                       n.c_str());
          return 2;
        }
        chosen.push_back(found);
      }
    }
    rc = run_suites(c, chosen);
  }
  if (!coverage_out.empty()) {
    try {
      coverage.write(coverage_out);
      std::printf("coverage: %zu points from %llu models: %s\n", coverage.points(),
                  (unsigned long long)coverage.models(), coverage_out.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "zblend_tb: %s\n", e.what());
      return 2;
    }
  }
  return rc;
}
