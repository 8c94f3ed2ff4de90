// Coverage for anti-aliasing (US 5,123,085): the sample pattern and the coverage rasterizer.
// Bit-exact rules in docs/raster.md, "Coverage".
#pragma once

#include <cstdint>
#include <vector>

#include "rop/fragment.h"
#include "geometry/geometry.h"
#include "raster.h"

namespace zb {

// One sample position inside a pixel, in 1/256 pixel from its top-left corner (0..255).
struct SamplePos {
  int x = 0;
  int y = 0;
};

// The documented N-rooks pattern of `n` samples (valid_coverage_samples(n)): sample i sits in
// row (2i + 1) * 128 / n and column (2 * col(i) + 1) * 128 / n, every row and column used
// once. Throws std::invalid_argument for an invalid n.
const std::vector<SamplePos>& sample_pattern(int n);

// Appends the coverage fragments of `tri`: every pixel of the viewport with at least one
// covered sample of the vp.coverage_samples pattern, coverage = the count, depth at the pixel
// centre by the rasterizer's exact formula clamped to the vertex depth range; rows top to
// bottom, each left to right. Samples use the same edge functions and top-left rule as pixel
// centres. When `z_exact` is given, appends each fragment's unrounded (clamped) depth too.
// `rows` scissors rows as for rasterize (raster.h): the rows kept give the same fragments.
void rasterize_coverage(const ScreenTriangle& tri, const Viewport& vp, std::vector<Fragment>& out,
                        std::vector<double>* z_exact = nullptr, RowRange rows = {});

// The pixels rasterize_coverage tests for `tri` (a fragment at most each): its vertices' box
// (a pixel with a sample position inside it), scissored to the viewport and `rows`.
struct PixelBox {
  int64_t x_lo = 0, x_hi = -1, y_lo = 0, y_hi = -1;
  bool empty() const { return x_lo > x_hi || y_lo > y_hi; }
  uint64_t pixels() const {
    return empty() ? 0 : uint64_t(x_hi - x_lo + 1) * uint64_t(y_hi - y_lo + 1);
  }
};
PixelBox coverage_box(const ScreenTriangle& tri, const Viewport& vp, RowRange rows = {});

}  // namespace zb
