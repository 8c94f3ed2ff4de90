// The hidden-line offset picked for a scene (docs/sizing.md, "The hidden-line offset").
#include "offset_plan.h"

#include <cmath>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "reference/line_reference.h"
#include "rop/rop.h"

namespace zb {

namespace {

std::string offset_text(const DepthOffset& o) {
  std::string t = o.faces ? fmt::format("{} units beyond the edge's own faces", o.units)
                          : fmt::format("{} units + {:g} x slope", o.units, o.slope_q8 / 256.0);
  if (o.clamp != 0) t += fmt::format(", at most {}", o.clamp);
  return t;
}

nlohmann::json trial_json(const OffsetTrial& t) {
  const DepthOffset& o = t.setting.offset;
  return {{"knob", t.setting.knob},
          {"value", std::isinf(t.setting.value) ? nlohmann::json(nullptr)
                                                : nlohmann::json(t.setting.value)},
          {"offset", {{"units", o.units}, {"slope_q8", o.slope_q8}, {"clamp", o.clamp},
                      {"faces", o.faces}}},
          {"hidden_drawn", t.error.hidden_drawn},
          {"visible_missing", t.error.visible_missing},
          {"hidden_drawn_share", t.error.hidden_drawn_share()},
          {"visible_missing_share", t.error.visible_missing_share()},
          {"within", t.meets}};
}

}  // namespace

OffsetPlan plan_offset(const Scene& scene, const OffsetPlanOptions& o) {
  const RasterizedScene rs = rasterize_scene(scene, o.viewport);
  const LineVisibility truth = line_visibility(rs);
  OffsetPlan plan;
  bool have_best = false;
  for (const lab::OffsetSetting& s : lab::offset_settings()) {
    GoldenRop rop;
    const Framebuffer image = render(rs, make_hidden_line_plan(false, s.offset), rop).framebuffer;
    OffsetTrial t{s, compare_lines(image, truth, kEdgeColor), false};
    t.meets = t.error.hidden_drawn_share() <= o.max_hidden_drawn &&
              t.error.visible_missing_share() <= o.max_visible_missing;
    if (o.progress)
      o.progress(fmt::format("offset {}: {:.3f}% hidden drawn, {:.3f}% visible missing{}",
                             offset_text(s.offset), 100 * t.error.hidden_drawn_share(),
                             100 * t.error.visible_missing_share(), t.meets ? "" : " (beyond)"));
    // Within the bounds beats beyond them; then the least total; then the first.
    const bool better = !have_best || (t.meets && !plan.found) ||
                        (t.meets == plan.found && t.total() < plan.choice.total());
    if (better) {
      plan.choice = t;
      plan.found = t.meets;
      have_best = true;
    }
    plan.trials.push_back(std::move(t));
  }
  return plan;
}

std::string offset_plan_text(const std::string& scene, const OffsetPlanOptions& o,
                             const OffsetPlan& plan) {
  std::string out = fmt::format(
      "hidden-line offset for {} at {}x{}: bounds {:.3f}% hidden edge pixels drawn, {:.3f}% "
      "visible ones missing (shares of the {} edge pixels of the exact line reference)\n\n",
      scene, o.viewport.width, o.viewport.height, 100 * o.max_hidden_drawn,
      100 * o.max_visible_missing,
      plan.trials.empty() ? size_t{0} : plan.trials.front().error.edge_pixels);
  out += fmt::format("{:<8} {:>10}  {:<44} {:>13} {:>16}  {}\n", "knob", "value", "offset",
                     "hidden drawn", "visible missing", "within");
  for (const OffsetTrial& t : plan.trials)
    out += fmt::format("{:<8} {:>10}  {:<44} {:>12.3f}% {:>15.3f}%  {}\n", t.setting.knob,
                       std::isinf(t.setting.value) ? std::string("none")
                                                   : fmt::format("{}", t.setting.value),
                       offset_text(t.setting.offset), 100 * t.error.hidden_drawn_share(),
                       100 * t.error.visible_missing_share(), t.meets ? "yes" : "no");
  out += fmt::format("\n{}: {} ({:.3f}% hidden drawn, {:.3f}% visible missing){}\n",
                     plan.found ? "choice" : "no setting within the bounds; the best",
                     offset_text(plan.choice.setting.offset),
                     100 * plan.choice.error.hidden_drawn_share(),
                     100 * plan.choice.error.visible_missing_share(),
                     plan.found && lab::is_default_offset(plan.choice.setting.offset)
                         ? ", the plans' default"
                         : "");
  return out;
}

std::string offset_plan_json(const std::string& scene, const OffsetPlanOptions& o,
                             const OffsetPlan& plan) {
  nlohmann::json j{{"scene", scene},
                   {"width", o.viewport.width},
                   {"height", o.viewport.height},
                   {"max_hidden_drawn", o.max_hidden_drawn},
                   {"max_visible_missing", o.max_visible_missing},
                   {"edge_pixels", plan.trials.empty() ? size_t{0}
                                                       : plan.trials.front().error.edge_pixels},
                   {"found", plan.found},
                   {"choice", trial_json(plan.choice)},
                   {"choice_is_default", lab::is_default_offset(plan.choice.setting.offset)}};
  j["trials"] = nlohmann::json::array();
  for (const OffsetTrial& t : plan.trials) j["trials"].push_back(trial_json(t));
  return j.dump(2) + "\n";
}

}  // namespace zb
