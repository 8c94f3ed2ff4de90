// zblend_tb: the Verilator testbench's command line. The named suites (tb/suites.cpp) run the
// golden model and the RTL in lock-step (zb::Cosim): every write at its cycle, and every colour,
// depth, coverage and peel bit after every pass; --replay runs a trace file the same way.
#include <chrono>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "cli.h"
#include "code_coverage.h"
#include "io/trace.h"
#include "output_paths.h"
#include "rtl_rop.h"
#include "suites.h"

using namespace zb;
using namespace zb::tb;
using zb::cli::UsageError;

namespace {

using Clock = std::chrono::steady_clock;

// What the command line asks beyond the suites' Config.
struct Args {
  std::vector<std::string> suites;
  std::string replay, coverage_out;
  int iterations = 0;
  int64_t fragments = 0;
  bool list = false;
  bool quiet = false;
  std::string defect = "blend";  // zblend_tb_bug: the injected defect
  int mutant = 0;                // zblend_tb_mut: the live mutant, 0 for none
  std::string schedule = "pass";
};

// Progress on stderr: a line as each suite starts, then one every kEvery with the share done
// (the suite's WorkCounter reports it through Config::progress).
class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool quiet) : quiet_(quiet) {}
  void start(const Suite& s) {
    name_ = s.name;
    start_ = last_ = Clock::now();
    if (!quiet_) std::fprintf(stderr, "zblend_tb: suite %s: started\n", name_);
  }
  void update(double done) {
    const auto now = Clock::now();
    if (quiet_ || now - last_ < kEvery) return;
    last_ = now;
    std::fprintf(stderr, "zblend_tb: suite %s: %.0f%% done after %.0f s\n", name_, 100 * done,
                 std::chrono::duration<double>(now - start_).count());
  }

 private:
  static constexpr std::chrono::seconds kEvery{5};
  bool quiet_;
  const char* name_ = "";
  Clock::time_point start_, last_;
};

// Replays a trace file (zblend trace) through the cosim. Returns the exit code; a trace it
// cannot read or run is bad input (UsageError).
int run_replay(const Config& c, const std::string& path) {
  try {
    const Trace tr = read_trace(path);
    std::fprintf(stderr, "zblend_tb: replay %s on the RTL's %s\n", path.c_str(), RtlRop::build());
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
    throw UsageError(e.what());
  }
}

