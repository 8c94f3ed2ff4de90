// zblend methods | scenes | plan: what the tool can run.
#include <fmt/core.h>

#include "commands.h"
#include "passes.h"
#include "scenes.h"

namespace zb::app {

namespace {

void print_methods() {
  fmt::print("{:<16} {:>6}  {:<34} {}\n", "method", "passes", "source", "what it does");
  for (const PassPlan& p : pass_plans())
    fmt::print("{:<16} {:>6}  {:<34} {}\n", p.name, p.passes.size(), p.source, p.description);
  fmt::print("{:<16} {:>6}  {:<34} {}\n", kReferenceMethod, "-", "exact ground truth",
             "every fragment sorted per pixel by depth, composited in floating point");
}

void print_scenes() {
  fmt::print("{:<14} {:>9}  {}\n", "scene", "triangles", "what it shows");
  for (const SceneInfo& s : builtin_scenes())
    fmt::print("{:<14} {:>9}  {}\n", s.name, builtin_scene(s.name)->triangle_count(),
               s.description);
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

}  // namespace

void add_info_commands(CLI::App& app) {
  app.add_subcommand("methods", "List the transparency methods (pass plans)")
      ->callback(print_methods);
  app.add_subcommand("scenes", "List the built-in scenes")->callback(print_scenes);
  auto* plan = app.add_subcommand("plan", "Show the passes of a method and their pipeline state");
  auto method = std::make_shared<std::string>();
  plan->add_option("--method,-m", *method, "Method name (see 'zblend methods')")->required();
  plan->callback([method] { print_plan(*method); });
}

}  // namespace zb::app
