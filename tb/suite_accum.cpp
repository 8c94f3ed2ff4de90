// accum: the accumulate blend (docs/datapath.md "7. Accumulate blend") through the pipeline, on
// one tile. The accumulation word is read at E5 and written at E11, as the colour: a younger
// fragment to the pixel issued 4 cycles after an older one takes the older one's write data
// (bypass), at 5 and 6 the forwarded word, from 7 on the RAM's (docs/rtl.md "Same-pixel
// distance"). The streams put a pixel's fragments at those distances on purpose: the pixel,
// then 3 to 6 fragments to pixels of their own (the window issues one a cycle while pixels are
// free), then the pixel again; runs on one or two pixels (the span: distance 4, and the
// accumulation's saturation) and random fragments between (same_pixel.h). Depth passes, peel
// planes, colour clears and resolves come between the accumulate passes. The note counts the
// distances the streams reached in the issue schedule without back-pressure (rtl_timing.h).
#include <fmt/core.h>

#include <algorithm>

#include "rop/fixed.h"
#include "same_pixel.h"
#include "suites.h"

namespace zb::tb {

namespace {

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
      SamePixelStreams d{r, std::vector<uint32_t>(6)};
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