// Runs the suites, one summary line each. Returns the exit code.
int run_suites(const Config& config, const std::vector<const Suite*>& chosen, bool quiet) {
  if (!quiet) std::fprintf(stderr, "zblend_tb: the RTL's %s\n", RtlRop::build());
  int passed = 0, failed = 0;
  ProgressPrinter progress(quiet);
  Config c = config;
  c.progress = [&progress](double done) { progress.update(done); };
  for (const Suite* s : chosen) {
    const auto t0 = std::chrono::steady_clock::now();
    progress.start(*s);
    Tally t;
    try {
      t = s->run(c);
    } catch (const std::exception& e) {
      std::printf("suite %s: error: %s\n", s->name, e.what());
      t.failed = true;
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool nothing = !t.failed && ((t.fragments == 0 && !t.port_only) || t.pixels == 0);
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

// The command line with the Verilator-style plusarg expanded: +trace is --waves
// out/tb_trace.fst (the whole run).
std::vector<std::string> expand_args(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "+trace") {
      args.emplace_back("--waves");
      args.emplace_back("out/tb_trace.fst");
    } else {
      args.push_back(a);
    }
  }
  return args;
}

void add_options(CLI::App& app, Config& c, Args& a) {
  app.add_option("--suite", a.suites,
                 "suite(s) to run, repeatable or comma-separated (default all)")
      ->delimiter(',');
  app.add_flag("--list-suites", a.list, "list the suites and exit");
  app.add_option("--seed", c.seed, "base seed; iteration i uses seed+i (printed on failure)");
  app.add_option("--iterations", a.iterations,
                 "iterations per suite, 1 or more (default: the suite's)");
  app.add_option("--fragments", a.fragments,
                 "scale, 1 or more: about this many fragments (random, hazard; blend: a sample)");
  app.add_option("--backpressure", c.cosim.rtl.backpressure,
                 "probability of stall and of a valid gap")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--waves", c.cosim.rtl.trace_path, "FST of the whole run (also +trace)");
  app.add_option("--schedule", a.schedule,
                 "pass (each pass loads and stores every tile it touches) or tile (the passes "
                 "up to a frame operation on the resident tile)")
      ->capture_default_str();
  app.add_option("--mismatch-fst", c.cosim.mismatch_fst, "FST written around the first mismatch")
      ->capture_default_str();
  app.add_option("--replay", a.replay, "replay a trace file (zblend trace) through the cosim");
  app.add_flag("-v,--verbose", c.verbose, "one line per iteration");
  app.add_flag("-q,--quiet", a.quiet, "no progress on stderr");
  app.add_flag("!--no-assertions", c.cosim.rtl.assertions,
               "run the RTL with its assertions off, to see what the comparison alone catches");
  app.add_flag("!--no-lockstep", c.cosim.lockstep,
               "compare the frames after each pass only, not every write at its cycle");
  app.add_flag("!--no-timing-check", c.cosim.rtl.check_timing,
               "do not check each tile's streaming cycles against the issue schedule "
               "(checked without back-pressure), to see what the comparisons alone catch");
#ifdef ZB_TB_BUG  // zblend_tb_bug: the RTL holds deliberate defects, one switched on per run
  app.add_option("--defect", a.defect,
                 "the injected defect: blend (alpha blend with an odd source alpha flips red "
                 "bit 0), window (the issue window lets a fragment pass an older one to its "
                 "pixel), accum (the accumulation word's bypass is never taken), copy (the tile's copy "
                 "of depth to peel flips a bit), resolve (the store's resolve does not "
                 "saturate), resolve-wboit (the store's resolve of the accumulation truncates), "
                 "layers (the layers word's bypass is never taken) or resolve-layers (the "
                 "store's resolve composites the layers back to front)")
      ->check(CLI::IsMember({"blend", "window", "accum", "copy", "resolve", "resolve-wboit",
                             "layers", "resolve-layers"}))
      ->capture_default_str();
#endif
#ifdef ZB_TB_MUT  // zblend_tb_mut: the RTL is Yosys's mutant netlist (docs/mutation.md)
  app.add_option("--mutant", a.mutant,
                 "the live mutant, 1 to the netlist's count (build/tb/mutation/mutations.txt, line "
                 "N); 0 runs the netlist unmutated")
      ->check(CLI::Range(0, 2047))
      ->capture_default_str();
#endif
#if defined(VM_COVERAGE) && VM_COVERAGE  // zblend_tb_fcov, and the ZBLEND_RTL_COVERAGE tree's
  app.add_option("--coverage-out", a.coverage_out,
                 "write the run's RTL coverage here at exit (verilator_coverage format, .dat): "
                 "the coverage plan's bins, and lines and toggles in a code coverage build");
#endif
}

// The checks before any work: counts, then the output paths (docs/cli.md, "Output paths").
void check_args(const CLI::App& app, Config& c, const Args& a) {
  for (const auto& [name, value] : {std::pair<const char*, int64_t>{"--iterations", a.iterations},
                                    {"--fragments", a.fragments}})
    if (app.count(name) && value < 1)
      throw UsageError(fmt::format("{}: {} is out of range (1 or more; leave it out for the "
                                   "suite's default)", name, value));
  c.iterations = a.iterations;
  c.fragments = static_cast<uint64_t>(a.fragments);
  if (!parse_schedule(a.schedule, c.cosim.rtl.schedule))
    throw UsageError(
        fmt::format("--schedule: unknown schedule '{}' (choose from pass, tile)", a.schedule));
  std::vector<std::string>& plusargs = c.cosim.rtl.plusargs;
  if (a.defect == "window") plusargs.push_back("+zb_bug_window");
  if (a.defect == "accum") plusargs.push_back("+zb_bug_accum");
  if (a.defect == "copy") plusargs.push_back("+zb_bug_copy");
  if (a.defect == "resolve") plusargs.push_back("+zb_bug_resolve");
  if (a.defect == "resolve-wboit") plusargs.push_back("+zb_bug_resolve_wboit");
  if (a.defect == "layers") plusargs.push_back("+zb_bug_layers");
  if (a.defect == "resolve-layers") plusargs.push_back("+zb_bug_resolve_layers");
  if (a.mutant) plusargs.push_back(fmt::format("+zb_mutant={}", a.mutant));
  // The mismatch waveform's directory is made only if a mismatch writes it.
  cli::check_outputs({{"--mismatch-fst", c.cosim.mismatch_fst, ".fst"}});
  cli::create_output_dirs(
      {{"--waves", c.cosim.rtl.trace_path, ".fst"}, {"--coverage-out", a.coverage_out, ".dat"}});
}

// The reproduce command's start (Config::command): argv[0] and every argument but those that
// choose the suite, seed, iterations and output files.
std::string base_command(const std::vector<std::string>& args) {
  static const std::set<std::string> kDropped = {"--suite", "--seed", "--iterations", "--waves",
                                                 "--mismatch-fst", "--coverage-out", "--replay"};
  std::string out = cli::shell_word(args.at(0));
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    const std::string name = a.substr(0, a.find('='));
    if (kDropped.count(name)) {
      if (a.find('=') == std::string::npos) ++i;  // and its value
      continue;
    }
    out += " " + cli::shell_word(a);
  }
  return out;
}

