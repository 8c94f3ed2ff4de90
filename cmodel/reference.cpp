#include "reference.h"

#include <algorithm>
#include <cmath>

namespace zb {
namespace {

uint8_t to_unorm8(double v) {
  return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
}

}  // namespace

// Per pixel: fragments sorted by unrounded depth, ties in submit order (the earlier one counts
// as nearer, as depth LESS keeps it). The nearest opaque fragment (or the background) is the
// base; the transparent fragments in front of it are composited over it back to front,
// c = a*s + (1-a)*c with a = alpha/255, in double, rounded to nearest once at the end.
Framebuffer render_reference(const RasterizedScene& rs) {
  const Viewport& vp = rs.viewport;
  Framebuffer fb(vp.width, vp.height, vp.depth_bits, rs.background);
  const size_t pixels = fb.color.size();

  // Bucket fragment indices by pixel, keeping submit order within a pixel.
  std::vector<uint32_t> start(pixels + 1, 0);
  for (const Fragment& f : rs.fragments) ++start[fb.index(f.x, f.y) + 1];
  for (size_t p = 0; p < pixels; ++p) start[p + 1] += start[p];
  std::vector<uint32_t> order(rs.fragments.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < rs.fragments.size(); ++i) {
    const Fragment& f = rs.fragments[i];
    order[fill[fb.index(f.x, f.y)]++] = i;
  }

  for (size_t p = 0; p < pixels; ++p) {
    auto first = order.begin() + start[p];
    auto last = order.begin() + start[p + 1];
    if (first == last) continue;
    std::stable_sort(first, last,
                     [&](uint32_t a, uint32_t b) { return rs.z_exact[a] < rs.z_exact[b]; });
    auto base = std::find_if(first, last, [&](uint32_t i) { return rs.fragments[i].color.a == 255; });
    const Rgba8 under = base == last ? rs.background : rs.fragments[*base].color;
    double c[3] = {double(under.r), double(under.g), double(under.b)};
    for (auto it = base; it != first;) {
      const Rgba8 s = rs.fragments[*--it].color;
      const double a = s.a / 255.0;
      c[0] = a * s.r + (1.0 - a) * c[0];
      c[1] = a * s.g + (1.0 - a) * c[1];
      c[2] = a * s.b + (1.0 - a) * c[2];
    }
    fb.color[p] = {to_unorm8(c[0]), to_unorm8(c[1]), to_unorm8(c[2]), 255};
    fb.depth[p] = rs.fragments[*first].z;
  }
  return fb;
}

}  // namespace zb
