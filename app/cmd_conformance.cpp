// zblend conformance export | check: the conformance kit's vectors and their checker
// (docs/conformance.md; the library is conformance/).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "check.h"
#include "cli.h"
#include "output_paths.h"
#include "commands.h"
#include "export.h"
#include "suite.h"
#include "vectors.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

namespace cf = zb::conformance;

struct ExportOptions {
  std::string dir;
  bool quick = false;
  bool list = false;
  uint64_t seed = 0;
};

struct CheckOptions {
  std::string suite, out, tests, arithmetic;
  bool no_accum = false;
  bool quick = false;
};

struct DigestOptions {
  std::string suite, test, arithmetic = "zblend";
};

void run_digests(const DigestOptions& o) {
  const std::optional<zb::Arithmetic> arith = zb::parse_arithmetic(o.arithmetic);
  if (!arith) throw UsageError("--arithmetic: " + zb::arithmetic_error(o.arithmetic));
  std::vector<cf::PassDigest> digests;
  try {
    digests = cf::replay_golden(cf::read_test_stream(o.suite, o.test), *arith).digests;
  } catch (const cf::ConformanceError& e) {
    throw UsageError(e.what());
  }
  for (const cf::PassDigest& p : digests) fmt::print("{} {:016x}\n", p.pass, p.digest);
}

void print_list(const std::vector<cf::TestSpec>& tests) {
  fmt::print("{:<30} {:<8} {:<7} {:>6}  {}\n", "test", "config", "kind", "frame", "what");
  for (const cf::TestSpec& t : tests)
    fmt::print("{:<30} {:<8} {:<7} {:>6}  {}\n", t.name, t.config.name, cf::to_string(t.kind),
               fmt::format("{}x{}", t.width, t.height),
               t.kind == cf::TestKind::kScene       ? fmt::format("scene {}, method {}", t.scene, t.method)
               : t.kind == cf::TestKind::kGenerated ? fmt::format("generated: {}", cf::to_string(t.family))
                                                    : fmt::format("seed {}", t.seed));
  fmt::print("{} tests\n", tests.size());
}

void run_export(const ExportOptions& o) {
  if (o.seed && o.quick) throw UsageError("--seed and --quick: choose one tier");
  const std::vector<cf::TestSpec> tests = o.seed ? cf::seeded_tests(o.seed) : cf::suite_tests(o.quick);
  if (o.list) {
    if (!o.dir.empty())
      throw UsageError(fmt::format("DIR: --list writes nothing; leave out '{}'", o.dir));
    print_list(tests);
    return;
  }
  if (o.dir.empty())
    throw UsageError("DIR: needed, the directory to write the suite to (or --list to see the tests)");
  check_outputs({{"DIR", o.dir, nullptr}});
  if (const std::string w = cf::build_warning(); !w.empty())
    fmt::print(stderr, "zblend conformance export: warning: {}\n", w);
  const auto start = std::chrono::steady_clock::now();
  cf::ExportSummary s;
  try {
    s = cf::export_suite(o.dir, tests);
  } catch (const cf::ConformanceError& e) {
    throw UsageError(e.what());
  }
  std::vector<std::string> configs;
  for (const cf::TestSpec& t : tests)
    if (configs.empty() || configs.back() != t.config.name) configs.push_back(t.config.name);
  fmt::print("{}: {} tests in {} configs ({}), {} fragments, {:.1f} MB, {:.1f} s\n", o.dir, s.tests,
             configs.size(), join(configs), s.fragments, double(s.bytes) / 1e6,
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

std::vector<std::string> split_tests(const std::string& list) {
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    if (name.empty())
      throw UsageError(fmt::format("--tests: '{}' has an empty name (give names separated by commas)", list));
    names.push_back(name);
    start = comma + 1;
  }
  return names;
}

void run_check(const CLI::App& cmd, const CheckOptions& o) {
  cf::Selection only;
  only.quick = o.quick;
  if (cmd.count("--tests")) only.names = split_tests(o.tests);
  std::error_code ec;
  if (!std::filesystem::is_directory(o.out, ec))
    throw UsageError(fmt::format("OUT: '{}' is not a directory (give the one holding "
                                 "<test>/got.<plane>.hex)", o.out));
  std::vector<cf::TestResult> results;
  std::string chosen;  // how the tests were chosen, when by the run in OUT
  bool no_accum = o.no_accum;
  std::string arith_name = o.arithmetic.empty() ? "zblend" : o.arithmetic;
  try {
    // Neither --tests nor --quick: the tests the run in OUT simulated, when a run left its
    // results there, so a --quick or subset run is not judged by the tests it never ran.
    if (only.names.empty() && !only.quick) {
      if (std::optional<cf::RunRecord> run = cf::read_run(o.out)) {
        only.from = (std::filesystem::path(o.out) / "results.json").string();
        if (run->tests.empty())
          throw UsageError(fmt::format("OUT: {} says the run simulated no test: give --tests or "
                                       "--quick to choose some", only.from));
        only.names = run->tests;
        // As the run checked them: a DUT it found without the plane, as --no-accum.
        no_accum = no_accum || !run->accum_plane;
        if (o.arithmetic.empty()) arith_name = run->arithmetic;  // as the run declared it
        chosen = fmt::format(" (the tests the run simulated{}, {})",
                             run->accum_plane ? "" : ", without the accumulation plane", only.from);
      }
    }
    cf::CheckRule rule;
    rule.cts = arith_name == "cts";
    const std::optional<zb::Arithmetic> arith =
        rule.cts ? zb::Arithmetic{} : zb::parse_arithmetic(arith_name);
    if (!arith)
      throw UsageError("--arithmetic: " + zb::arithmetic_error(arith_name) + "; or cts, the CTS verdict");
    rule.arithmetic = *arith;
    if (rule.cts)
      chosen += fmt::format(" (the CTS verdict: colour within {} a channel of zblend's, reported "
                            "apart as cts)", cf::kCtsColorThreshold);
    else if (!arith->is_zblend())
      chosen += fmt::format(" (arithmetic {}: the expected planes are the streams replayed in it)",
                            arith_name);
    // A failed test's line ends with the command that shows its first wrong pixel's history.
    const std::string program = command_of(*cmd.get_parent());
    results = cf::check_suite(o.suite, o.out, only, !no_accum, [&](const cf::TestResult& r) {
      if (r.pass || r.skipped || r.first_x < 0)
        fmt::print("{}\n", r.line);
      else
        fmt::print("{}; why: {} pixel {} {} --at {},{}{}\n", r.line, program, shell_word(o.suite),
                   r.name, r.first_x, r.first_y,
                   rule.cts || arith->is_zblend() ? "" : " --arithmetic " + arith_name);
      std::fflush(stdout);
    }, rule);
  } catch (const cf::ConformanceError& e) {
    throw UsageError(e.what());
  }
  // A skipped test is neither passed nor failed: it is counted apart.
  size_t failed = 0, skipped = 0, cts = 0;
  for (const cf::TestResult& r : results) {
    skipped += r.skipped ? 1 : 0;
    failed += r.pass || r.skipped ? 0 : 1;
    cts += r.cts ? 1 : 0;
  }
  const size_t checked = results.size() - skipped;
  fmt::print("{} of {} tests pass{}{}{}\n", checked - failed, checked,
             cts ? fmt::format(" ({} of them by the CTS threshold only, not exactly)", cts) : "",
             skipped ? fmt::format(", {} skipped (they need the accumulation plane)", skipped) : "",
             chosen);
  if (failed) throw VerificationError(fmt::format("{} of {} tests failed", failed, checked));
}

}  // namespace

