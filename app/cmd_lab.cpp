// zblend lab: methods x scenes, cost against error, charts and a report (docs/lab.md).
// The runs are in app/lab/lab.h and the report in app/lab/report.h; this file picks the scenes,
// spreads them over threads, writes the files and calls scripts/lab_charts.py.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

#include <fmt/core.h>

#include "chart_tools.h"
#include "cli.h"
#include "output_paths.h"
#include "scene_options.h"
#include "commands.h"
#include "io/image.h"
#include "lab.h"
#include "parallel/parallel.h"
#include "pipeline/passes.h"
#include "report.h"
#include "rtl_rop.h"
#include "io/scene_file.h"
#include "scene/scene_suite.h"
#include "scene/builtin_scenes.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct LabCommandOptions {
  std::string scenes = "all";
  std::string methods = "all";
  int width = 320;
  int height = 240;
  std::string out_dir = "out/lab";
  bool rtl = true;
  int jobs = 2;
  int supersample = 4;
  bool no_charts = false;
  bool quiet = false;
};

// The real scenes the lab runs besides the suite: short name, file, camera (empty: fitted).
struct RealScene {
  const char* name;
  const char* path;
  const char* camera;
};
constexpr RealScene kRealScenes[] = {
    {"regr01", "/usr/share/assimp/models/OBJ/regr01.obj",
     "eye=-500,-700,420,at=600,350,100,fov=40,up=0,0,1"},  // the house and its windows
    {"clearcoat", "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf", ""},
    {"bunny", "/usr/share/glmark2/models/bunny.obj", ""},
};

// Built-in scenes the lab runs when the suite does not already hold them.
constexpr const char* kBuiltinScenes[] = {"cad", "quads", "sphere-torus", "parts"};

lab::LabScene named_scene(const std::string& name, const std::string& family,
                          const std::string& description, const std::string& source,
                          const std::string& camera, bool quiet) {
  return {name, family, description, [name, source, camera, quiet] {
            Scene scene = resolve_scene(source, camera);
            if (!quiet) print_warnings("zblend lab: " + name, scene);
            return scene;
          }};
}

// Every scene of `zblend lab` with no --scenes: the suite, the built-ins, the real scenes that
// are installed (a missing one is named on stderr unless `quiet_missing`).
std::vector<lab::LabScene> default_scenes(bool quiet_missing, bool quiet) {
  std::vector<lab::LabScene> out;
  auto listed = [&](const std::string& n) {
    return std::any_of(out.begin(), out.end(), [&](const lab::LabScene& s) { return s.name == n; });
  };
  for (const SuiteScene& s : scene_suite())
    if (!listed(s.name))
      out.push_back(named_scene(s.name, s.family, s.description, s.name, "", quiet));
  for (const char* name : kBuiltinScenes) {
    if (listed(name)) continue;
    for (const SceneInfo& b : builtin_scenes())
      if (b.name == name)
        out.push_back(named_scene(name, "built-in", b.description, name, "", quiet));
  }
  for (const RealScene& r : kRealScenes) {
    std::error_code ec;
    if (fs::is_regular_file(r.path, ec))
      out.push_back(named_scene(r.name, "real", r.path, r.path, r.camera, quiet));
    else if (!quiet_missing)
      fmt::print(stderr, "zblend lab: skipping {}: {} is not installed (scripts/setup.sh)\n",
                 r.name, r.path);
  }
  return out;
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  if (!list.empty() && list.back() == ',') out.push_back("");
  return out;
}

