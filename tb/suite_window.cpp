// window: directed streams for the issue window: one pixel filling it, two alternating, rings
// of 2..WINDOW+3 pixels, one pixel at gaps of 0..4; read-modify-write states.
#include <algorithm>
#include <vector>

#include "suites.h"

namespace zb::tb {

namespace {

// The window suite's pixel patterns, as tile-local pixel numbers (p % W, p / W).
std::vector<int> window_pattern(int kind, Rng& r, size_t n) {
  std::vector<int> px;
  const int a = int(r.below(uint32_t(kRtlTileW * kRtlTileH)));
  auto other = [&] { return int(r.below(uint32_t(kRtlTileW * kRtlTileH))); };
  while (px.size() < n) switch (kind) {
      case 0: {  // one pixel fills the window, then others pass it, then it again
        for (unsigned i = 0; i < kRtlWindow + 3; ++i) px.push_back(a);
        for (int i = 0; i < 12; ++i) px.push_back(other());
        break;
      }
      case 1: px.push_back(int(px.size() % 2) ? a : (a + 1) % (kRtlTileW * kRtlTileH)); break;
      case 2: {  // a ring of k pixels: k below the span waits, at or above it streams
        const int k = 2 + int(r.below(kRtlWindow + 2));
        for (int i = 0; i < 8 * k; ++i) px.push_back((a + 3 * (i % k)) % (kRtlTileW * kRtlTileH));
        break;
      }
      default:  // one pixel every few fragments, the gap from 0 to the span
        px.push_back(a);
        for (uint32_t g = r.below(5); g > 0; --g) px.push_back(other());
        break;
    }
  px.resize(n);
  return px;
}

}  // namespace

Tally suite_window(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 8;
  const size_t per_pass = c.fragments ? std::max<uint64_t>(1, c.fragments / iters / 4) : 2000;
  WorkCounter progress(c, iters);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("window", c, seed, t, [&](Cosim& cs) {
      HazardStimulus stim(seed);
      Rng r(seed ^ 0x77);
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{10, 20, 30, 40});
      for (int kind = 0; kind < 4; ++kind) {
        std::vector<Fragment> f = stim.next_fragments(per_pass);  // depths, colours, coverage
        const std::vector<int> px = window_pattern(kind, r, f.size());
        for (size_t i = 0; i < f.size(); ++i) {
          f[i].x = uint16_t(px[i] % kRtlTileW);
          f[i].y = uint16_t(px[i] / kRtlTileW);
        }
        static const char* kNames[] = {"window-fill", "window-alternate", "window-ring",
                                       "window-gaps"};
        draw_pass(cs, kNames[kind], stim.next_state(), f);
      }
    });
    if (!ok) break;
    progress.add();
  }
  return t;
}

}  // namespace zb::tb
