// zblend sweep: one parameter moved in small steps, a CSV and a chart each (docs/sweeps.md).
// The sweeps themselves are in app/lab/sweeps.h; this file parses, writes and charts.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "chart_tools.h"
#include "cli.h"
#include "output_paths.h"
#include "scene_options.h"
#include "commands.h"
#include "io/image.h"
#include "sweeps.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::vector<std::string> kSweeps = {"orbit",  "depth", "layers", "order", "alpha",
                                          "samples", "offset", "wboit", "all"};

struct SweepOptions {
  std::string name;
  std::string out_dir = "out/sweeps";
  std::string scene = "cad";
  std::string samples_scene = "parts";
  std::string methods = "all";
  int steps = lab::OrbitOptions{}.steps;
  int threshold = lab::OrbitOptions{}.threshold;
  int width = 0;   // 0: each sweep's own size
  int height = 0;
  bool no_charts = false;
  bool quiet = false;
};

bool runs(const SweepOptions& o, const char* sweep) { return o.name == sweep || o.name == "all"; }

// Everything that can be checked before any work, the output directory last (it is created).
void check_options(const SweepOptions& o) {
  if (std::find(kSweeps.begin(), kSweeps.end(), o.name) == kSweeps.end())
    throw UsageError(o.name.empty()
                         ? fmt::format("sweep: name a sweep ({})", join(kSweeps))
                         : fmt::format("sweep: unknown sweep '{}' (choose from {})", o.name,
                                       join(kSweeps)));
  if (o.steps < 2 || o.steps > 3600)
    throw UsageError(fmt::format("--steps: {} is out of range (2 to 3600)", o.steps));
  if (o.threshold < 0 || o.threshold > 254)
    throw UsageError(fmt::format("--threshold: {} is out of range (0 to 254)", o.threshold));
  if ((o.width == 0) != (o.height == 0))
    throw UsageError("--width, --height: give both or neither");
  if (o.width != 0) check_viewport(o.width, o.height, kDefaultDepthBits);
  // The samples sweep renders its ground truth this many times larger.
  const int most = kMaxFrameSize / lab::SamplesOptions{}.supersample;
  if (runs(o, "samples") && std::max(o.width, o.height) > most)
    throw UsageError(fmt::format("--width, --height: at most {} for the samples sweep (its "
                                 "reference is {} times larger)", most,
                                 lab::SamplesOptions{}.supersample));
  if (runs(o, "orbit")) resolve_scene(o.scene);
  if (runs(o, "samples")) resolve_scene(o.samples_scene);
  parse_methods(o.methods);
}

void prepare_out_dir(const std::string& dir) { create_output_dirs({{"--out-dir", dir, nullptr}}); }

class SweepRun {
 public:
  SweepRun(const SweepOptions& o, std::string python, std::string script)
      : o_(o), python_(std::move(python)), script_(std::move(script)) {}

  void run() {
    const auto t0 = Clock::now();
    const bool all = o_.name == "all";
    lab::SweepResults& r = results_;
    if (all || o_.name == "orbit") orbit();
    if (all || o_.name == "depth") depth();
    if (all || o_.name == "layers") layers();
    if (all || o_.name == "order") order();
    if (all || o_.name == "alpha") alpha();
    if (all || o_.name == "samples") samples();
    if (all || o_.name == "offset") offset();
    if (all || o_.name == "wboit") wboit();
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (all) write("sweeps.md", lab::sweeps_markdown(r));
    note(fmt::format("sweep {}: {:.0f} s, written to {}", o_.name, r.seconds, o_.out_dir));
  }

 private:
  void note(const std::string& line) const {
    if (!o_.quiet) fmt::print(stderr, "{}\n", line);
  }
  lab::SweepProgress progress() const {
    return [this](const std::string& line) { note("  " + line); };
  }
  Viewport size_or(Viewport vp) const {
    if (o_.width != 0) vp.width = o_.width, vp.height = o_.height;
    return vp;
  }
  std::vector<std::string> methods() const {
    return parse_methods(o_.methods);
  }
  Scene scene(const std::string& name) const {
    Scene s = resolve_scene(name);
    if (!o_.quiet) print_warnings("zblend sweep", s);
    return s;
  }
  void write(const std::string& file, const std::string& text) const {
    write_or_fail(write_file_atomic((fs::path(o_.out_dir) / file).string(), text));
  }
  // NAME.csv, then NAME.png from it.
  void emit(const std::string& name, const std::string& csv) const {
    write(name + ".csv", csv);
    if (script_.empty()) return;
    const std::string base = (fs::path(o_.out_dir) / name).string();
    if (!run_program({python_, script_, name, base + ".csv", base + ".png"}, false))
      throw std::runtime_error(
          fmt::format("sweep {}: the chart script failed ({})", name, script_));
  }