// --scenes: "all", or names from the default list, suite scenes such as layers-N-aP, or scene
// files.
std::vector<lab::LabScene> pick_scenes(const LabCommandOptions& o) {
  std::vector<lab::LabScene> all = default_scenes(o.quiet || o.scenes != "all", o.quiet);
  if (o.scenes == "all") return all;
  std::vector<lab::LabScene> out;
  for (const std::string& name : split(o.scenes)) {
    auto it = std::find_if(all.begin(), all.end(), [&](const lab::LabScene& s) { return s.name == name; });
    if (it != all.end()) {
      out.push_back(*it);
      continue;
    }
    for (const RealScene& r : kRealScenes)
      if (name == r.name)
        throw UsageError(fmt::format("--scenes: '{}' needs {}, which is not installed "
                                     "(scripts/setup.sh)", name, r.path));
    if (suite_scene(name)) {
      out.push_back(named_scene(name, "layers", name, name, "", o.quiet));
      continue;
    }
    if (is_scene_path(name)) {
      std::error_code ec;
      if (!fs::is_regular_file(name, ec))
        throw UsageError(fmt::format("--scenes: no scene file '{}'", name));
      out.push_back(named_scene(fs::path(name).stem().string(), "file", name, name, "", o.quiet));
      continue;
    }
    std::vector<std::string> names;
    for (const lab::LabScene& s : all) names.push_back(s.name);
    throw UsageError(fmt::format("--scenes: unknown scene '{}' (choose from {}, layers-N-aP, "
                                 "all, or a .obj, .gltf or .glb file)", name, join(names)));
  }
  for (size_t i = 0; i < out.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (lab::path_name(out[i].name) == lab::path_name(out[j].name))
        throw UsageError(fmt::format("--scenes: '{}' is listed twice", out[i].name));
  return out;
}

std::vector<std::string> pick_methods(const std::string& list) {
  const std::vector<std::string> valid = method_names();
  if (list == "all") return valid;
  std::vector<std::string> out;
  for (const std::string& m : split(list)) {
    if (std::find(valid.begin(), valid.end(), m) == valid.end())
      throw UsageError(fmt::format("--methods: unknown method '{}' (choose from {}, or all)", m,
                                   join(valid)));
    if (std::find(out.begin(), out.end(), m) != out.end())
      throw UsageError(fmt::format("--methods: '{}' is listed twice", m));
    out.push_back(m);
  }
  return out;
}

void check_options(const LabCommandOptions& o) {
  check_viewport(o.width, o.height, kRtlDepthBits);
  if (o.jobs < 1 || o.jobs > 64)
    throw UsageError(fmt::format("-j: {} is out of range (1 to 64)", o.jobs));
  const int max_factor = std::min(kMaxFrameSize / o.width, kMaxFrameSize / o.height);
  if (o.supersample < 1 || o.supersample > std::min(8, max_factor))
    throw UsageError(fmt::format("--supersample: {} is out of range (1 to {} at {}x{})",
                                 o.supersample, std::min(8, max_factor), o.width, o.height));
  create_output_dirs({{"--out-dir", o.out_dir, nullptr}});
}

void write(const fs::path& path, const std::string& text) {
  write_or_fail(write_file_atomic(path.string(), text));
}

void write_scene_images(const fs::path& dir, const lab::LabScene& s, const lab::SceneRun& run) {
  std::error_code ec;
  fs::create_directories(dir / fs::path(lab::image_path(s.name, "x")).parent_path(), ec);
  for (size_t i = 0; i < run.rows.size(); ++i) {
    write_or_fail(write_png((dir / lab::image_path(s.name, run.rows[i].method)).string(), run.images[i]));
    write_or_fail(write_png((dir / lab::error_image_path(s.name, run.rows[i].method)).string(),
                            run.error_images[i]));
    if (!run.histories[i].empty())
      write(dir / lab::history_path(s.name, run.rows[i].method), run.histories[i]);
  }
  write_or_fail(write_png((dir / lab::reference_ss_path(s.name)).string(), run.reference_ss));
}

// Runs the scenes on `jobs` threads, writing each scene's images as it finishes; results in
// scene order. The first failure stops the others from starting new scenes and is rethrown.
std::vector<lab::SceneRun> run_scenes(const std::vector<lab::LabScene>& scenes,
                                      const lab::LabOptions& lo, const LabCommandOptions& o) {
  std::vector<lab::SceneRun> runs(scenes.size());
  std::vector<std::exception_ptr> errors(scenes.size());
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex print;
  size_t done = 0;
  const auto start = Clock::now();
  auto worker = [&] {
    for (size_t i; !failed && (i = next++) < scenes.size();) {
      try {
        lab::SceneRun run = lab::run_scene(scenes[i], lo);
        write_scene_images(o.out_dir, scenes[i], run);
        // Images are on disk: keep only the numbers.
        run.images.clear();
        run.error_images.clear();
        run.histories.clear();
        run.reference = run.reference_ss = Framebuffer{};
        std::lock_guard<std::mutex> lock(print);
        ++done;
        if (!o.quiet)
          fmt::print(stderr, "[{:>2}/{}] {:<16} {:>4} triangles, {} methods, {:6.1f} s; elapsed "
                     "{:6.1f} s\n", done, scenes.size(), scenes[i].name, run.triangles,
                     run.rows.size(), run.ms / 1000.0,
                     std::chrono::duration<double>(Clock::now() - start).count());
        runs[i] = std::move(run);
      } catch (...) {
        errors[i] = std::current_exception();
        failed = true;
      }
    }
  };
  run_workers(std::min<int>(o.jobs, static_cast<int>(scenes.size())), [&](int) { worker(); });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return runs;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void run_lab(const LabCommandOptions& o) {
  const std::vector<std::string> methods = pick_methods(o.methods);
  const std::vector<lab::LabScene> scenes = pick_scenes(o);
  check_options(o);
  const ChartTools tools = o.no_charts ? ChartTools{} : find_chart_tools("lab_charts.py");

  lab::LabOptions lo;
  lo.viewport = Viewport{o.width, o.height, kRtlDepthBits, kRtlCoverageSamples};
  lo.methods = methods;
  lo.rtl = o.rtl;
  lo.supersample = o.supersample;
  if (!o.quiet)
    fmt::print(stderr, "zblend lab: {} methods x {} scenes at {}x{}, {}, {} thread{}\n",
               methods.size(), scenes.size(), o.width, o.height,
               o.rtl ? fmt::format("golden model and RTL ({})", RtlRop::build())
                     : std::string("golden model only"),
               o.jobs, o.jobs > 1 ? "s" : "");
  const auto start = Clock::now();
  const std::vector<lab::SceneRun> runs = run_scenes(scenes, lo, o);

  lab::ReportInput in;
  in.width = o.width;
  in.height = o.height;
  in.supersample = o.supersample;
  in.rtl = o.rtl;
  for (size_t i = 0; i < scenes.size(); ++i) {
    in.scenes.push_back({scenes[i].name, scenes[i].family, scenes[i].description,
                         runs[i].triangles, runs[i].fragments});
    in.rows.insert(in.rows.end(), runs[i].rows.begin(), runs[i].rows.end());
  }
  in.summaries = lab::summarize(in.rows);
  in.line_summaries = lab::line_summary(in.rows);
  const fs::path dir = o.out_dir;
  write(dir / "lab.csv", lab::lab_csv(in.rows));
  write(dir / "lab_summary.csv", lab::summary_csv(in.summaries));
  std::error_code stale;
  if (in.line_summaries.empty()) {  // no hidden-line method ran: no stale file or chart
    fs::remove(dir / "lab_lines.csv", stale);
    fs::remove(dir / lab::hidden_line_chart_path(), stale);
  }
  else
    write(dir / "lab_lines.csv", lab::line_summary_csv(in.line_summaries));

  if (!o.no_charts) {
    std::error_code ec;
    fs::create_directories(dir / "charts", ec);
    if (!run_program({tools.python, tools.script, (dir / "lab_summary.csv").string(),
                      (dir / "charts").string(), std::to_string(kRtlBeat)}, false))
      throw std::runtime_error("scripts/lab_charts.py failed (its message above)");
  }
  std::vector<std::string> candidates = {lab::main_chart_path(), lab::main_bytes_chart_path(),
                                         lab::tile_beat_chart_path(),
                                         lab::port_bytes_chart_path(),
                                         lab::hidden_line_chart_path()};
  for (const lab::ReportScene& s : in.scenes) candidates.push_back(lab::family_chart_path(s.family));
  for (const std::string& c : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(dir / c, ec) &&
        std::find(in.charts.begin(), in.charts.end(), c) == in.charts.end())
      in.charts.push_back(c);
  }

  std::error_code ec;
  if (fs::is_regular_file(dir / "sweeps" / "sweeps.md", ec))
    in.sweeps_markdown = read_text(dir / "sweeps" / "sweeps.md");
  if (fs::is_directory(dir / "sweeps", ec))
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "sweeps", ec))
      if (e.path().extension() == ".png") in.sweep_images.push_back("sweeps/" + e.path().filename().string());
  std::sort(in.sweep_images.begin(), in.sweep_images.end());

  if (!o.quiet) {
    fmt::print(stderr, "zblend lab: {}\n", lab::tile_share_text(in.rows, kRtlBeat));
    fmt::print(stderr, "zblend lab: {}\n", lab::stream_share_text(in.rows, kRtlBeat));
    fmt::print(stderr, "zblend lab: {}", lab::schedule_text(in.rows));
  }
  write(dir / "report.md", lab::report_markdown(in));
  write(dir / "report.html", lab::report_html(in));
  if (!o.quiet)
    fmt::print(stderr, "zblend lab: {} rows in {:.1f} s: {}\n", in.rows.size(),
               std::chrono::duration<double>(Clock::now() - start).count(),
               (dir / "report.html").string());
}

}  // namespace

