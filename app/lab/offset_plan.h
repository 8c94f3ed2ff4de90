// The depth offset picked for a scene (docs/sizing.md, "The hidden-line offset"): every
// setting of the offset sweep (sweeps.h, offset_settings) rendered with hidden-line and
// measured against the exact line reference; the one of least error within both bounds wins.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "geometry/geometry.h"
#include "metrics/line_metrics.h"
#include "scene/scene.h"
#include "sweeps.h"

namespace zb {

struct OffsetPlanOptions {
  Viewport viewport{640, 480};
  double max_hidden_drawn = 0;     // bound on the share of edge pixels, 0..1
  double max_visible_missing = 0;  // the same
  std::function<void(const std::string&)> progress;  // a line per setting, when set
};

struct OffsetTrial {
  lab::OffsetSetting setting;
  LineError error;
  bool meets = false;  // both shares within their bounds
  double total() const { return error.hidden_drawn_share() + error.visible_missing_share(); }
};

struct OffsetPlan {
  std::vector<OffsetTrial> trials;  // in offset_settings() order
  bool found = false;
  // Found: the trial of least total error within both bounds (the first such in order).
  // Not found: the trial of least total error (the best achievable).
  OffsetTrial choice;
};

OffsetPlan plan_offset(const Scene& scene, const OffsetPlanOptions& o);

// The report: every setting's shares and the choice, as zblend plan prints it.
std::string offset_plan_text(const std::string& scene, const OffsetPlanOptions& o,
                             const OffsetPlan& plan);
std::string offset_plan_json(const std::string& scene, const OffsetPlanOptions& o,
                             const OffsetPlan& plan);

}  // namespace zb
