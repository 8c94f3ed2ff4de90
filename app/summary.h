// What a render of several methods reports: the table, summary.csv and the stats JSON.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pipeline/render.h"
#include "rop/backend.h"
#include "metrics/line_metrics.h"
#include "metrics/metrics.h"

namespace zb::app {

// One method's outcome: its image, its cost and its error against the reference.
struct MethodRun {
  std::string method;
  Framebuffer image;
  std::optional<PassStats> total;  // none for the reference
  Traffic traffic;                 // memory traffic of the passes (render.h)
  size_t passes = 0;
  std::optional<ImageError> error;  // none under --no-error
  std::vector<float> delta_e;       // error's per pixel, when error maps are drawn from it
  // Methods that draw edges: against the exact line reference (line_metrics.h).
  std::optional<LineError> line_error;
  double host_ms = 0;
  bool rtl = false;                // ran on the RTL: cycles are meaningful
  uint64_t tile_io_cycles = 0;     // RTL cycles loading and storing tiles
  bool compared = false;           // RTL and golden model compared (backend both)
  uint64_t mismatches = 0;         // pixels where they differ
};

std::string summary_csv(const std::vector<MethodRun>& runs);
void print_table(const std::vector<MethodRun>& runs);
// The stats JSON of a render; `header` holds scene, size and such.
std::string stats_json(const std::vector<MethodRun>& runs, const std::string& header_json);

}  // namespace zb::app
