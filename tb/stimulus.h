// The testbench's random stimulus (tb/suites.cpp's suites, the conformance kit's hazard and
// random streams, bench_rtl): the golden model's types only, no RTL model, so the kit links it
// without Verilator.
#pragma once

#include <cstdint>
#include <vector>

#include "rop/fragment.h"

namespace zb::tb {

struct Rng {  // splitmix64: suites' stimulus
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed * 0x2545f4914f6cdd1dull + 0x1234567) {}
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  uint32_t below(uint32_t n) { return uint32_t((next() >> 32) * n >> 32); }
  bool chance(double p) { return double(next() >> 11) * 0x1.0p-53 < p; }
};

// A random valid pass state: every depth function and blend mode, a colour mask a quarter of
// the time, the peel test.
RopState random_state(Rng& r);
uint8_t pick_alpha(Rng& r);    // 0, 1, 254, 255 half the time
uint8_t pick_channel(Rng& r);  // 0 or 255 a fifth of the time
// A random stream of `n` fragments on a w x h frame; `hot` > 0 makes runs on 1..hot pixels
// (`hot_share` of the time); depths repeat from `zpool`, which the stream updates.
std::vector<Fragment> random_stream(Rng& r, int w, int h, size_t n, int hot, double hot_share,
                                    std::vector<uint32_t>& zpool);

// The hazard suite's stimulus on one kRtlTileW x kRtlTileH tile, one pass at a time: mostly
// states where back-to-back fragments change the pixel (the read-modify-write path), and
// streams of long runs on 1-4 pixels mixed with random ones. Also drives tests/bench/bench_rtl.cpp.
class HazardStimulus {
 public:
  explicit HazardStimulus(uint64_t seed);
  RopState next_state();
  std::vector<Fragment> next_fragments(size_t count);

 private:
  Rng rng_;
  std::vector<uint32_t> zpool_;  // depths repeated across the stream: equal-depth cases
};

}  // namespace zb::tb
