// The named suites of zblend_tb; see suites.h.
#include "suites.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "rop/blend.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "scene/builtin_scenes.h"

namespace zb::tb {

CosimOptions cosim_options(const Config& c, uint64_t seed) {
  CosimOptions o;
  o.rtl.backpressure = c.backpressure;
  o.rtl.seed = seed;
  o.rtl.trace_path = c.trace;
  o.rtl.plusargs = c.plusargs;
  o.rtl.assertions = c.assertions;
  o.rtl.check_timing = c.check_timing;
  o.rtl.reread_stores = c.reread_stores;
  o.rtl.coverage = c.coverage;
  o.mismatch_fst = c.mismatch_fst;
  o.lockstep = c.lockstep;
  return o;
}

// The failure's last lines: the iteration, and the one command that runs it again alone with
// the whole run's waveform and its save file (docs/testbench.md "Waves").
static void fail(const char* suite, const Config& c, uint64_t seed) {
  std::printf("FAIL suite %s iteration seed %llu\n", suite, (unsigned long long)seed);
  const std::string fst = fmt::format("out/waves/{}-{}.fst", suite, seed);
  std::printf("reproduce with waves: %s --suite %s --seed %llu --iterations 1 --trace %s\n",
              c.command.empty() ? "zblend_tb" : c.command.c_str(), suite,
              (unsigned long long)seed, fst.c_str());
}

bool run_iteration(const char* suite, const Config& c, uint64_t seed, Tally& t,
                   const std::function<void(Cosim&)>& body) {
  Cosim cosim(cosim_options(c, seed));
  bool ok = true;
  try {
    body(cosim);
  } catch (const MismatchError& e) {
    std::printf("%s", e.what());
    fail(suite, c, seed);
    t.failed = true;
    ok = false;
    if (cosim.mismatches() == 0) ++t.mismatches;  // a counter mismatch
  } catch (const std::runtime_error& e) {  // a check of the driver's: counts, port, timing
    std::printf("suite %s: error: %s\n", suite, e.what());
    fail(suite, c, seed);
    t.failed = true;
    ok = false;
  }
  ++t.iterations;
  t.fragments += cosim.fragments();
  t.pixels += cosim.pixels_compared();
  t.mismatches += cosim.mismatches();
  t.io_cycles += cosim.rtl().tile_io_cycles();
  t.stream_cycles += cosim.rtl().total_cycles() - cosim.rtl().tile_io_cycles();
  if (c.verbose) std::printf("  %s seed %llu: %llu fragments\n", suite, (unsigned long long)seed,
                             (unsigned long long)cosim.fragments());
  return ok;
}

void draw_pass(Cosim& cs, const std::string& name, const RopState& st,
               const std::vector<Fragment>& f) {
  cs.label_pass(name);
  cs.begin_pass(st);
  cs.draw(f);
  cs.end_pass();
}

// scenes: every built-in scene with every pass plan, 96x72.
Tally suite_scenes(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 1;
  std::vector<std::pair<std::string, RasterizedScene>> scenes;
  for (const SceneInfo& info : builtin_scenes())
    scenes.emplace_back(info.name, rasterize_scene(*builtin_scene(info.name), Viewport{96, 72, 24}));
  Progress progress(c, uint64_t(iters) * scenes.size() * pass_plans().size());
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    for (const auto& [sname, rs] : scenes)
      for (const PassPlan& plan : pass_plans()) {
        const bool ok = run_iteration("scenes", c, seed, t, [&](Cosim& cs) {
          cs.begin_frame(rs.viewport.width, rs.viewport.height, rs.viewport.depth_bits,
                         rs.background, rs.viewport.coverage_samples);
          for (const PassState& p : plan.passes) {
            for (const FrameOp& op : p.frame_ops) cs.frame_op(resolve_op(op, rs.background));
            draw_pass(cs, sname + "/" + plan.name + "/" + p.name, p.rop, pass_fragments(rs, p));
          }
          for (const FrameOp& op : plan.final_ops) cs.frame_op(resolve_op(op, rs.background));
        });
        if (!ok) return t;
        progress.add();
      }
  }
  return t;
}

