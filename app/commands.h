// The zblend subcommands. Each registers itself on the top-level CLI11 app.
#pragma once

#include <optional>
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
void add_conformance_command(CLI::App& app);  // conformance export, conformance check
// `export` and `check` themselves, on `parent`: zblend's conformance, or zblend-conformance.
void add_conformance_commands(CLI::App& parent);

// Parses the command line and runs the chosen command: 0; a usage error or bad input, one line
// on stderr, 2; a verification failure or an internal error, 1. Every program's main.
int run_app(CLI::App& app, int argc, char** argv);

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
constexpr int kMaxThreads = 256;
int default_threads();
void add_threads_option(CLI::App* cmd, int& threads, const std::string& help);
void check_threads(int threads);

// Option checks shared by the subcommands; each throws UsageError naming the option.
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

// The rule for every output path (docs/cli.md, "Output paths"). A file must end in its
// extension and not be a directory; a directory must not be a file; the nearest existing
// directory above either must be writable and no file may stand on the way to it.
struct OutputPath {
  const char* option;     // "--out", named in the error
  std::string path;       // empty: not given, skipped
  const char* extension;  // ".png" ...; nullptr: the path is a directory
};
// Checks, changing nothing on disk.
void check_outputs(const std::vector<OutputPath>& outputs);
// check_outputs, then creates the missing directories (mkdir -p): once every other check passed.
void create_output_dirs(const std::vector<OutputPath>& outputs);
// check_outputs for one file.
void check_writable(const char* option, const std::string& path, const char* extension);
// Throws UsageError(error) unless `error` is empty.
void write_or_fail(const std::string& error);

// The scene's loader warnings on stderr, "PROGRAM: warning: ...", each once per process.
void print_warnings(const std::string& program, const Scene& scene);

// The one line for a CLI11 parse error of `app` (the top level). An unknown option names the
// closest valid one: "zblend render: error: unknown option '--scnee'; did you mean '--scene'?".
std::string parse_error_line(const CLI::App& app, const CLI::ParseError& e);

// "a, b, c", for error messages that name the valid choices.
std::string join(const std::vector<std::string>& items, const char* sep = ", ");

}  // namespace zb::app
