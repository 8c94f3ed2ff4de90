// zblend methods | scenes | plan: what the tool can run.
#include <iterator>

#include <fmt/core.h>
#include <fmt/format.h>

#include "cli.h"
#include "output_paths.h"
#include "scene_options.h"
#include "commands.h"
#include "io/image.h"
#include "pipeline/passes.h"
#include "scene/scene_suite.h"
#include "scene/builtin_scenes.h"
#include "offset_plan.h"
#include "wboit_plan.h"
#include "sizing.h"
#include "sizing_report.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

void print_methods() {
  fmt::print("{:<16} {:>6}  {:<34} {}\n", "method", "passes", "source", "what it does");
  for (const PassPlan& p : pass_plans())
    fmt::print("{:<16} {:>6}  {:<34} {}\n", p.name, p.passes.size(), p.source, p.description);
  fmt::print("{:<16} {:>6}  {:<34} {}\n", kReferenceMethod, "-", "exact ground truth",
             "every fragment sorted per pixel by depth, composited in floating point");
}

// The built-ins outside the suite, then the suite by family: one line per scene, the layers
// family as one line with its name pattern and sampled values.
void print_scenes() {
  constexpr const char* kRow = "{:<16} {:>9}  {:<16}  {}\n";
  auto in_suite = [](const std::string& name) {
    for (const SuiteScene& e : scene_suite())
      if (e.name == name) return true;
    return false;
  };
  fmt::print("{:<16} {:>9}  {}\n", "scene", "triangles", "what it shows");
  for (const SceneInfo& s : builtin_scenes())
    if (!in_suite(s.name))
      fmt::print("{:<16} {:>9}  {}\n", s.name, builtin_scene(s.name)->triangle_count(),
                 s.description);

  fmt::print("\nthe lab's suite (zblend lab), by family:\n");
  fmt::print(kRow, "scene", "triangles", "family", "built to break");
  bool layers_listed = false;
  for (const SuiteScene& e : scene_suite()) {
    if (e.family != "layers") {
      fmt::print(kRow, e.name, builtin_scene(e.name)->triangle_count(), e.family, e.description);
    } else if (!layers_listed) {
      layers_listed = true;
      const auto n = std::begin(kSuiteLayers), p = std::begin(kSuiteAlphaPercent);
      const std::string tris = fmt::format("{}-{}", layers_scene(n[0], 0.5f).triangle_count(),
                                           layers_scene(std::end(kSuiteLayers)[-1], 0.5f)
                                               .triangle_count());
      fmt::print(kRow, "layers-N-aP", tris, e.family,
                 fmt::format("N layers of alpha P% near to far, N = {}, P = {}: one-pass blending "
                             "reverses them, depth-peel-K keeps the nearest K",
                             fmt::join(n, std::end(kSuiteLayers), ", "),
                             fmt::join(p, std::end(kSuiteAlphaPercent), ", ")));
    }
  }
}

void print_plan(const std::string& method) {
  const PassPlan* plan = find_plan(method);
  if (!plan) {
    std::vector<std::string> names;
    for (const PassPlan& p : pass_plans()) names.push_back(p.name);
    throw UsageError(fmt::format("--method: '{}' has no pass plan (choose from {})", method,
                                 join(names)));
  }
  fmt::print("{} ({}): {}\n", plan->name, plan->source, plan->description);
  fmt::print("{:<4} {:<22} {:<16} {:<5} {:<6} {:<7} {:<6} {:<8} {}\n", "pass", "name", "primitives",
             "cull", "ztest", "zfunc", "zwrite", "blend", "mask");
  int n = 1;
  for (const PassState& p : plan->passes) {
    const RopState& r = p.rop;
    const std::string mask = fmt::format("{}{}{}{}", (r.color_mask & kMaskR) ? "R" : "-",
                                         (r.color_mask & kMaskG) ? "G" : "-",
                                         (r.color_mask & kMaskB) ? "B" : "-",
                                         (r.color_mask & kMaskA) ? "A" : "-");
    fmt::print("{:<4} {:<22} {:<16} {:<5} {:<6} {:<7} {:<6} {:<8} {}\n", n++, p.name,
               to_string(p.filter), to_string(p.cull), r.depth_test ? "on" : "off",
               to_string(r.depth_func), r.depth_write ? "on" : "off", to_string(r.blend), mask);
  }
}

// zblend plan --scene S --max-error E: a model sized to the scene (app/lab/sizing.h).
struct SizingCommand {
  std::string scene;
  std::string camera;
  int width = 640;
  int height = 480;
  int max_error = 0;
  std::string json;
  double max_hidden_drawn = 0;     // percent, with --max-visible-missing: the offset search
  double max_visible_missing = 0;
  double max_delta_e = 0;          // the wboit planes' search
};