// random: constrained-random states and streams, several passes per small frame; the first
// iteration adds every blend mode with every colour mask.
Tally suite_random(const Config& c) {
  Tally t;
  const uint64_t total = c.fragments ? c.fragments : 300000;
  const int iters = c.iterations ? c.iterations : std::max<int>(1, int(total / 6000));
  Progress progress(c, iters);
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
      for (unsigned b = 0; it == 0 && b < kBlendModes; ++b)
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

// hazard: long runs on 1-4 pixels, mixed with random ones, one tile; fragments per clock.
Tally suite_hazard(const Config& c) {
  Tally t;
  const uint64_t total = c.fragments ? c.fragments : 400000;
  const int iters = c.iterations ? c.iterations : 2;
  const size_t per_iter = std::max<uint64_t>(1, total / iters);
  uint64_t frags = 0, cycles = 0;
  double rtl_sec = 0;
  Progress progress(c, iters);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("hazard", c, seed, t, [&](Cosim& cs) {
      HazardStimulus stim(seed);
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{10, 20, 30, 40});
      const int passes = 4;
      for (int p = 0; p < passes; ++p) {
        const RopState st = stim.next_state();
        cs.label_pass("hazard-" + std::to_string(p + 1));
        cs.begin_pass(st);
        cs.draw(stim.next_fragments(per_iter / passes));
        const auto t0 = std::chrono::steady_clock::now();
        const PassStats s = cs.end_pass();  // the RTL simulation (the golden ran in draw)
        rtl_sec += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        frags += s.fragments_in;
        cycles += s.cycles;
      }
    });
    if (!ok) break;
    progress.add();
  }
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "fragments per clock %.4f (%llu fragments / %llu streaming cycles); RTL "
                "simulation %.3g fragments/s",
                cycles ? double(frags) / double(cycles) : 0.0, (unsigned long long)frags,
                (unsigned long long)cycles, rtl_sec > 0 ? double(frags) / rtl_sec : 0.0);
  t.note = buf;
  return t;
}

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

// window: directed streams for the issue window: one pixel filling it, two alternating, rings
// of 2..WINDOW+3 pixels, one pixel at gaps of 0..4; read-modify-write states.
Tally suite_window(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 8;
  const size_t per_pass = c.fragments ? std::max<uint64_t>(1, c.fragments / iters / 4) : 2000;
  Progress progress(c, iters);
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

// tiles: the tile planes' fast-clear bookkeeping. Passes from a menu that includes passes
// writing nothing at all (so a plane is fast-cleared twice with no store between) and
// accumulate passes (the accumulation plane), clears, peel copies and resolves between them, on one or two tiles, some passes touching one tile only; depths
// beside the last depth clear value; frames a few rows high or one or two tiles high.
Tally suite_tiles(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 12;
  Progress progress(c, iters);
  const uint32_t zmax = depth_max(24);
  Config reread = c;
  reread.reread_stores = true;  // and every store must leave the planes as they were
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("tiles", reread, seed, t, [&](Cosim& cs) {
      Rng r(seed ^ 0x5eed);
      const int w = kRtlTileW * (1 + int(r.below(2))) - int(r.below(3));
      // Short frames are cheap; tall ones (one or two tiles high) put every beat of a tile in
      // the frame, so a write-back to a wrong beat lands on a word that is compared.
      const bool tall = r.chance(0.5);
      const int h = tall ? kRtlTileH * (1 + int(r.below(2))) - int(r.below(3))
                         : 1 + int(r.below(uint32_t(std::min(kRtlTileH, 8))));
      const uint32_t row_odds = uint32_t(std::max(1, h / 8));  // about 8 rows of fragments
      cs.begin_frame(w, h, 24, Rgba8{1, 2, 3, 4});
      uint32_t zclear = zmax;  // the last depth clear value: a peel copy may carry it
      for (int p = 0; p < 8; ++p) {
        if (r.chance(0.4)) {
          zclear = r.chance(0.5) ? zmax : r.below(zmax);
          cs.frame_op({FrameOpKind::kClearDepth, {}, zclear, false});
        }
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kClearColor, {pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)}, 0, false});
        if (r.chance(0.2)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        if (r.chance(0.15)) cs.frame_op({FrameOpKind::kResolveWboit, {}, 0, false});
        RopState st;
        const uint32_t kind = r.below(7);
        if (kind >= 4 && r.chance(0.5)) {  // peel against a cleared plane: its clear value's bits
          zclear = r.below(zmax);
          cs.frame_op({FrameOpKind::kClearDepth, {}, zclear, false});
          cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        }
        static const char* kNames[] = {"write-all", "write-none", "read-blend", "coverage",
                                       "peel", "write-none-peel", "accumulate"};
        st.depth_test = kind != 0;
        st.depth_func = kind == 0 ? DepthFunc::kAlways : DepthFunc(1 + r.below(6));
        st.depth_write = kind == 0 || kind == 3 || (kind == 4 && r.chance(0.5));
        st.blend = kind == 0 ? BlendMode::kReplace : kind == 3 ? BlendMode::kCoverage
                 : kind == 1 || kind == 5 ? BlendMode::kReplace
                 : kind == 6 ? BlendMode::kAccumulate : BlendMode::kAlpha;
        st.color_mask = kind == 1 || kind == 5 ? 0 : kMaskRgba;
        st.peel_test = kind == 4 || kind == 5 || (kind == 6 && r.chance(0.3));
        const int xs = r.chance(0.3) ? std::min(w, kRtlTileW) : w;  // one tile only
        std::vector<Fragment> f;
        for (int y = 0; y < h; ++y) {
          if (r.below(row_odds) != 0) continue;
          for (int x = 0; x < xs; ++x) {
            Fragment g;
            g.x = uint16_t(x);
            g.y = uint16_t(y);
            // Depths beside the clear value too: a peel or depth test against a cleared word
            // then turns on its every bit (z = v or v + 1 tells v from v with one bit changed).
            if (r.chance(0.3))
              g.z = std::min(zmax, uint32_t(std::max<int64_t>(0, int64_t(zclear) - 1 + r.below(3))));
            else
              g.z = r.chance(0.2) ? (r.chance(0.5) ? 0 : zmax) : r.below(zmax + 1u);
            g.color = Rgba8{pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)};
            g.coverage = uint8_t(r.below(kRtlCoverageSamples + 1));
            g.prim = uint32_t(f.size() / 16);
            f.push_back(g);
          }
        }
        draw_pass(cs, std::string("tiles-") + kNames[kind], st, f);
      }
    });
    if (!ok) break;
    progress.add();
  }
  return t;
}

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

