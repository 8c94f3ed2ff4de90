// The testbench's random stimulus; see stimulus.h.
#include "stimulus.h"

#include <algorithm>
#include <utility>

#include "rtl_params.h"

namespace zb::tb {

RopState random_state(Rng& r) {
  RopState s;
  s.depth_test = !r.chance(0.15);
  s.depth_func = DepthFunc(r.below(8));
  s.depth_write = r.chance(0.6);
  s.blend = BlendMode(r.below(kCoreBlendModes));  // replace .. accumulate
  const uint32_t m = r.below(4);
  s.color_mask = m == 0 ? uint8_t(r.below(16)) : uint8_t(kMaskRgba);
  s.peel_test = r.chance(0.3);
  return s;
}

uint8_t pick_alpha(Rng& r) {
  static const uint8_t special[] = {0, 1, 254, 255};
  return r.chance(0.5) ? special[r.below(4)] : uint8_t(r.below(256));
}

uint8_t pick_channel(Rng& r) {
  return r.chance(0.2) ? (r.chance(0.5) ? 0 : 255) : uint8_t(r.below(256));
}

std::vector<Fragment> random_stream(Rng& r, int w, int h, size_t n, int hot, double hot_share,
                                    std::vector<uint32_t>& zpool) {
  const uint32_t zmax = depth_max(24);
  std::vector<Fragment> out;
  out.reserve(n);
  std::vector<std::pair<uint16_t, uint16_t>> spots;
  size_t run_left = 0;
  while (out.size() < n) {
    Fragment f;
    if (hot > 0 && run_left == 0 && r.chance(hot_share)) {
      spots.clear();
      const int k = 1 + int(r.below(uint32_t(hot)));
      const int bx = int(r.below(uint32_t(w))), by = int(r.below(uint32_t(h)));
      for (int i = 0; i < k; ++i) {  // neighbours, so the hot pixels share a tile mostly
        // One draw per statement: as two arguments of one call their order was the compiler's
        // (GCC drew y first, clang x), so a seed's stream differed by compiler. GCC's order is
        // kept, so every seed's stimulus of a GCC build is unchanged.
        const int dy = int(r.below(2));
        const int dx = int(r.below(3));
        spots.emplace_back(uint16_t(std::min(w - 1, bx + dx)), uint16_t(std::min(h - 1, by + dy)));
      }
      run_left = 8 + r.below(120);
    }
    if (run_left) {
      --run_left;
      const auto& s = spots[r.below(uint32_t(spots.size()))];
      f.x = s.first;
      f.y = s.second;
    } else {
      f.x = uint16_t(r.below(uint32_t(w)));
      f.y = uint16_t(r.below(uint32_t(h)));
    }
    switch (r.below(8)) {
      case 0: f.z = 0; break;
      case 1: f.z = zmax; break;
      case 2: f.z = zmax - 1; break;
      case 3: case 4: f.z = zpool[r.below(uint32_t(zpool.size()))]; break;  // equal depths
      default: f.z = r.below(zmax + 1u); break;
    }
    if (r.chance(0.05)) zpool[r.below(uint32_t(zpool.size()))] = f.z;
    f.color = Rgba8{pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)};
    f.front = r.chance(0.5);
    // Coverage: 0 (the rasterizer never sends it; the datapath defines it), 1, N - 1, N, or any.
    static const uint8_t kCov[] = {0, 1, kRtlCoverageSamples - 1, kRtlCoverageSamples};
    f.coverage = r.chance(0.5) ? kCov[r.below(4)] : uint8_t(r.below(kRtlCoverageSamples + 1));
    f.prim = uint32_t(out.size() / 16);
    out.push_back(f);
  }
  return out;
}

HazardStimulus::HazardStimulus(uint64_t seed) : rng_(seed), zpool_(4) {
  for (uint32_t& z : zpool_) z = rng_.below(depth_max(24));
}

RopState HazardStimulus::next_state() {
  RopState st = random_state(rng_);
  // Mostly states where back-to-back fragments change the pixel: the RMW path.
  if (rng_.chance(0.7)) {
    static const DepthFunc busy[] = {DepthFunc::kAlways, DepthFunc::kLequal, DepthFunc::kGequal,
                                     DepthFunc::kNotequal};
    st.depth_func = busy[rng_.below(4)];
    static const BlendMode rmw[] = {BlendMode::kAlpha, BlendMode::kAdditive,
                                    BlendMode::kCoverage, BlendMode::kUnder,
                                    BlendMode::kAccumulate};
    st.blend = rmw[rng_.below(5)];
  }
  return st;
}

std::vector<Fragment> HazardStimulus::next_fragments(size_t count) {
  return random_stream(rng_, kRtlTileW, kRtlTileH, count, 4, 0.9, zpool_);
}

}  // namespace zb::tb
