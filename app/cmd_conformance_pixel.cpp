// conformance pixel (zblend and the kit's zblend-conformance): the history of a few pixels of a
// conformance test's stream, from the suite alone (docs/history.md).
#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "check.h"
#include "suite.h"
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
  Trace trace;
  try {
    trace = conformance::read_test_stream(o.suite, o.test);
  } catch (const zb::conformance::ConformanceError& e) {
    throw UsageError(e.what());
  }
  check_json(o.json);
  const std::optional<Arithmetic> arith = parse_arithmetic(o.arithmetic);
  if (!arith) throw UsageError("--arithmetic: " + arithmetic_error(o.arithmetic));
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
