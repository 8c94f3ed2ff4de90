// blend: the blend unit exhaustively, through the whole pipeline, for both modes that read the
// destination: all 2^24 (s, a, d) on R, G, B and all 2^16 (a, d) on A, for alpha and additive.
// --fragments N samples the R, G, B part instead (about N fragments in all; A stays whole).
#include <algorithm>
#include <string>
#include <vector>

#include "suites.h"

namespace zb::tb {

namespace {

constexpr int kBlendW = kRtlTileW, kBlendH = kRtlTileH, kBlendPix = kBlendW * kBlendH;

Fragment at_pixel(int i, Rgba8 color) {
  Fragment f;
  f.x = uint16_t(i % kBlendW);
  f.y = uint16_t(i / kBlendW);
  f.color = color;
  return f;
}

// R, G, B: the 2^24 (s, a, d) of `mode`, all of them, or `count` < kBlendIndices indices spread
// over the whole space. Each pass starts a fresh frame cleared to 0. Per pixel a fragment with
// alpha 255 first loads the destination: m(x, 255) = x and m(0, 0) = 0, so both modes write the
// fragment's colour ("alpha: min(255, m(s, a) + m(d, 255 - a))", "additive: min(255, d +
// m(s, a))"); then the fragment under test blends onto it. Each pixel carries three triples: d
// in [0, 86) on R, d + 86 on G, d + 172 on B (clamped to 255). The destination alpha is 255
// here; blend_alpha_channel covers the rest.
constexpr uint64_t kBlendIndices = 256ull * 256 * 86;  // (a, s, d): d fastest, then s, then a
// A sample steps through the indices by a stride coprime to their count (2^17 * 43): distinct,
// and over every a.
constexpr uint64_t kSampleStride = 2654435761ull % kBlendIndices;
static_assert(kSampleStride % 2 == 1 && kSampleStride % 43 != 0, "stride must be coprime");
constexpr uint64_t kAlphaTotal = 256u * 256;  // (a, d) on A: d fastest
constexpr uint64_t kCoverageTotal = uint64_t(kRtlCoverageSamples + 1) * 256 * 86;  // d, s, k

void blend_rgb(Cosim& cs, BlendMode mode, const char* tag, uint64_t count, WorkCounter& progress) {
  RopState st;
  st.depth_test = false;
  st.blend = mode;
  const uint64_t stride = count >= kBlendIndices ? 1 : kSampleStride;
  count = std::min(count, kBlendIndices);
  std::vector<Fragment> f;
  f.reserve(2 * kBlendPix);
  uint64_t k = 0;
  int pass = 0;
  while (k < count) {
    const uint64_t first = k;
    cs.begin_frame(kBlendW, kBlendH, 24, Rgba8{0, 0, 0, 0});
    f.clear();
    // Groups of 8 pixels: 8 destinations, then the 8 blends onto them, so the blends follow
    // their pixel's write by 8 cycles (the hazard suite covers back-to-back).
    for (int base = 0; base < kBlendPix && k < count; base += 8) {
      const int n = int(std::min<uint64_t>(8, std::min<uint64_t>(kBlendPix - base, count - k)));
      for (int i = 0; i < n; ++i) {
        const uint8_t d = uint8_t((k + i) * stride % kBlendIndices % 86);
        f.push_back(at_pixel(base + i, Rgba8{d, uint8_t(std::min(255, d + 86)),
                                             uint8_t(std::min(255, d + 172)), 255}));
      }
      for (int i = 0; i < n; ++i) {
        const uint64_t v = (k + i) * stride % kBlendIndices;
        const uint8_t s = uint8_t(v / 86 % 256), a = uint8_t(v / (86 * 256));
        f.push_back(at_pixel(base + i, Rgba8{s, uint8_t(255 - s), uint8_t(s ^ 0x5a), a}));
      }
      k += uint64_t(n);
    }
    draw_pass(cs, std::string("blend-") + tag + "-rgb-" + std::to_string(++pass), st, f);
    progress.add(k - first);
  }
}

// A: all 2^16 (a, d) of `mode` on the alpha channel, where the source is the alpha itself. A
// replace pass loads the destinations (every channel, A included), then the blend pass. The
// R, G and B channels see further (s, a, d) triples on the way.
void blend_alpha_channel(Cosim& cs, BlendMode mode, const char* tag, WorkCounter& progress) {
  RopState load;
  load.depth_test = false;
  load.blend = BlendMode::kReplace;
  RopState st = load;
  st.blend = mode;
  std::vector<Fragment> dst, src;
  constexpr uint32_t kTotal = kAlphaTotal;
  for (uint32_t first = 0; first < kTotal; first += kBlendPix) {
    cs.begin_frame(kBlendW, kBlendH, 24, Rgba8{0, 0, 0, 0});
    dst.clear();
    src.clear();
    for (uint32_t v = first; v < std::min<uint32_t>(kTotal, first + kBlendPix); ++v) {
      const uint8_t a = uint8_t(v >> 8), d = uint8_t(v);
      const int i = int(v - first);
      dst.push_back(at_pixel(i, Rgba8{uint8_t(v * 37u), uint8_t(v >> 3), uint8_t(~v), d}));
      src.push_back(
          at_pixel(i, Rgba8{uint8_t(v * 11u + 3u), uint8_t(v >> 5), uint8_t(v * 101u), a}));
    }
    const std::string n = std::to_string(first / kBlendPix + 1);
    draw_pass(cs, std::string("blend-") + tag + "-a-load-" + n, load, dst);
    draw_pass(cs, std::string("blend-") + tag + "-a-" + n, st, src);
    progress.add(src.size());
  }
}

// Coverage: all (k, s, d), k = 0..N, through the whole pipeline. A replace pass (depth test
// off: depth stays ZMAX, coverage 0) loads d; a coverage pass at z = 0 is then nearer on every
// pixel, so the weight is k: "(w*s + (N - w)*d + N/2) >> log2 N" with w = k (the farther and
// full cases use the same unit with w = N - cs and N, values k covers). As blend_rgb, three
// triples per pixel: d on R, d + 86 on G, d + 172 on B (clamped), all four channels blended.
void blend_coverage_rgb(Cosim& cs, WorkCounter& progress) {
  RopState load;
  load.depth_test = false;
  load.blend = BlendMode::kReplace;
  RopState st;
  st.depth_test = true;
  st.depth_write = true;
  st.blend = BlendMode::kCoverage;
  constexpr uint64_t kTotal = kCoverageTotal;
  std::vector<Fragment> dst, src;
  int pass = 0;
  for (uint64_t first = 0; first < kTotal; first += kBlendPix) {
    cs.begin_frame(kBlendW, kBlendH, 24, Rgba8{0, 0, 0, 0}, kRtlCoverageSamples);
    dst.clear();
    src.clear();
    for (uint64_t v = first; v < std::min<uint64_t>(kTotal, first + kBlendPix); ++v) {
      const uint8_t d = uint8_t(v % 86), s = uint8_t(v / 86 % 256);
      const uint8_t k = uint8_t(v / (86 * 256));
      const int i = int(v - first);
      dst.push_back(at_pixel(i, Rgba8{d, uint8_t(std::min(255, d + 86)),
                                      uint8_t(std::min(255, d + 172)), uint8_t(v * 7u)}));
      Fragment f = at_pixel(i, Rgba8{s, s, s, uint8_t(255 - s)});
      f.z = 0;
      f.coverage = k;
      src.push_back(f);
    }
    const std::string n = std::to_string(++pass);
    draw_pass(cs, "blend-coverage-load-" + n, load, dst);
    draw_pass(cs, "blend-coverage-" + n, st, src);
    progress.add(src.size());
  }
}

}  // namespace

Tally suite_blend(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 1;
  const uint64_t count = c.fragments ? std::max<uint64_t>(1, c.fragments / 4) : kBlendIndices;
  const uint64_t per_iteration = 2 * std::min(count, kBlendIndices) + 2 * kAlphaTotal + kCoverageTotal;
  WorkCounter progress(c, iters * per_iteration);
  for (int it = 0; it < iters; ++it) {
    const bool ok = run_iteration("blend", c, c.seed + it, t, [&](Cosim& cs) {
      blend_rgb(cs, BlendMode::kAlpha, "alpha", count, progress);
      blend_alpha_channel(cs, BlendMode::kAlpha, "alpha", progress);
      blend_rgb(cs, BlendMode::kAdditive, "additive", count, progress);
      blend_alpha_channel(cs, BlendMode::kAdditive, "additive", progress);
      blend_coverage_rgb(cs, progress);
    });
    if (!ok) break;
  }
  t.note = count >= kBlendIndices
               ? "per iteration and per mode (alpha, additive): all 2^24 (s, a, d) on R/G/B, "
                 "all 2^16 (a, d) on A; coverage: all (k, s, d), k = 0..N"
               : "per iteration and per mode (alpha, additive): a sample of " +
                     std::to_string(3 * count) + " (s, a, d) on R/G/B, all 2^16 (a, d) on A";
  return t;
}

}  // namespace zb::tb