void add_lab_command(CLI::App& app) {
  auto o = std::make_shared<LabCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lab", "Run every method on the scene suite: cost against error, charts and a report "
             "(docs/lab.md)");
  cmd->add_option("--scenes", o->scenes,
                  "Comma-separated scenes: suite and built-in names, layers-N-aP, regr01, "
                  "clearcoat, bunny, scene files; or all")
      ->capture_default_str();
  cmd->add_option("--methods,--method,-m", o->methods,
                  "Comma-separated methods (see 'zblend methods'), or all")
      ->capture_default_str();
  cmd->add_option("--width,-W", o->width, "Frame width in pixels")->capture_default_str();
  cmd->add_option("--height,-H", o->height, "Frame height in pixels")->capture_default_str();
  cmd->add_option("--out-dir", o->out_dir,
                  "Output directory: lab.csv, lab_summary.csv, images/, charts/, report.md and "
                  "report.html; sweeps/ is read if present")
      ->capture_default_str();
  // Two flags, so that the help shows the default once and plainly.
  cmd->add_flag("--rtl", "Also run each method on the Verilated RTL for its cycle count (the "
                         "default)");
  cmd->add_flag_callback("--no-rtl", [o] { o->rtl = false; },
                         "Golden model only: no RTL cycle counts");
  cmd->add_option("-j,--jobs", o->jobs, "Scenes run at once, one thread each")
      ->capture_default_str();
  cmd->add_option("--supersample", o->supersample,
                  "Samples per pixel per axis of the supersampled reference")
      ->capture_default_str();
  cmd->add_flag("--no-charts", o->no_charts, "Skip scripts/lab_charts.py (no python3-matplotlib)");
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors");
  cmd->callback([o, cmd] {
    if (cmd->count("--rtl") && cmd->count("--no-rtl"))
      throw UsageError("--rtl, --no-rtl: give one of them");
    run_lab(*o);
  });
}

}  // namespace zb::app
