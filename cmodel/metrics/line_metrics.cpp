#include "line_metrics.h"

namespace zb {

LinePixel line_pixel(const Framebuffer& image, const LineVisibility& reference, Rgba8 visible,
                     size_t i) {
  const bool full = image.color[i] == visible;
  switch (reference.pixels[i]) {
    case EdgePixel::kHidden: return full ? LinePixel::kHiddenDrawn : LinePixel::kHiddenRight;
    case EdgePixel::kVisible: return full ? LinePixel::kVisibleRight : LinePixel::kVisibleMissing;
    case EdgePixel::kNone: break;
  }
  return LinePixel::kNoEdge;
}

std::optional<std::pair<int, int>> first_line_error(const Framebuffer& image,
                                                    const LineVisibility& reference, Rgba8 visible) {
  if (image.color.size() != reference.pixels.size()) return std::nullopt;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const LinePixel p = line_pixel(image, reference, visible, i);
    if (p == LinePixel::kHiddenDrawn || p == LinePixel::kVisibleMissing)
      return std::pair<int, int>{int(i % size_t(reference.width)), int(i / size_t(reference.width))};
  }
  return std::nullopt;
}

LineError compare_lines(const Framebuffer& image, const LineVisibility& reference, Rgba8 visible) {
  LineError e;
  e.edge_pixels = reference.edge_pixels;
  e.visible_pixels = reference.visible_pixels;
  if (image.color.size() != reference.pixels.size()) return e;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const LinePixel p = line_pixel(image, reference, visible, i);
    e.hidden_drawn += p == LinePixel::kHiddenDrawn;
    e.visible_missing += p == LinePixel::kVisibleMissing;
  }
  return e;
}

}  // namespace zb
