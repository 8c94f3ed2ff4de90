// Primitives binned by the bands of rows they may touch (frame_render.h), binned on several
// threads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "raster/internal/edge_functions.h"
#include "geometry/geometry.h"
#include "parallel/parallel.h"

namespace zb {

// A primitive in a band's list: its index and the passes that draw it (bit i: pass i; plans of
// more than 32 passes ask pass_draws for the others), so a pass skips what it filters out
// without touching the primitive.
struct BinItem {
  uint32_t index = 0;
  uint32_t passes = 0;
};

// Primitives binned by band, in primitive order. The primitives are cut into contiguous
// slices binned by different threads: band b's list is slice 0's list for b, then slice 1's...
struct Bins {
  int bands = 0;
  std::vector<std::vector<BinItem>> lists;  // [slice * bands + band]
  size_t slices() const { return bands ? lists.size() / size_t(bands) : 0; }
  const std::vector<BinItem>& list(size_t slice, int band) const {
    return lists[slice * size_t(bands) + size_t(band)];
  }
};

// Bins `count` primitives on `threads` threads. rows(i, lo, hi, passes) gives the rows
// primitive i may touch (false: none; hi inclusive, both within the frame) and its pass bits.
// The threads find each primitive's bands and count; the lists are then allocated by the
// caller at their exact sizes (lists grown in the workers' own malloc arenas cost megabytes of
// resident memory, measured) and filled.
template <class Rows>
Bins bin_by_band(size_t count, int bands, int band_rows, int threads, Rows&& rows) {
  const int slices = static_cast<int>(std::clamp<size_t>(count / 4096, 1, size_t(threads)));
  auto slice_range = [&](int s, size_t& first, size_t& last) {
    first = count * size_t(s) / size_t(slices);
    last = count * size_t(s + 1) / size_t(slices);
  };
  struct Span {
    int32_t lo = 0, hi = -1;  // bands; none when hi < lo
    uint32_t passes = 0;
  };
  std::vector<Span> spans(count);
  std::vector<size_t> sizes(size_t(slices) * size_t(bands), 0);
  run_workers(slices, [&](int s) {
    size_t first = 0, last = 0;
    slice_range(s, first, last);
    size_t* n = &sizes[size_t(s) * size_t(bands)];
    for (size_t i = first; i < last; ++i) {
      int lo = 0, hi = 0;
      Span& sp = spans[i];
      if (!rows(i, lo, hi, sp.passes)) continue;
      sp.lo = lo / band_rows;
      sp.hi = hi / band_rows;
      for (int b = sp.lo; b <= sp.hi; ++b) ++n[b];
    }
  });
  Bins bins;
  bins.bands = bands;
  bins.lists.resize(sizes.size());
  for (size_t k = 0; k < sizes.size(); ++k) bins.lists[k].reserve(sizes[k]);
  run_workers(slices, [&](int s) {
    size_t first = 0, last = 0;
    slice_range(s, first, last);
    std::vector<BinItem>* lists = &bins.lists[size_t(s) * size_t(bands)];
    for (size_t i = first; i < last; ++i)
      for (int b = spans[i].lo; b <= spans[i].hi; ++b)
        lists[b].push_back(BinItem{static_cast<uint32_t>(i), spans[i].passes});
  });
  return bins;
}

// Rows [floor(y_lo / 256), floor(y_hi / 256)] clipped to the frame; false when the box misses
// it. Every rasterizer (pixel centres, coverage samples, lines) stays inside this box.
inline bool box_rows(const Viewport& vp, int64_t x_lo, int64_t x_hi, int64_t y_lo,
                     int64_t y_hi, int& lo, int& hi) {
  if (edge::floor_div(x_hi, kSubpixelOne) < 0 || edge::floor_div(x_lo, kSubpixelOne) >= vp.width) return false;
  const int64_t r0 = std::max<int64_t>(0, edge::floor_div(y_lo, kSubpixelOne));
  const int64_t r1 = std::min<int64_t>(vp.height - 1, edge::floor_div(y_hi, kSubpixelOne));
  if (r0 > r1) return false;
  lo = static_cast<int>(r0);
  hi = static_cast<int>(r1);
  return true;
}

}  // namespace zb
