// What `zblend plan --scene S --max-error E` prints and writes: the analysis, the trials, the
// choice and the RTL build for it (docs/sizing.md).
#pragma once

#include <string>

#include "sizing.h"

namespace zb {

// The text report.
std::string sizing_text(const std::string& scene, const SizingOptions& o, const SizingResult& r);

// The JSON report. Its "rtl" object names the choice as the CMake options and the render that
// checks it (`make plan-rtl` reads these keys): ZBLEND_RTL_DEPTH_BITS, ZBLEND_RTL_COV_SAMPLES,
// ZBLEND_RTL_TILE, render_method.
std::string sizing_json(const std::string& scene, const SizingOptions& o, const SizingResult& r);

}  // namespace zb
