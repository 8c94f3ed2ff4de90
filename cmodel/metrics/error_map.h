// Error maps: where a method fails, as a picture (docs/lab.md "Error maps"). A shaded method's
// map is each pixel's CIEDE2000 against its fair reference on a perceptually uniform ramp
// (error_ramp below), with the scale drawn in the picture; a hidden-line method's shows its hidden
// edges drawn and its visible edges missing in two colours.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "reference/line_reference.h"
#include "rop/framebuffer.h"

namespace zb {

// The error maps' colour ramp at t in [0, 1] (clamped; NaN is 0): perceptually uniform, its
// CIELAB lightness rising evenly from black to pale yellow.
Rgba8 error_ramp(double t);

// Each pixel's CIEDE2000 of `image` against `reference` (row-major; empty for frames of
// different sizes).
std::vector<float> delta_e_map(const Framebuffer& image, const Framebuffer& reference);

// The value below which a share `p` (0..1) of `values` lie (nearest rank); 0 when empty.
double percentile(const std::vector<float>& values, double p);

// A scale for maps that compare: the smallest 1, 2 or 5 x 10^k at or above `value`, at least
// kMinErrorScale (below it no difference is visible).
constexpr double kMinErrorScale = 1.0;
double nice_error_scale(double value);

// The one scale of maps shown side by side: the largest 99th percentile of theirs (an empty map
// counts 0), as nice_error_scale rounds it.
double shared_error_scale(const std::vector<std::vector<float>>& maps);
// One map's own scale: its 99th percentile as nice_error_scale rounds it (at least
// kMinErrorScale); shared_error_scale is the largest of these.
double error_scale(const std::vector<float>& map);

// The pixel (x, y) of the largest value, the first in row-major order on a tie; none when no
// value is above 0 (nothing wrong to point at).
std::optional<std::pair<int, int>> worst_pixel(const std::vector<float>& values, int width);

// The ticks of a legend from 0 to `scale`, both included: fifths of 1 and 5 x 10^k, quarters
// of 2 x 10^k and of any other scale.
std::vector<double> error_scale_ticks(double scale);

// The map of `de` (width x height) at `scale` (that value and above the brightest): a pixel
// with no error in kExactColor, which the ramp never takes, so an exact map does not look like
// an empty one. Below it a legend strip: the exact colour, the ramp from 0 to the scale with its
// ticks, and a line with the map's own largest error, where it is and the share of exact
// pixels. With `mark`, a ring around that pixel. The picture is at least kLegendWidth wide (the
// frame left-aligned on black).
constexpr int kLegendWidth = 240;
constexpr Rgba8 kExactColor{24, 64, 72, 255};
Framebuffer error_map_image(const std::vector<float>& de, int width, int height, double scale,
                            std::optional<std::pair<int, int>> mark = std::nullopt);

// A hidden-line method's map against the exact line reference (a pixel drawn in the visible
// style when its colour is `visible`): edges drawn as they should be in two greys (visible
// ones light, hidden ones dark), hidden edges drawn (kHiddenDrawnColor) and visible edges
// missing (kVisibleMissingColor), the rest (no edge: not measured) black, with a legend strip
// naming the four.
constexpr Rgba8 kHiddenDrawnColor{255, 60, 60, 255};
constexpr Rgba8 kVisibleMissingColor{60, 200, 255, 255};
constexpr Rgba8 kVisibleRightColor{150, 150, 150, 255};
constexpr Rgba8 kHiddenRightColor{70, 70, 70, 255};
Framebuffer line_error_map_image(const Framebuffer& image, const LineVisibility& reference,
                                 Rgba8 visible);

}  // namespace zb