void blend_rgb(Cosim& cs, BlendMode mode, const char* tag, uint64_t count, Progress& progress) {
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
void blend_alpha_channel(Cosim& cs, BlendMode mode, const char* tag, Progress& progress) {
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
void blend_coverage_rgb(Cosim& cs, Progress& progress) {
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

// blend: the blend unit exhaustively, through the whole pipeline, for both modes that read the
// destination: all 2^24 (s, a, d) on R, G, B and all 2^16 (a, d) on A, for alpha and additive.
// --fragments N samples the R, G, B part instead (about N fragments in all; A stays whole).
Tally suite_blend(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 1;
  const uint64_t count = c.fragments ? std::max<uint64_t>(1, c.fragments / 4) : kBlendIndices;
  const uint64_t per_iteration = 2 * std::min(count, kBlendIndices) + 2 * kAlphaTotal + kCoverageTotal;
  Progress progress(c, iters * per_iteration);
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

const std::vector<Suite>& suites() {
  static const std::vector<Suite> kSuites = {
      {"scenes", "every built-in scene x every pass plan at 96x72", suite_scenes},
      {"random", "constrained-random states and streams, small frames, several passes",
       suite_random},
      {"hazard", "runs of fragments on 1-4 pixels mixed with random ones; fragments per clock",
       suite_hazard},
      {"window",
       "directed issue-window streams: one pixel filling it, two alternating, rings, gaps",
       suite_window},
      {"tiles",
       "fast-clear bookkeeping: passes that write nothing between clears, one or two tiles",
       suite_tiles},
      {"clears",
       "a store's last write-back meeting the next fast clear, then clears with no store "
       "between, probed at every pixel",
       suite_clears},
      {"accum",
       "accumulate passes (weighted blended OIT) with same-pixel fragments at issue distances "
       "4 to 7 (bypass, forwarding), runs and random ones; resolves between",
       suite_accum},
      {"blend",
       "alpha and additive over all 2^24 (s, a, d), 2^16 (a, d) on A; coverage over all "
       "(k, s, d)",
       suite_blend},
  };
  return kSuites;
}

const Suite* find_suite(const std::string& name) {
  for (const Suite& s : suites())
    if (name == s.name) return &s;
  return nullptr;
}

}  // namespace zb::tb