std::vector<const Suite*> chosen_suites(const Args& a) {
  std::vector<const Suite*> chosen;
  if (a.suites.empty())
    for (const Suite& s : suites()) chosen.push_back(&s);
  for (const std::string& n : a.suites) {
    const Suite* found = find_suite(n);
    if (!found) throw UsageError(fmt::format("unknown suite '{}' (see --list-suites)", n));
    chosen.push_back(found);
  }
  return chosen;
}

int run(const Config& config, const Args& a, const std::vector<const Suite*>& chosen) {
  Config c = config;
  CoverageTotals coverage;
  if (!a.coverage_out.empty()) {
    coverage = CoverageTotals(a.coverage_out + ".part");
    c.cosim.rtl.coverage = &coverage;
  }
  const int rc = a.replay.empty() ? run_suites(c, chosen, a.quiet) : run_replay(c, a.replay);
  if (!a.coverage_out.empty()) {
    try {
      coverage.write(a.coverage_out);
      std::printf("coverage: %zu points from %llu models: %s\n", coverage.points(),
                  (unsigned long long)coverage.models(), a.coverage_out.c_str());
    } catch (const std::exception& e) {
      throw UsageError(e.what());
    }
  }
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  Config c;
  Args a;
  const std::vector<std::string> args = expand_args(argc, argv);
  std::vector<const char*> cargv;
  for (const std::string& arg : args) cargv.push_back(arg.c_str());

  CLI::App app{"zblend_tb: the RTL (Verilated zb_rop) against the golden model, bit for bit"};
  app.name("zblend_tb");
  add_options(app, c, a);
  return cli::run_main(app, int(cargv.size()), cargv.data(), [&] {
    if (a.list) {
      for (const Suite& s : suites()) std::printf("%-8s %s\n", s.name, s.about);
      return 0;
    }
    std::vector<const Suite*> chosen;
    if (a.replay.empty()) chosen = chosen_suites(a);
    check_args(app, c, a);
    c.command = base_command(args);
    return run(c, a, chosen);
  });
}
