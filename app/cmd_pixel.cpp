// zblend pixel and conformance pixel: the history of a few pixels of a scene under one method,
// of a trace file, or of a conformance test's stream (docs/history.md).
#include <cstdio>
#include <functional>
#include <memory>
#include <algorithm>
#include <regex>
#include <utility>

#include <fmt/core.h>

#include "check.h"
#include "cli.h"
#include "commands.h"
#include "history/history_report.h"
#include "io/image.h"
#include "io/trace.h"
#include "output_paths.h"
#include "vectors.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "pixel_retires.h"
#include "rtl_params.h"
#include "tile_io.h"
#include "scene_options.h"

namespace zb::app {

using namespace cli;

namespace {

constexpr size_t kMaxPixels = 4096;  // the histories are held whole; a frame's worth is a render

struct PixelOptions {
  FrameOptions frame;
  std::string method = "three-pass";
  std::string backend = "golden";
  std::string schedule = "tile";
  std::string trace;
  std::string at;
  std::string json;
  std::string background;
  bool quiet = false;
};

struct SuitePixelOptions {
  std::string suite, test, at, json;
};

// "X,Y[;X,Y...]" inside a width x height frame.
std::vector<std::pair<int, int>> parse_at(const std::string& text, int width, int height) {
  if (text.empty()) throw UsageError("--at: give the pixel as X,Y (several: X,Y;X,Y)");
  static const std::regex one(R"(\s*(\d{1,6})\s*,\s*(\d{1,6})\s*)");
  std::vector<std::pair<int, int>> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(';', start), text.size());
    const std::string part = text.substr(start, end - start);
    std::smatch m;
    if (!std::regex_match(part, m, one))
      throw UsageError(fmt::format("--at: '{}' is not X,Y (two whole numbers, pixel column and "
                                   "row from the top-left)", part));
    const int x = std::stoi(m[1]), y = std::stoi(m[2]);
    if (x >= width || y >= height)
      throw UsageError(fmt::format("--at: pixel ({}, {}) is outside the {}x{} frame (columns 0 to "
                                   "{}, rows 0 to {})", x, y, width, height, width - 1, height - 1));
    for (const auto& p : out)
      if (p == std::make_pair(x, y)) throw UsageError(fmt::format("--at: pixel ({}, {}) given twice", x, y));
    out.emplace_back(x, y);
    if (out.size() > kMaxPixels)
      throw UsageError(fmt::format("--at: more than {} pixels; render the frame instead", kMaxPixels));
    start = end + 1;
  }
  return out;
}

// The histories on stdout as text (or JSON with --json -), and as JSON to a file.
void write_histories(const FrameHistory& f, const std::string& title, const std::string& source,
                     const std::string& method, const std::string& json, const Scene* scene) {
  if (json == "-") {
    std::fputs(history_json(f, source, method, scene).c_str(), stdout);
    return;
  }
  std::string text = title + "\n";
  for (const PixelHistory& h : f.pixels) text += "\n" + history_text(f, h, scene);
  std::fputs(text.c_str(), stdout);
  if (!json.empty()) write_or_fail(write_file_atomic(json, history_json(f, source, method, scene)));
}

void add_rtl(FrameHistory& f, const std::string& schedule_text,
             const std::function<void(Backend&)>& run) {
  RtlOptions o;
  if (!parse_schedule(schedule_text, o.schedule))
    throw UsageError(fmt::format("--schedule: unknown schedule '{}' (choose from tile, pass)", schedule_text));
  add_rtl_retires(f, o, run);
}

void check_backend(const CLI::App& cmd, const PixelOptions& o, int depth_bits) {
  if (o.backend != "golden" && o.backend != "rtl")
    throw UsageError(fmt::format("--backend: unknown backend '{}' (choose from golden, rtl)", o.backend));
  if (o.backend == "golden" && cmd.count("--schedule"))
    throw UsageError("--schedule: needs --backend rtl");
  if (o.backend == "rtl" && depth_bits != kRtlDepthBits)
    throw UsageError(fmt::format("--backend rtl: the RTL model is built with {}-bit depth, not {}",
                                 kRtlDepthBits, depth_bits));
}

void check_json(const std::string& json) {
  if (!json.empty() && json != "-") check_writable("--json", json, ".json");
}

