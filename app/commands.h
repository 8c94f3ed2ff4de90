// The zblend subcommands. Each registers itself on the top-level CLI11 app.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "geometry/geometry.h"
#include "scene/scene.h"

namespace zb::app {

// Bad input from the user: reported as one line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The RTL and the golden model disagreed: exit code 1, after the report.
struct VerificationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_render_command(CLI::App& app);
void add_trace_command(CLI::App& app);
void add_info_commands(CLI::App& app);  // methods, scenes, plan
void add_lab_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

// What every subcommand that renders takes: the scene, its camera and the frame.
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
constexpr int kMaxThreads = 1024;
int default_threads();
void add_threads_option(CLI::App* cmd, int& threads, const std::string& help);
void check_threads(int threads);

// Option checks shared by the subcommands; each throws UsageError naming the option.
// A built-in scene name or a scene file (scene_file.h, is_scene_path); `camera`, when not empty,
// is the text of --camera.
Scene resolve_scene(const std::string& name, const std::string& camera = "");
std::vector<std::string> parse_methods(const std::string& list);  // "a,b" or "all"
Viewport check_viewport(int width, int height, int depth_bits);
// Fails early, before any work, when `path` lacks `extension` or its directory is not writable.
void check_writable(const char* option, const std::string& path, const char* extension);
// Throws UsageError(error) unless `error` is empty.
void write_or_fail(const std::string& error);

// "a, b, c", for error messages that name the valid choices.
std::string join(const std::vector<std::string>& items, const char* sep = ", ");

}  // namespace zb::app
