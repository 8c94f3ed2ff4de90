// Option checks shared by the subcommands.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <mutex>
#include <set>
#include <thread>
#include <unistd.h>

#include <fmt/core.h>

#include "commands.h"
#include "pipeline/passes.h"
#include "io/scene_file.h"
#include "scene/camera.h"
#include "scene/builtin_scenes.h"

namespace zb::app {

namespace fs = std::filesystem;

std::string join(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

Scene resolve_scene(const std::string& name, const std::string& camera) {
  // Checked first: a bad --camera fails before a large file is read.
  std::optional<CameraSpec> spec;
  if (!camera.empty()) {
    try {
      spec = parse_camera_spec(camera);
    } catch (const std::invalid_argument& e) {
      throw UsageError(fmt::format("--camera: {}", e.what()));
    }
  }
  // A built-in name wins; any other name that exists on disk (a directory, a file without a
  // known extension) goes to the loader, which says what is wrong with it.
  std::optional<Scene> scene = is_scene_path(name) ? std::nullopt : builtin_scene(name);
  std::error_code ec;
  if (!scene && (is_scene_path(name) || fs::exists(name, ec))) {
    try {
      scene = load_scene_file(name);
    } catch (const SceneFileError& e) {
      throw UsageError(fmt::format("--scene: {}", e.what()));
    }
  }
  if (!scene) {
    std::vector<std::string> names;
    for (const SceneInfo& s : builtin_scenes()) names.push_back(s.name);
    throw UsageError(fmt::format("--scene: unknown scene '{}' (choose from {}, or a .obj, .gltf or "
                                 ".glb file)", name, join(names)));
  }
  if (spec) {
    try {
      aim_camera(*scene, *spec);
    } catch (const std::invalid_argument& e) {
      throw UsageError(fmt::format("--camera: {}", e.what()));
    }
  }
  return std::move(*scene);
}

std::vector<std::string> parse_methods(const std::string& list) {
  const std::vector<std::string> valid = method_names();
  if (list == "all") return valid;
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    if (std::find(valid.begin(), valid.end(), name) == valid.end())
      throw UsageError(fmt::format("--method: unknown method '{}' (choose from {}, or all)", name,
                                   join(valid)));
    out.push_back(name);
    start = comma + 1;
  }
  return out;
}

namespace {

void check_range(const char* option, int value, int lo, int hi) {
  if (value < lo || value > hi)
    throw UsageError(fmt::format("{}: {} is out of range ({} to {})", option, value, lo, hi));
}

}  // namespace

void add_frame_options(CLI::App* cmd, FrameOptions& o) {
  cmd->add_option("--scene,-s", o.scene,
                  "Built-in scene (see 'zblend scenes') or a file: .obj (+.mtl), .gltf, .glb "
                  "(docs/scenes.md)")
      ->capture_default_str();
  cmd->add_option("--camera", o.camera,
                  "Camera eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z] (default: the scene's own; "
                  "files: fitted to the bounds; up: +y, or -z looking straight up or down)");
  cmd->add_option("--width,-W", o.width, "Frame width in pixels")->capture_default_str();
  cmd->add_option("--height,-H", o.height, "Frame height in pixels")->capture_default_str();
  cmd->add_option("--depth-bits", o.depth_bits, "Depth buffer width in bits")
      ->capture_default_str();
}

int default_threads() {
  return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMaxThreads);
}

void add_threads_option(CLI::App* cmd, int& threads, const std::string& help) {
  cmd->add_option("--threads", threads,
                  fmt::format("{} (1 to {}; default: every core)", help, kMaxThreads))
      ->capture_default_str();
}

void check_threads(int threads) { check_range("--threads", threads, 1, kMaxThreads); }

Viewport check_viewport(int width, int height, int depth_bits) {
  check_range("--width", width, 1, kMaxFrameSize);
  check_range("--height", height, 1, kMaxFrameSize);
  check_range("--depth-bits", depth_bits, kMinDepthBits, kMaxDepthBits);
  return {width, height, depth_bits};
}

void add_background_option(CLI::App* cmd, std::string& text) {
  cmd->add_option("--background", text,
                  "Background colour R,G,B or R,G,B,A, 0 to 255 each (A: 255 if left out), "
                  "instead of the scene's");
}

std::optional<Rgba8> parse_background(const std::string& text) {
  if (text.empty()) return std::nullopt;
  uint8_t v[4] = {0, 0, 0, 255};
  size_t n = 0, start = 0;
  for (; start <= text.size() && n < 4; ++n) {
    const size_t comma = std::min(text.find(',', start), text.size());
    int x = -1;
    const auto [end, ec] = std::from_chars(text.data() + start, text.data() + comma, x);
    if (ec != std::errc() || end != text.data() + comma || x < 0 || x > 255) break;
    v[n] = static_cast<uint8_t>(x);
    start = comma + 1;
  }
  if (start <= text.size() || n < 3)
    throw UsageError(
        fmt::format("--background: '{}' is not R,G,B or R,G,B,A, each 0 to 255", text));
  return Rgba8{v[0], v[1], v[2], v[3]};
}

