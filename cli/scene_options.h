// The options the programs that render share, and their checks: the scene, its camera, the
// frame, the methods, the threads, the background; each check throws UsageError naming the
// option.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geometry/geometry.h"
#include "scene/scene.h"

namespace zb::cli {

// What every command that renders takes: the scene, its camera and the frame.
struct FrameOptions {
  std::string scene = "cad";
  std::string camera;
  int width = 640;
  int height = 480;
  int depth_bits = kDefaultDepthBits;
};

// Registers --scene, --camera, --width, --height and --depth-bits on `cmd`.
void add_frame_options(CLI::App* cmd, FrameOptions& o);

// --threads N: registers it on `cmd` (default: every core, default_threads()); check_threads
// throws UsageError unless 1 <= N <= kMaxThreads.
constexpr int kMaxThreads = 256;
int default_threads();
void add_threads_option(CLI::App* cmd, int& threads, const std::string& help);
void check_threads(int threads);

// A built-in scene name or a scene file (scene_file.h, is_scene_path); `camera`, when not empty,
// is the text of --camera.
Scene resolve_scene(const std::string& name, const std::string& camera = "");
std::vector<std::string> parse_methods(const std::string& list);  // "a,b" or "all"
Viewport check_viewport(int width, int height, int depth_bits);

// --background R,G,B[,A] (0-255 each; A defaults to 255): registers it on `cmd`.
// parse_background gives nothing for empty text.
void add_background_option(CLI::App* cmd, std::string& text);
std::optional<Rgba8> parse_background(const std::string& text);
// resolve_scene(frame.scene, frame.camera) with the --background text applied; the text is
// checked first, so a bad one fails before a large file is read.
Scene resolve_scene_with_background(const FrameOptions& frame, const std::string& background);

// The scene's loader warnings on stderr, "PROGRAM: warning: ...", each once per process.
void print_warnings(const std::string& program, const Scene& scene);

}  // namespace zb::cli