  void orbit() {
    lab::SweepResults& r = results_;
    r.orbit_scene = o_.scene;
    r.orbit.steps = o_.steps;
    r.orbit.threshold = o_.threshold;
    r.orbit.viewport = size_or(r.orbit.viewport);
    r.orbit.methods = methods();
    r.orbit_rows = lab::orbit_sweep(scene(o_.scene), r.orbit, progress());
    emit("orbit", lab::orbit_csv(r.orbit_rows));
  }
  void depth() {
    lab::SweepResults& r = results_;
    r.depth.viewport = size_or(r.depth.viewport);
    r.depth_rows = lab::depth_sweep(r.depth, progress());
    emit("depth", lab::depth_csv(r.depth_rows));
  }
  void layers() {
    lab::SweepResults& r = results_;
    r.layers.viewport = size_or(r.layers.viewport);
    r.layers.methods = methods();
    r.layers_rows = lab::layers_sweep(r.layers, progress());
    emit("layers", lab::method_csv("layers", r.layers_rows));
  }
  void order() {
    lab::SweepResults& r = results_;
    r.order.viewport = size_or(r.order.viewport);
    r.order_rows = lab::order_sweep(r.order, progress());
    emit("order", lab::method_csv("layers", r.order_rows));
  }
  void alpha() {
    lab::SweepResults& r = results_;
    r.alpha.viewport = size_or(r.alpha.viewport);
    r.alpha.methods = methods();
    r.alpha_rows = lab::alpha_sweep(r.alpha, progress());
    emit("alpha", lab::method_csv("alpha", r.alpha_rows));
  }
  void samples() {
    lab::SweepResults& r = results_;
    r.samples_scene = o_.samples_scene;
    r.samples.viewport = size_or(r.samples.viewport);
    r.samples_rows = lab::samples_sweep(scene(o_.samples_scene), r.samples, progress());
    emit("samples", lab::method_csv("samples", r.samples_rows));
  }

  void offset() {
    lab::SweepResults& r = results_;
    r.offset.viewport = size_or(r.offset.viewport);
    r.offset_rows = lab::offset_sweep(r.offset, progress());
    emit("offset", lab::offset_csv(r.offset_rows));
  }

  void wboit() {
    lab::SweepResults& r = results_;
    r.wboit.viewport = size_or(r.wboit.viewport);
    r.wboit_rows = lab::wboit_sweep(r.wboit, progress());
    emit("wboit", lab::wboit_csv(r.wboit_rows));
  }

  const SweepOptions& o_;
  std::string python_;
  std::string script_;
  lab::SweepResults results_;
};

void run_sweep(const SweepOptions& o) {
  check_options(o);
  const ChartTools tools = o.no_charts ? ChartTools{} : find_chart_tools("sweep_charts.py");
  prepare_out_dir(o.out_dir);
  SweepRun(o, tools.python, tools.script).run();
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Stability sweeps: camera orbit, depth separation against depth bits, layer "
               "count, alpha, coverage samples, hidden-line depth offset against face tilt, "
               "weighted blended OIT's widths; "
               "NAME.csv and NAME.png each (docs/sweeps.md)");
  cmd->add_option("name", o->name, "Sweep: " + join(kSweeps, ", ") +
                                       " ('all' also writes sweeps.md)");
  cmd->add_option("--out-dir", o->out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--scene,-s", o->scene,
                  "orbit: the scene the camera goes around (built-in or a file)")
      ->capture_default_str();
  cmd->add_option("--samples-scene", o->samples_scene,
                  "samples: the scene with many edges (its opaque objects only)")
      ->capture_default_str();
  cmd->add_option("--method,-m", o->methods,
                  "orbit, layers, alpha: methods, a comma-separated list, or 'all'")
      ->capture_default_str();
  cmd->add_option("--steps", o->steps, "orbit: frames over 360 degrees")->capture_default_str();
  cmd->add_option("--threshold", o->threshold,
                  "orbit: a pixel pops when a channel changes by more than the reference's "
                  "change plus this many 8-bit units")
      ->capture_default_str();
  cmd->add_option("--width,-W", o->width,
                  "Frame width of every sweep (default 320)");
  cmd->add_option("--height,-H", o->height, "Frame height of every sweep (default 240; with --width)");
  cmd->add_flag("--no-charts", o->no_charts, "Write the CSV files only (no python3)");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  cmd->callback([o] { run_sweep(*o); });
}

}  // namespace zb::app