// The scene of a --scene plan, after its --json path is checked and its directory made.
Scene plan_scene(const SizingCommand& c) {
  const std::vector<OutputPath> outputs = {{"--json", c.json, ".json"}};
  check_outputs(outputs);
  Scene scene = resolve_scene(c.scene, c.camera);
  create_output_dirs(outputs);
  print_warnings("zblend plan", scene);
  return scene;
}

void write_plan_json(const SizingCommand& c, const std::string& json) {
  if (!c.json.empty()) write_or_fail(write_file_atomic(c.json, json));
}

void run_sizing(const SizingCommand& c) {
  if (c.max_error < 0 || c.max_error > 255)
    throw UsageError(fmt::format("--max-error: {} is out of range (0 to 255, 8-bit units)",
                                 c.max_error));
  const Viewport vp = check_viewport(c.width, c.height, kDefaultDepthBits);
  const Scene scene = plan_scene(c);
  SizingOptions o;
  o.width = vp.width;
  o.height = vp.height;
  o.max_error = c.max_error;
  o.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  const SizingResult r = size_model(scene, o);
  fmt::print("{}", sizing_text(c.scene, o, r));
  write_plan_json(c, sizing_json(c.scene, o, r));
  if (!r.found)
    throw VerificationError(fmt::format("no method meets --max-error {}: the best achievable "
                                        "error is {} ({})", c.max_error,
                                        r.choice.beyond_rounding, r.choice.method));
}

// zblend plan --scene S --max-hidden-drawn P --max-visible-missing Q: the hidden-line depth
// offset for the scene (app/lab/offset_plan.h).
void run_offset_plan(const SizingCommand& c) {
  for (const auto& [name, v] : {std::pair{"--max-hidden-drawn", c.max_hidden_drawn},
                                std::pair{"--max-visible-missing", c.max_visible_missing}})
    if (!(v >= 0 && v <= 100))
      throw UsageError(fmt::format("{}: {} is out of range (0 to 100, percent of the edge "
                                   "pixels)", name, v));
  const Viewport vp = check_viewport(c.width, c.height, kDefaultDepthBits);
  const Scene scene = plan_scene(c);
  OffsetPlanOptions o;
  o.viewport = vp;
  o.max_hidden_drawn = c.max_hidden_drawn / 100;
  o.max_visible_missing = c.max_visible_missing / 100;
  o.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  const OffsetPlan plan = plan_offset(scene, o);
  fmt::print("{}", offset_plan_text(c.scene, o, plan));
  write_plan_json(c, offset_plan_json(c.scene, o, plan));
  if (!plan.found)
    throw VerificationError(fmt::format(
        "no offset meets --max-hidden-drawn {} and --max-visible-missing {}", c.max_hidden_drawn,
        c.max_visible_missing));
}

// zblend plan --scene S --max-delta-e D: weighted blended OIT's planes for the scene
// (app/lab/wboit_plan.h).
void run_wboit_plan(const SizingCommand& c) {
  if (!(c.max_delta_e >= 0 && c.max_delta_e <= 100))
    throw UsageError(fmt::format("--max-delta-e: {} is out of range (0 to 100, mean CIEDE2000)",
                                 c.max_delta_e));
  const Viewport vp = check_viewport(c.width, c.height, kDefaultDepthBits);
  const Scene scene = plan_scene(c);
  WboitPlanOptions o;
  o.viewport = vp;
  o.max_delta_e = c.max_delta_e;
  fmt::print(stderr, "wboit planes for {}: {} formats and the patents' methods...\n", c.scene,
             lab::WboitOptions{}.acc_bits.size() * lab::WboitOptions{}.weight_bits.size());
  const WboitPlan plan = plan_wboit(scene, o);
  fmt::print("{}", wboit_plan_text(c.scene, o, plan));
  write_plan_json(c, wboit_plan_json(c.scene, o, plan));
  if (!plan.found)
    throw VerificationError(fmt::format("no wboit format meets --max-delta-e {}: the best is "
                                        "{:.3f}", c.max_delta_e,
                                        plan.choice.error.delta_e_mean));
}

