// zblend pixel: the history of a few pixels of a scene under one method or of a trace file, on
// the golden model and beside the RTL (docs/history.md).
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <utility>

#include <fmt/core.h>
#include <fmt/format.h>

#include "cli.h"
#include "commands.h"
#include "output_paths.h"
#include "pixel_common.h"
#include "io/trace.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "pixel_retires.h"
#include "rtl_params.h"
#include "tile_io.h"
#include "scene_options.h"

namespace zb::app {

using namespace cli;

namespace {

struct PixelOptions {
  FrameOptions frame;
  std::string method = "three-pass";
  std::string backend = "golden";
  std::string schedule = "tile";
  std::string waves;
  std::string trace;
  std::string at;
  std::string json;
  std::string background;
  bool quiet = false;
};

void add_rtl(FrameHistory& f, const PixelOptions& po, const std::function<void(Backend&)>& run) {
  RtlOptions o;
  if (!parse_schedule(po.schedule, o.schedule))
    throw UsageError(fmt::format("--schedule: unknown schedule '{}' (choose from tile, pass)", po.schedule));
  o.trace_path = po.waves;
  add_rtl_retires(f, o, run);
  if (po.waves.empty()) return;
  std::vector<std::vector<std::string>> files;
  try {
    files = write_pixel_save_files(f, po.waves);
  } catch (const std::exception& e) {  // nothing half-written: the FST and any save file go
    std::error_code ec;
    std::filesystem::remove(po.waves, ec);
    for (const PixelHistory& h : f.pixels)
      for (size_t page = 1;; ++page)
        if (!std::filesystem::remove(pixel_save_file_path(po.waves, h.x, h.y, f.pixels.size() > 1, page), ec))
          break;
    throw UsageError(fmt::format("--waves: {}", e.what()));
  }
  for (size_t k = 0; k < files.size(); ++k) {
    const std::vector<std::string>& pages = files[k];
    fmt::print(stderr, "zblend pixel: waves: {} (the whole run); pixel ({}, {}): {} (gtkwave {}): "
                       "markers at its fragments' accepts and writes, {} a save file\n",
               po.waves, f.pixels[k].x, f.pixels[k].y, fmt::join(pages, ", "), pages.front(),
               kMarkersPerSaveFile);
  }
}

// Every output is checked, and its directory made, before the frame runs: a bad path fails at
// once, naming its option, with nothing written.
void prepare_outputs(const PixelOptions& o, const std::vector<std::pair<int, int>>& pixels) {
  check_json(o.json);
  std::vector<OutputPath> outputs{{"--json", o.json == "-" ? "" : o.json, ".json"},
                                  {"--waves", o.waves, ".fst"}};
  if (!o.waves.empty())
    for (const auto& [x, y] : pixels)
      outputs.push_back({"--waves", pixel_save_file_path(o.waves, x, y, pixels.size() > 1), ".gtkw"});
  create_output_dirs(outputs);
}

void check_backend(const CLI::App& cmd, const PixelOptions& o, int depth_bits) {
  if (o.backend != "golden" && o.backend != "rtl" && o.backend != "both")
    throw UsageError(fmt::format("--backend: unknown backend '{}' (choose from golden, rtl, both)", o.backend));
  for (const char* option : {"--schedule", "--waves"})
    if (o.backend == "golden" && cmd.count(option))
      throw UsageError(fmt::format("{}: needs --backend rtl or both", option));
  if (o.backend != "golden" && depth_bits != kRtlDepthBits)
    throw UsageError(fmt::format("--backend rtl: the RTL model is built with {}-bit depth, not {}",
                                 kRtlDepthBits, depth_bits));
}

void run_trace_pixel(const CLI::App& cmd, const PixelOptions& o) {
  for (const char* option : {"--scene", "--camera", "--width", "--height", "--depth-bits", "--method",
                             "--background"})
    if (cmd.count(option))
      throw UsageError(fmt::format("--trace, {}: a trace holds its frame and passes; give one of them",
                                   option));
  Trace trace;
  try {
    trace = read_trace(o.trace);
  } catch (const TraceError& e) {
    throw UsageError(e.what());
  }
  check_backend(cmd, o, trace.depth_bits);
  const std::vector<std::pair<int, int>> pixels = parse_at(o.at, trace.width, trace.height);
  prepare_outputs(o, pixels);
  FrameHistory f = record_history(trace, pixels);
  if (o.backend != "golden") add_rtl(f, o, [&](Backend& b) { replay_trace(trace, b); });
  write_histories(f, fmt::format("trace {} ({})", o.trace, count_text(f.passes.size(), "pass", "passes")), o.trace, "", o.json, nullptr);
}

void run_pixel(const CLI::App& cmd, const PixelOptions& o) {
  if (!o.trace.empty()) return run_trace_pixel(cmd, o);
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const std::vector<std::pair<int, int>> pixels = parse_at(o.at, vp.width, vp.height);
  const PassPlan* plan = find_plan(o.method);
  if (!plan)
    throw UsageError(fmt::format("--method: unknown method '{}' (see 'zblend methods')", o.method));
  check_backend(cmd, o, vp.depth_bits);
  prepare_outputs(o, pixels);
  const Scene scene = resolve_scene_with_background(o.frame, o.background);
  if (!o.quiet) print_warnings("zblend pixel", scene);
  const RasterizedScene rs = rasterize_scene(scene, vp);
  FrameHistory f = record_history(rs, *plan, pixels);  // replay-checked
  if (o.backend != "golden") add_rtl(f, o, [&](Backend& b) { render(rs, *plan, b); });
  write_histories(f, fmt::format("scene {}, method {} ({})", o.frame.scene, o.method,
                                 count_text(f.passes.size(), "pass", "passes")),
                  o.frame.scene, o.method, o.json, &scene);
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
                  "golden, or rtl (both: the same): the Verilated RTL runs the frame too, and each "
                  "fragment's retire (its cycles, and a write that is not the golden model's) is shown")
      ->capture_default_str();
  cmd->add_option("--schedule", o->schedule, "RTL: tile or pass (as zblend render)")->capture_default_str();
  cmd->add_option("--waves", o->waves,
                  "RTL: the run's FST, and beside it a GTKWave save file per pixel with a marker at "
                  "each of its accepts and writes (F.gtkw; F-X-Y.gtkw for several pixels)");
  add_at_json_options(cmd, o->at, o->json);
  add_background_option(cmd, o->background);
  cmd->add_flag("--quiet,-q", o->quiet, "No scene warnings");
  cmd->callback([o, cmd] { run_pixel(*cmd, *o); });
}

}  // namespace zb::app
