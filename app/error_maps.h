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

// Writes every run's map but the reference method's: a shaded method's CIEDE2000 against its
// fair reference (the exact one; the supersampled one for coverage anti-aliasing, made here),
// at one scale for all (the largest 99th percentile, rounded up to 1, 2 or 5 x 10^k); a
// hidden-line method's edges against `lines`. Returns the scale.
double write_error_maps(const std::vector<MethodRun>& runs, const Framebuffer& reference,
                        const std::optional<LineVisibility>& lines, const Scene& scene,
                        const Viewport& vp, const std::string& out, const std::string& out_dir);

}  // namespace zb::app
