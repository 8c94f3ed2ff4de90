// zblend trace: writes the fragment streams and pass states of a render to a trace file, which
// the testbench (zblend_tb --replay) runs on both backends.
#include <memory>

#include <fmt/core.h>

#include "commands.h"
#include "passes.h"
#include "render.h"
#include "trace.h"

namespace zb::app {
namespace {

struct TraceOptions {
  std::string scene = "cad";
  std::string camera;
  std::string method = "three-pass";
  int width = 640;
  int height = 480;
  int depth_bits = kDefaultDepthBits;
  std::string out;
};

void run_trace(const TraceOptions& o) {
  const Scene scene = resolve_scene(o.scene, o.camera);
  const PassPlan* plan = find_plan(o.method);
  if (!plan) {
    std::vector<std::string> names;
    for (const PassPlan& p : pass_plans()) names.push_back(p.name);
    throw UsageError(fmt::format("--method: '{}' has no pass plan (choose from {})", o.method,
                                 join(names)));
  }
  const Viewport vp = check_viewport(o.width, o.height, o.depth_bits);
  check_writable("--out", o.out, ".zbt");
  const Trace trace = make_trace(rasterize_scene(scene, vp), *plan);
  write_or_fail(write_trace(o.out, trace));
  size_t fragments = 0;
  for (const TracePass& p : trace.passes) fragments += p.fragments.size();
  fmt::print("{}: {} passes, {} fragments, {}x{}, {} depth bits\n", o.out, trace.passes.size(),
             fragments, trace.width, trace.height, trace.depth_bits);
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto o = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "trace", "Write a render's fragment streams and pass states to a trace file (.zbt)");
  cmd->add_option("--scene,-s", o->scene,
                  "Built-in scene (see 'zblend scenes') or a file: .obj (+.mtl), .gltf, .glb "
                  "(docs/scenes.md)")
      ->capture_default_str();
  cmd->add_option("--camera", o->camera,
                  "Camera eye=x,y,z,at=x,y,z,fov=deg (default: the scene's own; files: fitted "
                  "to the bounds)");
  cmd->add_option("--method,-m", o->method, "Method with a pass plan (see 'zblend methods')")
      ->capture_default_str();
  cmd->add_option("--width,-W", o->width, "Frame width in pixels")->capture_default_str();
  cmd->add_option("--height,-H", o->height, "Frame height in pixels")->capture_default_str();
  cmd->add_option("--depth-bits", o->depth_bits, "Depth buffer width in bits")
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "Output trace file (.zbt)")->required();
  cmd->callback([o] { run_trace(*o); });
}

}  // namespace zb::app
