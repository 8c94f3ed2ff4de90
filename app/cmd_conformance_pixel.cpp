// conformance pixel (zblend and the kit's zblend-conformance): the history of a few pixels of a
// conformance test's stream, from the suite alone (docs/history.md).
#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "check.h"
#include "cli.h"
#include "commands.h"
#include "io/trace.h"
#include "pixel_common.h"
#include "vectors.h"

namespace zb::app {

using namespace cli;

namespace {

struct SuitePixelOptions {
  std::string suite, test, at, json, arithmetic = "zblend";
};

void run_suite_pixel(const SuitePixelOptions& o) {
  std::vector<std::string> names;
  try {
    names = conformance::verified_test_names(o.suite);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  if (std::find(names.begin(), names.end(), o.test) == names.end())
    throw UsageError(fmt::format("TEST: '{}' is not a test of {} (its manifest.json names them)",
                                 o.test, o.suite));
  check_json(o.json);
  const std::optional<Arithmetic> arith = parse_arithmetic(o.arithmetic);
  if (!arith)
    throw UsageError(fmt::format("--arithmetic: '{}' is not an arithmetic: zblend, or <each|sum>-"
                                 "<zblend|round255|floor256|ceil256|round256>[-one256]",
                                 o.arithmetic));
  Trace trace;
  try {
    trace = conformance::read_stream(o.suite + "/" + o.test + "/stream.hex");
  } catch (const TraceError& e) {
    throw UsageError(e.what());
  }
  const FrameHistory f =
      conformance::stream_history(trace, parse_at(o.at, trace.width, trace.height), *arith);
  write_histories(f, fmt::format("conformance test {} of {} ({}{})", o.test, o.suite,
                                 count_text(f.passes.size(), "pass", "passes"),
                                 arith->is_zblend() ? "" : ", arithmetic " + o.arithmetic),
                  o.suite + "/" + o.test, "", o.json, nullptr);
}

}  // namespace

void add_suite_pixel_command(CLI::App& parent) {
  auto o = std::make_shared<SuitePixelOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "pixel", "The history of a pixel of a test of SUITE, from the suite alone: every fragment "
               "of its stream that reached the pixel and what the golden model did with it");
  cmd->add_option("SUITE", o->suite, "The suite's directory (conformance export)")->required();
  cmd->add_option("TEST", o->test, "The test's name (its directory in SUITE)")->required();
  add_at_json_options(cmd, o->at, o->json);
  cmd->add_option("--arithmetic", o->arithmetic,
                  "The DUT's declared blend arithmetic to replay in (docs/datapath.md \"Declared "
                  "arithmetic\"; default zblend)");
  cmd->callback([o] { run_suite_pixel(*o); });
}

}  // namespace zb::app