void run_trace_pixel(const CLI::App& cmd, const PixelOptions& o) {
  for (const char* option : {"--scene", "--camera", "--width", "--height", "--depth-bits", "--method",
                             "--background"})
    if (cmd.count(option))
      throw UsageError(fmt::format("--trace, {}: a trace holds its frame and passes; give one of them",
                                   option));
  check_json(o.json);
  Trace trace;
  try {
    trace = read_trace(o.trace);
  } catch (const TraceError& e) {
    throw UsageError(e.what());
  }
  check_backend(cmd, o, trace.depth_bits);
  FrameHistory f = record_history(trace, parse_at(o.at, trace.width, trace.height));
  if (o.backend == "rtl") add_rtl(f, o.schedule, [&](Backend& b) { replay_trace(trace, b); });
  write_histories(f, fmt::format("trace {} ({} passes)", o.trace, f.passes.size()), o.trace, "", o.json, nullptr);
}

void run_pixel(const CLI::App& cmd, const PixelOptions& o) {
  if (!o.trace.empty()) return run_trace_pixel(cmd, o);
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const std::vector<std::pair<int, int>> pixels = parse_at(o.at, vp.width, vp.height);
  const PassPlan* plan = find_plan(o.method);
  if (!plan)
    throw UsageError(fmt::format("--method: unknown method '{}' (see 'zblend methods')", o.method));
  check_backend(cmd, o, vp.depth_bits);
  check_json(o.json);
  const Scene scene = resolve_scene_with_background(o.frame, o.background);
  if (!o.quiet) print_warnings("zblend pixel", scene);
  const RasterizedScene rs = rasterize_scene(scene, vp);
  FrameHistory f = record_history(rs, *plan, pixels);  // replay-checked
  if (o.backend == "rtl") add_rtl(f, o.schedule, [&](Backend& b) { render(rs, *plan, b); });
  write_histories(f, fmt::format("scene {}, method {} ({} passes)", o.frame.scene, o.method, f.passes.size()),
                  o.frame.scene, o.method, o.json, &scene);
}

void run_suite_pixel(const SuitePixelOptions& o) {
  std::vector<std::string> names;
  try {
    names = conformance::suite_test_names(o.suite);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  if (std::find(names.begin(), names.end(), o.test) == names.end())
    throw UsageError(fmt::format("TEST: '{}' is not a test of {} (its manifest.json names them)",
                                 o.test, o.suite));
  check_json(o.json);
  Trace trace;
  try {
    trace = conformance::read_stream(o.suite + "/" + o.test + "/stream.hex");
  } catch (const TraceError& e) {
    throw UsageError(e.what());
  }
  for (TracePass& p : trace.passes) p.name.clear();  // stream.hex names none: decode numbers them
  const FrameHistory f = record_history(trace, parse_at(o.at, trace.width, trace.height));
  write_histories(f, fmt::format("conformance test {} of {} ({} passes)", o.test, o.suite, f.passes.size()),
                  o.suite + "/" + o.test, "", o.json, nullptr);
}

}  // namespace

void add_pixel_command(CLI::App& app) {
  auto o = std::make_shared<PixelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pixel", "The history of a pixel: every fragment that reached it, pass by pass, what the "
               "tests and the blend did with it, the frame operations, its final value");
  add_frame_options(cmd, o->frame);
  cmd->add_option("--method,-m", o->method, "Method (see 'zblend methods')")->capture_default_str();
  cmd->add_option("--trace", o->trace, "A trace file (.zbt, zblend trace) instead of a scene and method");
  cmd->add_option("--backend,-b", o->backend,
                  "golden, or rtl: the Verilated RTL runs the frame too, and each fragment's "
                  "retire (its cycles, and a write that is not the golden model's) is shown")
      ->capture_default_str();
  cmd->add_option("--schedule", o->schedule, "RTL: tile or pass (as zblend render)")->capture_default_str();
  cmd->add_option("--at", o->at, "Pixel X,Y (column, row from the top-left); several: X,Y;X,Y")
      ->required();
  cmd->add_option("--json", o->json, "The histories as JSON to this file (- : to stdout, instead of the text)");
  add_background_option(cmd, o->background);
  cmd->add_flag("--quiet,-q", o->quiet, "No scene warnings");
  cmd->callback([o, cmd] { run_pixel(*cmd, *o); });
}

void add_suite_pixel_command(CLI::App& parent) {
  auto o = std::make_shared<SuitePixelOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "pixel", "The history of a pixel of a test of SUITE, from the suite alone: every fragment "
               "of its stream that reached the pixel and what the golden model did with it");
  cmd->add_option("SUITE", o->suite, "The suite's directory (conformance export)")->required();
  cmd->add_option("TEST", o->test, "The test's name (its directory in SUITE)")->required();
  cmd->add_option("--at", o->at, "Pixel X,Y (column, row from the top-left); several: X,Y;X,Y")
      ->required();
  cmd->add_option("--json", o->json, "The histories as JSON to this file (- : to stdout, instead of the text)");
  cmd->callback([o] { run_suite_pixel(*o); });
}

}  // namespace zb::app
