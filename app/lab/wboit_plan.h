// Weighted blended OIT's planes sized to a scene (docs/sizing.md, "The wboit planes"): every
// accumulation width and weight range of the wboit sweep rendered on the scene; the narrowest
// accumulation word whose mean CIEDE2000 against `reference` stays within the bound wins, at
// its best weight range. The patents' methods are measured beside it at their traffic.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "sweeps.h"

namespace zb {

struct WboitPlanOptions {
  Viewport viewport{640, 480};
  double max_delta_e = 1.0;  // bound on the mean CIEDE2000 against the reference
};

struct WboitPlan {
  std::vector<lab::WboitRow> rows;  // wboit_scene_rows: the baselines, then every format
  bool found = false;
  // Found: the narrowest word within the bound (least error at that width, then the smallest
  // weight range). Not found: the format of least error.
  lab::WboitRow choice;
  // The baselines within the bound at no more traffic than the choice: they beat it here.
  std::vector<lab::WboitRow> cheaper;
};

WboitPlan plan_wboit(const Scene& scene, const WboitPlanOptions& o);

// The report, as zblend plan prints it, and as JSON.
std::string wboit_plan_text(const std::string& scene, const WboitPlanOptions& o,
                            const WboitPlan& plan);
std::string wboit_plan_json(const std::string& scene, const WboitPlanOptions& o,
                            const WboitPlan& plan);

}  // namespace zb
