// zblend render's error maps (docs/cli.md "Error maps"): each method's per-pixel error against
// its fair reference as a picture, one scale for the whole run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/geometry.h"
#include "reference/line_reference.h"
#include "scene/scene.h"
#include "summary.h"

namespace zb::app {

// Where a method's map goes: DIR/METHOD-error.png under --out-dir, else FILE-error.png beside
// the --out FILE.png.
std::string error_map_path(const std::string& out, const std::string& out_dir, const std::string& method);

// --error-scale: one scale for the run's maps (auto, the default: they compare), each map its
// own (per-method), or a number of dE2000.
struct ErrorScale {
  enum class Kind { kShared, kPerMethod, kFixed } kind = Kind::kShared;
  double value = 0;  // kFixed's
};
// "auto", "per-method" or a number above 0; UsageError naming --error-scale otherwise.
ErrorScale parse_error_scale(const std::string& text);

// Writes every run's map but the reference method's: a shaded method's CIEDE2000 against its
// fair reference (the exact one, as run.delta_e holds it when given; the supersampled one for
// coverage anti-aliasing, made here on `threads` workers), at `scale`: shared, the largest
// 99th percentile rounded up to 1, 2 or 5 x 10^k; per method, its own so rounded; or fixed. A
// hidden-line method's edges against `lines`. Returns what the scale was, for the user.
std::string write_error_maps(const std::vector<MethodRun>& runs, const Framebuffer& reference,
                             const std::optional<LineVisibility>& lines, const Scene& scene,
                             const Viewport& vp, const std::string& out, const std::string& out_dir,
                             const ErrorScale& scale, int threads);

}  // namespace zb::app
