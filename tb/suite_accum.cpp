// accum: the accumulate blend (docs/datapath.md "7. Accumulate blend") through the pipeline, on
// one tile. The accumulation word is read at E5 and written at E11, as the colour: a younger
// fragment to the pixel issued 4 cycles after an older one takes the older one's write data
// (bypass), at 5 and 6 the forwarded word, from 7 on the RAM's (docs/rtl.md "Same-pixel
// distance"). The streams put a pixel's fragments at those distances on purpose: the pixel,
// then 3 to 6 fragments to pixels of their own (the window issues one a cycle while pixels are
// free), then the pixel again; runs on one or two pixels (the span: distance 4, and the
// accumulation's saturation) and random fragments between. Depth passes, peel planes, colour
// clears and resolves come between the accumulate passes. The note counts the distances the
// streams reached in the issue schedule without back-pressure (rtl_timing.h).
#include <fmt/core.h>

#include <algorithm>

#include "rop/fixed.h"
#include "rtl_timing.h"
#include "suites.h"

namespace zb::tb {

namespace {

constexpr int kPixels = kRtlTileW * kRtlTileH;

struct Draw {
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

RopState accumulate_state(Rng& r) {
  static const DepthFunc funcs[] = {DepthFunc::kLess, DepthFunc::kLequal, DepthFunc::kAlways,
                                    DepthFunc::kGreater, DepthFunc::kNotequal};
  RopState s;
  s.blend = BlendMode::kAccumulate;
  s.depth_test = r.chance(0.7);
  s.depth_func = funcs[r.below(5)];
  s.depth_write = r.chance(0.2);
  s.color_mask = r.chance(0.85) ? uint8_t(kMaskRgba) : uint8_t(r.below(16));
  s.peel_test = r.chance(0.2);
  return s;
}

// Same-pixel issue distances 4..7 of `f` (one tile's stream) in the issue schedule.
void count_distances(const std::vector<Fragment>& f, uint64_t dist[4]) {
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

}  // namespace

Tally suite_accum(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 6;
  constexpr int kPasses = 4;
  const size_t per_pass =
      c.fragments ? std::max<uint64_t>(1, c.fragments / uint64_t(iters) / kPasses) : 3000;
  uint64_t dist[4] = {};
  WorkCounter progress(c, uint64_t(iters));
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("accum", c, seed, t, [&](Cosim& cs) {
      Rng r(seed ^ 0xacc0ull);
      Draw d{r, std::vector<uint32_t>(6)};
      for (uint32_t& z : d.zpool) z = r.below(depth_max(24));
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{20, 40, 60, 255}, kRtlCoverageSamples,
                     kRtlWboit);
      // The opaque depth the accumulate passes test against.
      RopState opaque;
      opaque.depth_test = true;
      opaque.depth_write = true;
      draw_pass(cs, "accum-opaque", opaque, d.stream(per_pass / 2));
      for (int p = 0; p < kPasses; ++p) {
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kResolveWboit, {}, 0, false});
        if (r.chance(0.1))
          cs.frame_op({FrameOpKind::kClearColor, Rgba8{uint8_t(r.below(256)), 0, 0, 255}, 0,
                       false});
        const RopState st = accumulate_state(r);
        const std::vector<Fragment> f = d.stream(per_pass);
        if (st.color_mask != 0) count_distances(f, dist);
        draw_pass(cs, "accum-" + std::to_string(p + 1), st, f);
      }
      cs.frame_op({FrameOpKind::kResolveWboit, {}, 0, false});
    });
    if (!ok) break;
    progress.add();
  }
  t.note = fmt::format(
      "same-pixel issue distances 4/5/6/7 in accumulate passes (the schedule without "
      "back-pressure): {}/{}/{}/{}",
      dist[0], dist[1], dist[2], dist[3]);
  if (!t.failed && std::find(std::begin(dist), std::end(dist), 0u) != std::end(dist))
    t.note += "; warning: a distance was never reached";
  return t;
}

}  // namespace zb::tb
