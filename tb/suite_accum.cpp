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
  constexpr int kPasses = 4;
  return same_pixel_suite(
      "accum", "accumulate", c, kPasses, 0xacc0ull, 6,
      [&](Cosim& cs, Rng& r, SamePixelStreams& d, size_t per_pass, int p, uint64_t dist[4]) {
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kResolveWboit, {}, 0, false});
        if (r.chance(0.1))
          cs.frame_op({FrameOpKind::kClearColor, Rgba8{uint8_t(r.below(256)), 0, 0, 255}, 0,
                       false});
        const RopState st = accumulate_state(r);
        const std::vector<Fragment> f = d.stream(per_pass);
        if (st.color_mask != 0) count_distances(f, dist);
        draw_pass(cs, "accum-" + std::to_string(p + 1), st, f);
        if (p == kPasses - 1) cs.frame_op({FrameOpKind::kResolveWboit, {}, 0, false});
      });
}

}  // namespace zb::tb
