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

// One pixel's fragments `f[0..n)` (indices into rs.fragments, in submit order): sorted by
// unrounded depth, ties in submit order (the earlier one counts as nearer, as depth LESS keeps
// it). The nearest opaque fragment (or the background) is the base; the transparent fragments in
// front of it are composited over it back to front, c = a*s + (1-a)*c with a = alpha/255, in
// double; no fragments give the background. Leaves f sorted.
Rgb composite_pixel(const RasterizedScene& rs, uint32_t* f, size_t n) {
  uint32_t* first = f;
  uint32_t* last = f + n;
  const auto nearer = [&](uint32_t a, uint32_t b) { return rs.z_exact[a] < rs.z_exact[b]; };
  if (n > 32) {
    std::stable_sort(first, last, nearer);
  } else {  // stable too, without stable_sort's buffer for the few layers most pixels have
    for (uint32_t* i = first + (n > 0); i < last; ++i) {
      const uint32_t v = *i;
      uint32_t* j = i;
      for (; j > first && nearer(v, *(j - 1)); --j) *j = *(j - 1);
      *j = v;
    }
  }
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

// The buckets of composite_rows, kept by a caller that composites band after band.
struct ExactScratch {
  std::vector<uint32_t> start, order, fill;
};

// Per pixel of rows [row0, row0 + rows) (rs holds only their fragments), in row-major order,
// visit(p, colour, depth) with p counted from the band's first pixel: composite_pixel's
// unrounded colour and the nearest depth, or the background and the far depth.
template <class Visit>
void composite_rows(const RasterizedScene& rs, int row0, int rows, ExactScratch& scratch, Visit visit) {
  const Viewport& vp = rs.viewport;
  const size_t pixels = static_cast<size_t>(vp.width) * size_t(rows);
  const Rgba8 bg = rs.background;
  auto index = [&](const Fragment& f) { return static_cast<size_t>(f.y - row0) * vp.width + f.x; };

  // Bucket fragment indices by pixel, keeping submit order within a pixel.
  std::vector<uint32_t>& start = scratch.start;
  start.assign(pixels + 1, 0);
  for (const Fragment& f : rs.fragments) ++start[index(f) + 1];
  for (size_t p = 0; p < pixels; ++p) start[p + 1] += start[p];
  std::vector<uint32_t>& order = scratch.order;
  order.resize(rs.fragments.size());
  std::vector<uint32_t>& fill = scratch.fill;
  fill.assign(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < rs.fragments.size(); ++i) order[fill[index(rs.fragments[i])]++] = i;

  const Rgb background{double(bg.r), double(bg.g), double(bg.b)};
  for (size_t p = 0; p < pixels; ++p) {
    auto first = order.begin() + start[p];
    auto last = order.begin() + start[p + 1];
    if (first == last) {
      visit(p, background, depth_max(vp.depth_bits));
      continue;
    }
    const Rgb c = composite_pixel(rs, &*first, size_t(last - first));
    visit(p, c, rs.fragments[*first].z);
  }
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
  ExactScratch scratch;
  composite_rows(rs, 0, vp.height, scratch, [&](size_t p, const Rgb& c, uint32_t depth) {
    fb.color[p] = {to_unorm8(c[0]), to_unorm8(c[1]), to_unorm8(c[2]), 255};
    fb.depth[p] = depth;
  });
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
    ExactScratch scratch;
    std::vector<Rgb> sums;
    std::vector<uint32_t> nearest;
    RasterizedScene rs;
    rs.viewport = big;
    rs.background = scene.background;
    for (int b; (b = next++) < bands;) {
      const int y0 = b * kBandRows, y1 = std::min(vp.height, y0 + kBandRows);
      rs.fragments.clear();
      rs.z_exact.clear();
      for (const ScreenTriangle& t : triangles)
        rasterize(t, big, rs.fragments, &rs.z_exact, RowRange{y0 * factor, y1 * factor});
      // Each sub-pixel's colour summed into its pixel as it comes, row by row: the order of
      // the sums is the sub-pixels' row-major one, as a whole frame's would be.
      const size_t n = size_t(vp.width) * size_t(y1 - y0);
      sums.assign(n, Rgb{0, 0, 0});
      nearest.assign(n, depth_max(vp.depth_bits));
      // Sub-pixels come one by one in row-major order: their pixel follows without a division.
      size_t row_first = 0, p = 0;
      int sx = 0, sy = 0, bx = 0;
      composite_rows(rs, y0 * factor, (y1 - y0) * factor, scratch, [&](size_t, const Rgb& c, uint32_t depth) {
        for (int k = 0; k < 3; ++k) sums[p][k] += c[k];
        nearest[p] = std::min(nearest[p], depth);
        if (++sx == factor) sx = 0, ++p;
        if (++bx == big.width) {
          bx = 0;
          if (++sy == factor) sy = 0, row_first += size_t(vp.width);
          p = row_first;
        }
      });
      for (size_t k = 0; k < n; ++k) {
        const size_t p = fb.index(int(k % size_t(vp.width)), y0 + int(k / size_t(vp.width)));
        fb.color[p] = {to_unorm8(sums[k][0] / samples), to_unorm8(sums[k][1] / samples),
                       to_unorm8(sums[k][2] / samples), 255};
        fb.depth[p] = nearest[k];
      }
    }
  });
  return fb;
}

}  // namespace zb
