// The read-modify-write suites' streams (accum, layers): one tile's fragments at the
// same-pixel issue distances the forwarding and bypass serve (docs/rtl.md "Same-pixel distance").
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "rop/fixed.h"
#include "rop/fragment.h"
#include "rtl_timing.h"
#include "suites.h"

namespace zb::tb {

inline constexpr int kPixels = kRtlTileW * kRtlTileH;

// Streams that put a pixel's fragments at the same-pixel issue distances on purpose: the
// pixel, then 3 to 6 fragments to pixels of their own, then the pixel again; runs on one or two
// pixels; random fragments between. Depths from a small pool (equal depths) and the extremes,
// alphas from the edges (0, 1, 127, 128, 254, 255) or random.
struct SamePixelStreams {
  Rng& r;
  std::vector<uint32_t> zpool;

  uint32_t depth() {
    const uint32_t zmax = depth_max(24);
    switch (r.below(6)) {
      case 0: return 0;
      case 1: return zmax;
      case 2: case 3: return zpool[r.below(uint32_t(zpool.size()))];
      default: return r.below(zmax + 1u);
    }
  }
  uint8_t alpha() {
    static const uint8_t special[] = {0, 1, 127, 128, 254, 255};
    return r.chance(0.4) ? special[r.below(6)] : uint8_t(r.below(256));
  }
  Fragment at(int pixel) {
    Fragment f;
    f.x = uint16_t(pixel % kRtlTileW);
    f.y = uint16_t(pixel / kRtlTileW);
    f.z = depth();
    f.color = Rgba8{uint8_t(r.below(256)), uint8_t(r.below(256)), uint8_t(r.below(256)), alpha()};
    f.coverage = uint8_t(kRtlCoverageSamples);
    return f;
  }
  int pixel() { return int(r.below(kPixels)); }

  // `n` fragments: distance patterns, runs and random fragments, in pieces.
  std::vector<Fragment> stream(size_t n) {
    std::vector<Fragment> out;
    while (out.size() < n) {
      switch (r.below(4)) {
        case 0:
        case 1: {  // the pixel, then 3..6 others, again and again
          const int a = pixel(), gap = 3 + int(r.below(4));
          for (int rep = 2 + int(r.below(6)); rep > 0; --rep) {
            out.push_back(at(a));
            for (int i = 0; i < gap; ++i) out.push_back(at(pixel()));
          }
          break;
        }
        case 2: {  // a run on one or two pixels
          const int a = pixel(), b = r.chance(0.5) ? a : (a + 1) % kPixels;
          for (int i = 8 + int(r.below(32)); i > 0; --i) out.push_back(at(r.chance(0.5) ? a : b));
          break;
        }
        default:
          for (int i = 1 + int(r.below(20)); i > 0; --i) out.push_back(at(pixel()));
          break;
      }
    }
    out.resize(n);
    for (size_t i = 0; i < out.size(); ++i) out[i].prim = uint32_t(i / 16);
    return out;
  }
};

// Same-pixel issue distances 4..7 of `f` (one tile's stream) in the issue schedule.
inline void count_distances(const std::vector<Fragment>& f, uint64_t dist[4]) {
  IssueSchedule schedule(kRtlWindow, size_t(kPixels));
  std::vector<uint32_t> px(f.size());
  for (size_t i = 0; i < f.size(); ++i) px[i] = uint32_t(f[i].y) * kRtlTileW + f[i].x;
  std::vector<uint64_t> issue(f.size());
  schedule.run(px.data(), px.size(), issue.data());
  std::vector<uint64_t> last(size_t(kPixels), ~uint64_t{0});
  for (size_t i = 0; i < f.size(); ++i) {
    const uint64_t prev = last[px[i]];
    if (prev != ~uint64_t{0} && issue[i] - prev >= 4 && issue[i] - prev <= 7)
      ++dist[issue[i] - prev - 4];
    last[px[i]] = issue[i];
  }
}

// A read-modify-write suite's frame loop (accum, layers): per iteration a fresh Cosim on one
// tile, its Rng (seed ^ salt) and streams (a depth pool of `zpool` depths), the frame cleared,
// an opaque pass of per_pass / 2 fragments named NAME-opaque, then `passes` calls of
// pass(cs, r, d, per_pass, p, dist), which draws pass p and counts its distances. The note
// gives the distances reached in MODE passes, and warns when one never was.
template <class Pass>
Tally same_pixel_suite(const char* name, const char* mode, const Config& c, int passes,
                       uint64_t salt, size_t zpool, Pass&& pass) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 6;
  const size_t per_pass =
      c.fragments ? std::max<uint64_t>(1, c.fragments / uint64_t(iters) / uint64_t(passes)) : 3000;
  uint64_t dist[4] = {};
  WorkCounter progress(c, uint64_t(iters));
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration(name, c, seed, t, [&](Cosim& cs) {
      Rng r(seed ^ salt);
      SamePixelStreams d{r, std::vector<uint32_t>(zpool)};
      for (uint32_t& z : d.zpool) z = r.below(depth_max(24));
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{20, 40, 60, 255}, kRtlCoverageSamples,
                     kRtlWboit);
      RopState opaque;  // the opaque depth (and colour) the passes test against
      opaque.depth_test = true;
      opaque.depth_write = true;
      draw_pass(cs, std::string(name) + "-opaque", opaque, d.stream(per_pass / 2));
      for (int p = 0; p < passes; ++p) pass(cs, r, d, per_pass, p, dist);
    });
    if (!ok) break;
    progress.add();
  }
  t.note = fmt::format(
      "same-pixel issue distances 4/5/6/7 in {} passes (the schedule without back-pressure): "
      "{}/{}/{}/{}",
      mode, dist[0], dist[1], dist[2], dist[3]);
  if (!t.failed && std::find(std::begin(dist), std::end(dist), 0u) != std::end(dist))
    t.note += "; warning: a distance was never reached";
  return t;
}

}  // namespace zb::tb