// The plan command's three forms: --method alone; --scene with --max-error; --scene with
// --max-hidden-drawn and --max-visible-missing.
void run_plan_command(const CLI::App& cmd, const std::string& method, const SizingCommand& c) {
  const char* scene_options[] = {"--max-error",  "--max-hidden-drawn", "--max-visible-missing",
                                 "--max-delta-e", "--camera", "--width", "--height", "--json"};
  if (cmd.count("--method")) {
    if (cmd.count("--scene"))
      throw UsageError("--method, --scene: give one of them (--method M: a method's passes; "
                       "--scene S --max-error E: a model sized to the scene)");
    for (const char* o : scene_options)
      if (cmd.count(o)) throw UsageError(fmt::format("{}: goes with --scene, not --method", o));
    print_plan(method);
    return;
  }
  if (!cmd.count("--scene")) {
    for (const char* o : scene_options)
      if (cmd.count(o)) throw UsageError(fmt::format("--scene: needed with {}", o));
    throw UsageError("give --method M (a method's passes) or --scene S --max-error E (a model "
                     "sized to the scene)");
  }
  const bool offset = cmd.count("--max-hidden-drawn") || cmd.count("--max-visible-missing");
  if (cmd.count("--max-delta-e")) {
    if (cmd.count("--max-error") || offset)
      throw UsageError("--max-delta-e: give it alone (the wboit planes), not with --max-error or "
                       "the hidden-line offset's bounds");
    run_wboit_plan(c);
    return;
  }
  if (offset) {
    if (cmd.count("--max-error"))
      throw UsageError("--max-error, --max-hidden-drawn: give one of them (--max-error: a model "
                       "sized to the scene; --max-hidden-drawn and --max-visible-missing: the "
                       "hidden-line offset)");
    for (const char* o : {"--max-hidden-drawn", "--max-visible-missing"})
      if (!cmd.count(o))
        throw UsageError(fmt::format("{}: needed with the other bound of the hidden-line offset "
                                     "(both in percent of the edge pixels)", o));
    run_offset_plan(c);
    return;
  }
  if (!cmd.count("--max-error"))
    throw UsageError("--max-error: needed with --scene (the error bound, 0 to 255)");
  run_sizing(c);
}

}  // namespace

void add_info_commands(CLI::App& app) {
  app.add_subcommand("methods", "List the transparency methods (pass plans)")
      ->callback(print_methods);
  app.add_subcommand("scenes", "List the built-in scenes and the lab's scene suite by family")
      ->callback(print_scenes);
  auto* plan = app.add_subcommand(
      "plan", "Show the passes of a method and their pipeline state (--method), pick the "
              "hidden-line depth offset for a scene (--scene, --max-hidden-drawn, "
              "--max-visible-missing), size weighted blended OIT's planes (--scene, "
              "--max-delta-e), or size a model "
              "to a scene (--scene, --max-error): the cheapest method and narrowest depth bits, "
              "coverage samples and tile size within the error, verified (docs/sizing.md)");
  auto method = std::make_shared<std::string>();
  auto sizing = std::make_shared<SizingCommand>();
  plan->add_option("--method,-m", *method, "Method name (see 'zblend methods'): show its passes");
  plan->add_option("--scene,-s", sizing->scene,
                   "Size a model to this scene: built-in (see 'zblend scenes') or a .obj, .gltf "
                   "or .glb file");
  plan->add_option("--max-error,-e", sizing->max_error,
                   "With --scene: the bound E, 8-bit units (0 to 255), on the largest channel "
                   "error against 'reference' beyond the 8-bit blend's rounding (0: as close as "
                   "compositing every layer in order gets)");
  plan->add_option("--max-hidden-drawn", sizing->max_hidden_drawn,
                   "With --scene and --max-visible-missing: pick the hidden-line depth offset "
                   "whose hidden edge pixels drawn stay within this share (percent of the exact "
                   "line reference's edge pixels)");
  plan->add_option("--max-visible-missing", sizing->max_visible_missing,
                   "With --scene and --max-hidden-drawn: the bound on visible edge pixels "
                   "missing (percent)");
  plan->add_option("--max-delta-e", sizing->max_delta_e,
                   "With --scene: size weighted blended OIT's planes, the narrowest accumulation "
                   "word whose mean CIEDE2000 against 'reference' stays within this; the "
                   "patents' methods measured beside it");
  plan->add_option("--camera", sizing->camera,
                   "With --scene: camera eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z]");
  plan->add_option("--width,-W", sizing->width, "With --scene: frame width in pixels")
      ->capture_default_str();
  plan->add_option("--height,-H", sizing->height, "With --scene: frame height in pixels")
      ->capture_default_str();
  plan->add_option("--json", sizing->json,
                   "With --scene: the report as JSON (--max-error: make plan-rtl reads it)");
  plan->callback([plan, method, sizing] { run_plan_command(*plan, *method, *sizing); });
}

}  // namespace zb::app