void add_conformance_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "conformance", "The conformance kit's vectors: export a suite, check a DUT's planes");
  cmd->require_subcommand(1, 1);
  add_conformance_commands(*cmd);
}

void add_conformance_commands(CLI::App& parent) {
  CLI::App* cmd = &parent;
  auto e = std::make_shared<ExportOptions>();
  CLI::App* exp = cmd->add_subcommand(
      "export", "Write the suite (streams, expected planes, manifest) to DIR, replacing an "
                "earlier suite there");
  exp->add_option("DIR", e->dir, "Directory to write (new, empty, or an earlier suite)");
  exp->add_flag("--quick", e->quick, "Only the CI-sized subset (the same tests, names and files)");
  exp->add_flag("--list", e->list, "List the tests instead of writing them");
  exp->add_option("--seed", e->seed,
                  "The seeded random tier instead: new random streams for every seed N >= 1, "
                  "each reproducible from it (for overnight runs)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 62));
  exp->callback([e] { run_export(*e); });

  auto c = std::make_shared<CheckOptions>();
  CLI::App* chk = cmd->add_subcommand(
      "check", "Compare a DUT's planes, OUT/<test>/got.<plane>.hex, with SUITE's signatures: a "
               "line per test; exit 1 when any fails");
  chk->add_option("SUITE", c->suite, "The suite's directory (zblend conformance export)")->required();
  chk->add_option("OUT", c->out, "The DUT's output directory")->required();
  chk->add_option("--tests", c->tests,
                  "Only these tests, NAME,NAME,... (a CI slice; default: those the run in OUT "
                  "simulated, by its results.json, else every test)");
  chk->add_flag("--quick", c->quick, "Only the suite's quick tier (as scripts/conformance.py "
                                     "--quick), with --tests those of them");
  chk->add_flag("--no-accum", c->no_accum,
                "The DUT has no accumulation plane: skip the tests that need it (reported as "
                "skip, not pass) and read no got.accum.hex");
  chk->add_option("--arithmetic", c->arithmetic,
                  "The DUT's declared blend arithmetic (docs/datapath.md \"Declared arithmetic\"): "
                  "zblend (the default), sum-round255, sum-ceil256, ...; the expected planes are "
                  "the streams replayed in it; cts: colour within the Khronos CTS blend tests' "
                  "threshold of zblend's, reported apart (default: the run's, by its results.json)");
  chk->callback([chk, c] { run_check(*chk, *c); });

  auto d = std::make_shared<DigestOptions>();
  CLI::App* dig = cmd->add_subcommand(
      "digests", "Print the golden model's digest of the planes after each pass of a test, as "
                 "the testbench writes got.passes.hex (docs/conformance.md \"Every pass seen\")");
  dig->add_option("SUITE", d->suite, "The suite's directory")->required();
  dig->add_option("TEST", d->test, "A test of the suite")->required();
  dig->add_option("--arithmetic", d->arithmetic,
                  "The blend arithmetic to replay in (default zblend)");
  dig->callback([d] { run_digests(*d); });
  add_reach_command(*cmd);
  add_suite_pixel_command(*cmd);
}

}  // namespace zb::app
