// random: constrained-random states and streams, several passes per small frame; the first
// iteration adds every blend mode with every colour mask.
#include <fmt/core.h>

#include <algorithm>
#include <string>
#include <vector>

#include "rop/fixed.h"
#include "suites.h"

namespace zb::tb {

Tally suite_random(const Config& c) {
  Tally t;
  const uint64_t total = c.fragments ? c.fragments : 300000;
  const int iters = c.iterations ? c.iterations : std::max<int>(1, int(total / 6000));
  WorkCounter progress(c, iters);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("random", c, seed, t, [&](Cosim& cs) {
      Rng r(seed);
      // Mostly one tile; sometimes straddling tile edges.
      const int w = r.chance(0.25) ? 60 + int(r.below(90)) : 1 + int(r.below(48));
      const int h = r.chance(0.25) ? 60 + int(r.below(40)) : 1 + int(r.below(40));
      const Rgba8 clear{uint8_t(r.below(256)), uint8_t(r.below(256)), uint8_t(r.below(256)),
                        pick_alpha(r)};
      cs.begin_frame(w, h, 24, clear);
      std::vector<uint32_t> zpool(8);
      for (uint32_t& z : zpool) z = r.chance(0.3) ? depth_max(24) : r.below(depth_max(24));
      const int passes = 2 + int(r.below(4));
      const size_t per_pass = std::max<size_t>(1, 6000 / passes);
      for (int p = 0; p < passes; ++p) {
        // Frame operations between passes: random peel planes (the depth of the frame so
        // far, copied), depth and colour clears.
        if (r.chance(0.4)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        if (r.chance(0.2))
          cs.frame_op({FrameOpKind::kClearDepth, {}, zpool[r.below(uint32_t(zpool.size()))], false});
        if (r.chance(0.15))
          cs.frame_op({FrameOpKind::kClearColor,
                       {pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)}, 0, false});
        if (r.chance(0.1))
          cs.frame_op({FrameOpKind::kResolveUnder,
                       {pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)}, 0, false});
        const RopState st = random_state(r);
        draw_pass(cs, "random-" + std::to_string(p + 1), st,
                  random_stream(r, w, h, per_pass, 4, 0.3, zpool));
      }
      // The first iteration also draws every blend mode with every colour mask, a short pass
      // each: random states reach a given pair once in 320 passes.
      for (unsigned b = 0; it == 0 && b < kCoreBlendModes; ++b)
        for (uint8_t m = 0; m < 16; ++m) {
          RopState st = random_state(r);
          st.blend = BlendMode(b);
          st.color_mask = m;
          draw_pass(cs, fmt::format("random-blend{}-mask{:x}", b, m), st,
                    random_stream(r, w, h, 40, 4, 0.3, zpool));
        }
    });
    if (!ok) break;
    progress.add();
  }
  return t;
}

}  // namespace zb::tb
