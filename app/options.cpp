// Option checks shared by the subcommands.
#include <algorithm>
#include <filesystem>
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
  cmd->add_option("--threads", threads, help + " (default: every core)")->capture_default_str();
}

void check_threads(int threads) {
  if (threads < 1)
    throw UsageError(fmt::format("--threads: {} is out of range (at least 1 thread)", threads));
  check_range("--threads", threads, 1, kMaxThreads);
}

Viewport check_viewport(int width, int height, int depth_bits) {
  check_range("--width", width, 1, kMaxFrameSize);
  check_range("--height", height, 1, kMaxFrameSize);
  check_range("--depth-bits", depth_bits, kMinDepthBits, kMaxDepthBits);
  return {width, height, depth_bits};
}

void check_writable(const char* option, const std::string& path, const char* extension) {
  if (fs::path(path).extension() != extension)
    throw UsageError(fmt::format("{}: '{}' must end in {}", option, path, extension));
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir))
    throw UsageError(fmt::format("{}: directory '{}' does not exist", option, dir.string()));
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError(fmt::format("{}: directory '{}' is not writable", option, dir.string()));
}

void write_or_fail(const std::string& error) {
  if (!error.empty()) throw UsageError(error);
}

}  // namespace zb::app
