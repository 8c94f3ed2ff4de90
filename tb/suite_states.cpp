// states: every pass state the coverage plan crosses (tb/cov/coverage_plan.json, pass_state):
// depth test off or each function x depth write x blend mode x colour mask x peel test, a
// short pass each on one tile, in a shuffled order so each state follows a random other.
#include <fmt/core.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "rtl_params.h"
#include "suites.h"

namespace zb::tb {

namespace {

constexpr int kDepthBins = 9;  // test off, then the eight functions
constexpr int kStates = kDepthBins * 2 * kCoreBlendModes * 16 * 2;

RopState state_of(int i) {
  RopState st;
  const int peel = i % 2, mask = i / 2 % 16, blend = i / 32 % kCoreBlendModes;
  const int write = i / (32 * kCoreBlendModes) % 2, depth = i / (64 * kCoreBlendModes);
  st.depth_test = depth != 0;
  st.depth_func = DepthFunc(depth == 0 ? 1 : depth - 1);
  st.depth_write = write != 0;
  st.blend = BlendMode(blend);
  st.color_mask = uint8_t(mask);
  st.peel_test = peel != 0;
  return st;
}

}  // namespace

Tally suite_states(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 1;
  const size_t per_pass = c.fragments ? std::max<uint64_t>(1, c.fragments / kStates) : 12;
  WorkCounter progress(c, uint64_t(iters) * kStates);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("states", c, seed, t, [&](Cosim& cs) {
      Rng r(seed);
      std::vector<int> order(kStates);
      std::iota(order.begin(), order.end(), 0);
      for (int i = kStates - 1; i > 0; --i) std::swap(order[i], order[r.below(uint32_t(i + 1))]);
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{40, 80, 120, pick_alpha(r)});
      std::vector<uint32_t> zpool(8);
      for (uint32_t& z : zpool) z = r.chance(0.3) ? depth_max(24) : r.below(depth_max(24));
      for (int k = 0; k < kStates; ++k) {
        // A peel plane to test against now and then: the depth so far, or a cleared one.
        if (r.chance(0.05)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        if (r.chance(0.03))
          cs.frame_op({FrameOpKind::kClearDepth, {}, zpool[r.below(uint32_t(zpool.size()))],
                       false});
        const int s = order[size_t(k)];
        draw_pass(cs, fmt::format("states-{}", s), state_of(s),
                  random_stream(r, kRtlTileW, kRtlTileH, per_pass, 2, 0.5, zpool));
        progress.add();
      }
    });
    if (!ok) break;
  }
  return t;
}

}  // namespace zb::tb
