// Weighted blended OIT's planes sized to a scene (docs/sizing.md, "The wboit planes").
#include "wboit_plan.h"

#include <tuple>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace zb {

namespace {

int word_bits(const WboitFormat& f) { return 4 * f.acc_bits + f.rev_bits; }

nlohmann::json row_json(const lab::WboitRow& r) {
  nlohmann::json j{{"method", r.method}, {"bytes", r.bytes},
                   {"delta_e_mean", r.error.delta_e_mean}, {"rmse", r.error.rmse},
                   {"max_abs", r.error.max_abs}};
  if (r.method == "wboit") {
    j["acc_bits"] = r.format.acc_bits;
    j["rev_bits"] = r.format.rev_bits;
    j["weight_bits"] = r.format.weight_bits;
    j["word_bits"] = word_bits(r.format);
  }
  return j;
}

}  // namespace

WboitPlan plan_wboit(const Scene& scene, const WboitPlanOptions& o) {
  lab::WboitOptions so;
  so.viewport = o.viewport;
  WboitPlan plan;
  plan.rows = lab::wboit_scene_rows(scene, so);
  bool have = false;
  for (const lab::WboitRow& r : plan.rows) {
    if (r.method != "wboit") continue;
    const bool meets = r.error.delta_e_mean <= o.max_delta_e;
    const auto key = [&](const lab::WboitRow& x) {
      return std::make_tuple(word_bits(x.format), x.error.delta_e_mean, x.format.weight_bits);
    };
    // Within the bound beats beyond it; within, the narrowest word; beyond, the least error.
    const bool better =
        !have || (meets && !plan.found) ||
        (meets && plan.found && key(r) < key(plan.choice)) ||
        (!meets && !plan.found && r.error.delta_e_mean < plan.choice.error.delta_e_mean);
    if (better) plan.choice = r, plan.found = meets, have = true;
  }
  for (const lab::WboitRow& r : plan.rows)
    if (r.method != "wboit" && r.error.delta_e_mean <= o.max_delta_e &&
        r.bytes <= plan.choice.bytes)
      plan.cheaper.push_back(r);
  return plan;
}

std::string wboit_plan_text(const std::string& scene, const WboitPlanOptions& o,
                            const WboitPlan& plan) {
  std::string out = fmt::format(
      "wboit planes for {} at {}x{}: bound {:.2f} mean CIEDE2000 against the reference\n\n",
      scene, o.viewport.width, o.viewport.height, o.max_delta_e);
  out += fmt::format("{:<14} {:>5} {:>5} {:>5} {:>6} {:>12} {:>10} {:>8}  {}\n", "method", "A",
                     "R", "W", "word", "traffic kB", "mean dE", "max", "within");
  for (const lab::WboitRow& r : plan.rows) {
    const bool w = r.method == "wboit";
    out += fmt::format("{:<14} {:>5} {:>5} {:>5} {:>6} {:>12.1f} {:>10.3f} {:>8}  {}\n", r.method,
                       w ? std::to_string(r.format.acc_bits) : "",
                       w ? std::to_string(r.format.rev_bits) : "",
                       w ? std::to_string(r.format.weight_bits) : "",
                       w ? std::to_string(word_bits(r.format)) : "", r.bytes / 1e3,
                       r.error.delta_e_mean, r.error.max_abs,
                       r.error.delta_e_mean <= o.max_delta_e ? "yes" : "no");
  }
  const WboitFormat& f = plan.choice.format;
  out += fmt::format("\n{}: ACC_BITS {}, REV_BITS {}, WEIGHT_BITS {} ({}-bit word; {:.3f} mean "
                     "CIEDE2000, {:.1f} kB)\n",
                     plan.found ? "choice" : "no format within the bound; the best", f.acc_bits,
                     f.rev_bits, f.weight_bits, word_bits(f), plan.choice.error.delta_e_mean,
                     plan.choice.bytes / 1e3);
  for (const lab::WboitRow& r : plan.cheaper)
    out += fmt::format("{} is within the bound at no more traffic ({:.3f}, {:.1f} kB): it beats "
                       "wboit here\n",
                       r.method, r.error.delta_e_mean, r.bytes / 1e3);
  return out;
}

std::string wboit_plan_json(const std::string& scene, const WboitPlanOptions& o,
                            const WboitPlan& plan) {
  nlohmann::json j{{"scene", scene},
                   {"width", o.viewport.width},
                   {"height", o.viewport.height},
                   {"max_delta_e", o.max_delta_e},
                   {"found", plan.found},
                   {"choice", row_json(plan.choice)}};
  j["trials"] = nlohmann::json::array();
  for (const lab::WboitRow& r : plan.rows) j["trials"].push_back(row_json(r));
  j["cheaper"] = nlohmann::json::array();
  for (const lab::WboitRow& r : plan.cheaper) j["cheaper"].push_back(row_json(r));
  return j.dump(2) + "\n";
}

}  // namespace zb