Scene resolve_scene_with_background(const FrameOptions& frame, const std::string& background) {
  const std::optional<Rgba8> colour = parse_background(background);
  Scene scene = resolve_scene(frame.scene, frame.camera);
  if (colour) scene.background = *colour;
  return scene;
}

namespace {

// The nearest existing directory at or above `dir` (empty: "."), which must be writable with no
// file on the way.
void check_dir_above(const char* option, fs::path dir) {
  if (dir.empty()) dir = ".";
  std::error_code ec;
  while (!fs::exists(dir, ec)) {
    const fs::path up = dir.parent_path();
    if (up == dir) break;
    dir = up.empty() ? fs::path(".") : up;
  }
  if (!fs::is_directory(dir, ec))
    throw UsageError(fmt::format("{}: {} is a file, not a directory", option, dir.string()));
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError(fmt::format("{}: directory '{}' is not writable", option, dir.string()));
}

void check_output(const OutputPath& o) {
  if (o.path.empty()) return;
  const fs::path path(o.path);
  if (!o.extension) return check_dir_above(o.option, path);
  if (path.extension() != o.extension)
    throw UsageError(fmt::format("{}: '{}' must end in {}", o.option, o.path, o.extension));
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(fmt::format("{}: {} is a directory, not a {} file", o.option, o.path,
                                 o.extension));
  check_dir_above(o.option, path.parent_path());
}

}  // namespace

void check_outputs(const std::vector<OutputPath>& outputs) {
  for (const OutputPath& o : outputs) check_output(o);
}

void create_output_dirs(const std::vector<OutputPath>& outputs) {
  check_outputs(outputs);
  for (const OutputPath& o : outputs) {
    const fs::path dir = o.extension ? fs::path(o.path).parent_path() : fs::path(o.path);
    std::error_code ec;
    if (!o.path.empty() && !dir.empty()) fs::create_directories(dir, ec);
    if (ec)
      throw UsageError(fmt::format("{}: cannot create directory '{}': {}", o.option, dir.string(),
                                   ec.message()));
  }
}

void check_writable(const char* option, const std::string& path, const char* extension) {
  check_output({option, path, extension});
}

void write_or_fail(const std::string& error) {
  if (!error.empty()) throw UsageError(error);
}

void print_warnings(const std::string& program, const Scene& scene) {
  static std::mutex mutex;
  static std::set<std::string> printed;  // scene name and warning: lab loads scenes repeatedly
  const std::lock_guard<std::mutex> lock(mutex);
  for (const std::string& w : scene.warnings)
    if (printed.insert(scene.name + '\n' + w).second)
      fmt::print(stderr, "{}: warning: {}\n", program, w);
}

namespace {

// Optimal string alignment distance: edits, with a swap of neighbours as one.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                          d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The option of `cmd` closest to `typed`, or "" when none is close: at most a third of the
// name's letters wrong, and never all of them.
std::string closest_option(const CLI::App& cmd, const std::string& typed) {
  const size_t letters = typed.size() - std::min(typed.find_first_not_of('-'), typed.size());
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const CLI::Option* opt : cmd.get_options()) {
    std::vector<std::string> names;
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    for (const std::string& n : names) {
      const size_t d = edit_distance(typed, n);
      if (d < best_distance) {
        best_distance = d;
        best = n;
      }
    }
  }
  const bool close = best_distance <= std::max<size_t>(1, letters / 3) && best_distance < letters;
  return close ? best : "";
}

bool is_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && !std::isdigit(static_cast<unsigned char>(arg[1])) &&
         arg[1] != '.';
}

}  // namespace

std::string parse_error_line(const CLI::App& app, const CLI::ParseError& e) {
  const CLI::App* cmd = &app;
  std::string program = app.get_name();
  while (!cmd->get_subcommands().empty()) {
    cmd = cmd->get_subcommands().front();
    program += " " + cmd->get_name();
  }
  // An unknown option first: it may be a misspelt required one.
  const std::vector<std::string> extras = app.remaining(true);
  const auto option = std::find_if(extras.begin(), extras.end(), is_option);
  const bool extra = e.get_exit_code() == static_cast<int>(CLI::ExitCodes::ExtrasError);
  if (option == extras.end() && extra && !extras.empty())
    return fmt::format("{}: error: unexpected argument '{}' (see '{} --help')", program,
                       extras.front(), program);
  if (option == extras.end())
    return fmt::format("{}: error: {} (see '{} --help')", app.get_name(), e.what(), program);
  const std::string typed = option->substr(0, option->find('='));
  const std::string near = closest_option(*cmd, typed);
  if (near.empty())
    return fmt::format("{}: error: unknown option '{}' (see '{} --help')", program, typed, program);
  return fmt::format("{}: error: unknown option '{}'; did you mean '{}'?", program, typed, near);
}

int run_app(CLI::App& app, int argc, char** argv) {
  const std::string name = app.get_name();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s\n", parse_error_line(app, e).c_str());
    return 2;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const VerificationError& e) {
    std::fprintf(stderr, "%s: FAILED: %s\n", name.c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", name.c_str(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace zb::app
