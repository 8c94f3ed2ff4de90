// The error of a hidden-line image against the exact line reference (reference/line_reference.h):
// hidden edge pixels drawn and visible edge pixels missing, as shares of the reference's edge
// pixels (docs/lab.md, "Hidden-line error").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

#include "reference/line_reference.h"
#include "rop/framebuffer.h"

namespace zb {

struct LineError {
  size_t edge_pixels = 0;      // the reference's edge pixels
  size_t visible_pixels = 0;   // of which visible
  size_t hidden_drawn = 0;     // hidden in the reference, drawn in the visible style
  size_t visible_missing = 0;  // visible in the reference, not drawn in the visible style
  double hidden_drawn_share() const { return share(hidden_drawn); }
  double visible_missing_share() const { return share(visible_missing); }

 private:
  double share(size_t n) const { return edge_pixels ? double(n) / double(edge_pixels) : 0.0; }
};

// One pixel of a hidden-line image against the exact line reference.
enum class LinePixel : uint8_t {
  kNoEdge,          // no edge there in the reference
  kHiddenRight,     // a hidden edge, not drawn in the visible style
  kVisibleRight,    // a visible edge, drawn in the visible style
  kHiddenDrawn,     // a hidden edge drawn in the visible style
  kVisibleMissing,  // a visible edge not drawn in the visible style
};
// Pixel i (row-major) of `image` (the reference's size), drawn in the visible style when its
// colour is `visible`.
LinePixel line_pixel(const Framebuffer& image, const LineVisibility& reference, Rgba8 visible,
                     size_t i);

// The first wrong pixel (kHiddenDrawn or kVisibleMissing) in row-major order; none when there is
// none or the sizes differ.
std::optional<std::pair<int, int>> first_line_error(const Framebuffer& image,
                                                    const LineVisibility& reference, Rgba8 visible);

// `image` against `reference`, a pixel being drawn in the visible style when its colour is
// `visible` (a dimmed hidden edge, or nothing, is not). For a method that dims hidden edges,
// hidden_drawn counts hidden edges drawn full and visible_missing visible ones drawn dimmed.
LineError compare_lines(const Framebuffer& image, const LineVisibility& reference, Rgba8 visible);

}  // namespace zb
