// zblend trace: writes the fragment streams and pass states of a render to a trace file, which
// the testbench (zblend_tb --replay) runs on both backends.
#include <memory>

#include <fmt/core.h>

#include "cli.h"
#include "output_paths.h"
#include "scene_options.h"
#include "commands.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "io/trace.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

struct TraceOptions {
  FrameOptions frame;
  std::string method = "three-pass";
  std::string out;
  std::string background;
};

void run_trace(const TraceOptions& o) {
  const PassPlan* plan = find_plan(o.method);
  if (!plan) {
    std::vector<std::string> names;
    for (const PassPlan& p : pass_plans()) names.push_back(p.name);
    throw UsageError(fmt::format("--method: '{}' has no pass plan (choose from {})", o.method,
                                 join(names)));
  }
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const std::vector<OutputPath> outputs = {{"--out", o.out, ".zbt"}};
  check_outputs(outputs);
  const Scene scene = resolve_scene_with_background(o.frame, o.background);
  create_output_dirs(outputs);
  print_warnings("zblend trace", scene);
  const Trace trace = make_trace(rasterize_scene(scene, vp), *plan);
  write_or_fail(write_trace(o.out, trace));
  size_t fragments = 0;
  for (const TracePass& p : trace.passes) fragments += p.fragments.size();
  fmt::print("{}: {}, {} fragments, {}x{}, {} depth bits\n", o.out,
             count_text(trace.passes.size(), "pass", "passes"),
             fragments, trace.width, trace.height, trace.depth_bits);
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto o = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "trace", "Write a render's fragment streams and pass states to a trace file (.zbt)");
  add_frame_options(cmd, o->frame);
  cmd->add_option("--method,-m", o->method, "Method with a pass plan (see 'zblend methods')")
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "Output trace file (.zbt)")->required();
  add_background_option(cmd, o->background);
  cmd->callback([o] { run_trace(*o); });
}

}  // namespace zb::app
