#include "reference.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "geometry/geometry.h"
#include "parallel/parallel.h"
#include "raster/raster.h"

namespace zb {
namespace {

uint8_t to_unorm8(double v) {
  return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
}

using Rgb = std::array<double, 3>;

// The exact composite of every pixel, unrounded, and each pixel's nearest depth (the far depth
// where nothing covers it).
struct ExactFrame {
  std::vector<Rgb> color;
  std::vector<uint32_t> depth;
};

// One pixel's fragments `f[0..n)` (indices into rs.fragments, in submit order): sorted by
// unrounded depth, ties in submit order (the earlier one counts as nearer, as depth LESS keeps
// it). The nearest opaque fragment (or the background) is the base; the transparent fragments in
// front of it are composited over it back to front, c = a*s + (1-a)*c with a = alpha/255, in
// double; no fragments give the background. Leaves f sorted.
Rgb composite_pixel(const RasterizedScene& rs, uint32_t* f, size_t n) {
  uint32_t* first = f;
  uint32_t* last = f + n;
  std::stable_sort(first, last,
                   [&](uint32_t a, uint32_t b) { return rs.z_exact[a] < rs.z_exact[b]; });
  uint32_t* base = std::find_if(first, last, [&](uint32_t i) { return rs.fragments[i].color.a == 255; });
  const Rgba8 under = base == last ? rs.background : rs.fragments[*base].color;
  Rgb c{double(under.r), double(under.g), double(under.b)};
  for (uint32_t* it = base; it != first;) {
    const Rgba8 s = rs.fragments[*--it].color;
    const double a = s.a / 255.0;
    c[0] = a * s.r + (1.0 - a) * c[0];
    c[1] = a * s.g + (1.0 - a) * c[1];
    c[2] = a * s.b + (1.0 - a) * c[2];
  }
  return c;
}

// Per pixel of rows [row0, row0 + rows) (rs holds only their fragments), composite_pixel.
ExactFrame composite_exact(const RasterizedScene& rs, int row0, int rows) {
  const Viewport& vp = rs.viewport;
  const size_t pixels = static_cast<size_t>(vp.width) * size_t(rows);
  const Rgba8 bg = rs.background;
  ExactFrame out{std::vector<Rgb>(pixels, Rgb{double(bg.r), double(bg.g), double(bg.b)}),
                 std::vector<uint32_t>(pixels, depth_max(vp.depth_bits))};
  auto index = [&](const Fragment& f) { return static_cast<size_t>(f.y - row0) * vp.width + f.x; };

  // Bucket fragment indices by pixel, keeping submit order within a pixel.
  std::vector<uint32_t> start(pixels + 1, 0);
  for (const Fragment& f : rs.fragments) ++start[index(f) + 1];
  for (size_t p = 0; p < pixels; ++p) start[p + 1] += start[p];
  std::vector<uint32_t> order(rs.fragments.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < rs.fragments.size(); ++i) order[fill[index(rs.fragments[i])]++] = i;

  for (size_t p = 0; p < pixels; ++p) {
    auto first = order.begin() + start[p];
    auto last = order.begin() + start[p + 1];
    if (first == last) continue;
    const Rgb c = composite_pixel(rs, &*first, size_t(last - first));
    out.color[p] = c;
    out.depth[p] = rs.fragments[*first].z;
  }
  return out;
}

}  // namespace

std::vector<ReferencePixel> reference_pixels(const RasterizedScene& rs,
                                             const std::vector<std::pair<int, int>>& at) {
  // One pass over the fragments, each kept for the asked pixel it lies on.
  std::unordered_map<uint64_t, size_t> slot;
  for (size_t k = 0; k < at.size(); ++k)
    slot.emplace(uint64_t(uint32_t(at[k].second)) << 32 | uint32_t(at[k].first), k);
  std::vector<std::vector<uint32_t>> here(at.size());
  for (uint32_t i = 0; i < rs.fragments.size(); ++i) {
    const Fragment& f = rs.fragments[i];
    if (const auto it = slot.find(uint64_t(f.y) << 32 | f.x); it != slot.end()) here[it->second].push_back(i);
  }
  std::vector<ReferencePixel> out(at.size());
  for (size_t k = 0; k < at.size(); ++k) {
    ReferencePixel& p = out[k];
    const Rgb c = composite_pixel(rs, here[k].data(), here[k].size());  // none: the background
    p.color = {to_unorm8(c[0]), to_unorm8(c[1]), to_unorm8(c[2]), 255};
    for (const uint32_t i : here[k]) {  // sorted now, nearest first
      const Fragment& f = rs.fragments[i];
      if (!p.layers.empty() && p.layers.back().color.a == 255) {
        ++p.behind;
        continue;
      }
      p.layers.push_back({f.prim, rs.z_exact[i], f.color});
    }
  }
  return out;
}

Framebuffer render_reference(const RasterizedScene& rs) {
  const Viewport& vp = rs.viewport;
  Framebuffer fb(vp.width, vp.height, vp.depth_bits, rs.background);
  const ExactFrame exact = composite_exact(rs, 0, vp.height);
  for (size_t p = 0; p < fb.color.size(); ++p) {
    const Rgb& c = exact.color[p];
    fb.color[p] = {to_unorm8(c[0]), to_unorm8(c[1]), to_unorm8(c[2]), 255};
  }
  fb.depth = exact.depth;
  return fb;
}

Framebuffer render_reference_supersampled(const Scene& scene, const Viewport& vp, int factor, int threads) {
  if (factor < 1 || vp.width > kMaxFrameSize / factor || vp.height > kMaxFrameSize / factor)
    throw std::invalid_argument("supersampling factor " + std::to_string(factor) +
                                " outside 1.." + std::to_string(kMaxFrameSize) +
                                " / frame size");
  Viewport big = vp;
  big.width = vp.width * factor;
  big.height = vp.height * factor;
  const std::vector<ScreenTriangle> triangles = setup_triangles(scene, big);
  Framebuffer fb(vp.width, vp.height, vp.depth_bits, scene.background, vp.coverage_samples);
  const double samples = double(factor) * factor;
  // Bands of output rows, each rasterized alone (a row range keeps the fragments and their
  // order): a band's fragments, not the frame's, are held at once, and bands run side by side.
  constexpr int kBandRows = 8;
  const int bands = (vp.height + kBandRows - 1) / kBandRows;
  std::atomic<int> next{0};
  run_workers(std::min(resolve_threads(threads), bands), [&](int) {
    RasterizedScene rs;
    rs.viewport = big;
    rs.background = scene.background;
    for (int b; (b = next++) < bands;) {
      const int y0 = b * kBandRows, y1 = std::min(vp.height, y0 + kBandRows);
      rs.fragments.clear();
      rs.z_exact.clear();
      for (const ScreenTriangle& t : triangles)
        rasterize(t, big, rs.fragments, &rs.z_exact, RowRange{y0 * factor, y1 * factor});
      const ExactFrame exact = composite_exact(rs, y0 * factor, (y1 - y0) * factor);
      for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < vp.width; ++x) {
          Rgb sum{0, 0, 0};
          uint32_t nearest = depth_max(vp.depth_bits);
          for (int sy = 0; sy < factor; ++sy) {
            for (int sx = 0; sx < factor; ++sx) {
              const size_t s = static_cast<size_t>((y - y0) * factor + sy) * big.width + x * factor + sx;
              for (int c = 0; c < 3; ++c) sum[c] += exact.color[s][c];
              nearest = std::min(nearest, exact.depth[s]);
            }
          }
          const size_t p = fb.index(x, y);
          fb.color[p] = {to_unorm8(sum[0] / samples), to_unorm8(sum[1] / samples),
                         to_unorm8(sum[2] / samples), 255};
          fb.depth[p] = nearest;
        }
      }
    }
  });
  return fb;
}

}  // namespace zb
