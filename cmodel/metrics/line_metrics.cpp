#include "line_metrics.h"

namespace zb {

LineError compare_lines(const Framebuffer& image, const LineVisibility& reference, Rgba8 visible) {
  LineError e;
  e.edge_pixels = reference.edge_pixels;
  e.visible_pixels = reference.visible_pixels;
  if (image.color.size() != reference.pixels.size()) return e;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const bool full = image.color[i] == visible;
    switch (reference.pixels[i]) {
      case EdgePixel::kHidden: e.hidden_drawn += full; break;
      case EdgePixel::kVisible: e.visible_missing += !full; break;
      case EdgePixel::kNone: break;
    }
  }
  return e;
}

}  // namespace zb
