// The options the programs that render share, and their checks; see scene_options.h.
#include "scene_options.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

#include <fmt/core.h>

#include "cli.h"
#include "io/scene_file.h"
#include "pipeline/passes.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"

namespace zb::cli {

namespace fs = std::filesystem;

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

void print_warnings(const std::string& program, const Scene& scene) {
  static std::mutex mutex;
  static std::set<std::string> printed;  // scene name and warning: lab loads scenes repeatedly
  const std::lock_guard<std::mutex> lock(mutex);
  for (const std::string& w : scene.warnings)
    if (printed.insert(scene.name + '\n' + w).second)
      fmt::print(stderr, "{}: warning: {}\n", program, w);
}

}  // namespace zb::cli
