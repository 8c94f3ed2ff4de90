// zblend pixel: the history of a few pixels of a scene under one method (docs/history.md).
#include <cstdio>
#include <memory>
#include <regex>
#include <utility>

#include <fmt/core.h>

#include "cli.h"
#include "commands.h"
#include "history/history_report.h"
#include "io/image.h"
#include "output_paths.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "scene_options.h"

namespace zb::app {

using namespace cli;

namespace {

constexpr size_t kMaxPixels = 4096;  // the histories are held whole; a frame's worth is a render

struct PixelOptions {
  FrameOptions frame;
  std::string method = "three-pass";
  std::string at;
  std::string json;
  std::string background;
  bool quiet = false;
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

void run_pixel(const PixelOptions& o) {
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const std::vector<std::pair<int, int>> pixels = parse_at(o.at, vp.width, vp.height);
  const PassPlan* plan = find_plan(o.method);
  if (!plan)
    throw UsageError(fmt::format("--method: unknown method '{}' (see 'zblend methods')", o.method));
  if (!o.json.empty() && o.json != "-") check_writable("--json", o.json, ".json");
  const Scene scene = resolve_scene_with_background(o.frame, o.background);
  if (!o.quiet) print_warnings("zblend pixel", scene);
  const RasterizedScene rs = rasterize_scene(scene, vp);
  const FrameHistory f = record_history(rs, *plan, pixels);  // replay-checked
  if (o.json == "-") {
    std::fputs(history_json(f, o.frame.scene, o.method, &scene).c_str(), stdout);
    return;
  }
  std::string text = fmt::format("scene {}, method {} ({} passes)\n", o.frame.scene, o.method, f.passes.size());
  for (const PixelHistory& h : f.pixels) text += "\n" + history_text(f, h, &scene);
  std::fputs(text.c_str(), stdout);
  if (!o.json.empty()) write_or_fail(write_file_atomic(o.json, history_json(f, o.frame.scene, o.method, &scene)));
}

}  // namespace

void add_pixel_command(CLI::App& app) {
  auto o = std::make_shared<PixelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pixel", "The history of a pixel: every fragment that reached it, pass by pass, what the "
               "tests and the blend did with it, the frame operations, its final value");
  add_frame_options(cmd, o->frame);
  cmd->add_option("--method,-m", o->method, "Method (see 'zblend methods')")->capture_default_str();
  cmd->add_option("--at", o->at, "Pixel X,Y (column, row from the top-left); several: X,Y;X,Y")
      ->required();
  cmd->add_option("--json", o->json, "The histories as JSON to this file (- : to stdout, instead of the text)");
  add_background_option(cmd, o->background);
  cmd->add_flag("--quiet,-q", o->quiet, "No scene warnings");
  cmd->callback([o] { run_pixel(*o); });
}

}  // namespace zb::app
