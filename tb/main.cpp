// zblend_tb: the Verilator testbench. Named suites run the golden model and the RTL in
// lockstep (zb::Cosim) and compare every colour and depth bit after every pass.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cosim.h"
#include "fixed.h"
#include "passes.h"
#include "render.h"
#include "scenes.h"
#include "trace.h"

namespace {

using namespace zb;

struct Config {
  uint64_t seed = 1;
  int iterations = 0;        // 0: the suite's default
  uint64_t fragments = 0;    // 0: the suite's default scale
  double backpressure = 0;
  std::string trace;         // whole-run FST
  std::string mismatch_fst = "out/mismatch.fst";
  bool verbose = false;
};

struct Tally {
  uint64_t iterations = 0, fragments = 0, pixels = 0, mismatches = 0;
  uint64_t stream_cycles = 0, io_cycles = 0;
  bool failed = false;
  std::string note;
};

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

CosimOptions cosim_options(const Config& c, uint64_t seed) {
  CosimOptions o;
  o.rtl.backpressure = c.backpressure;
  o.rtl.seed = seed;
  o.rtl.trace_path = c.trace;
  o.mismatch_fst = c.mismatch_fst;
  return o;
}

// Runs one iteration's body on a fresh Cosim; folds its counts into `t`. Returns false on a
// mismatch (the report is printed) so the suite stops.
bool run_iteration(const char* suite, const Config& c, uint64_t seed, Tally& t,
                   const std::function<void(Cosim&)>& body) {
  Cosim cosim(cosim_options(c, seed));
  bool ok = true;
  try {
    body(cosim);
  } catch (const MismatchError& e) {
    std::printf("%s", e.what());
    std::printf("FAIL suite %s iteration seed %llu: replay with --suite %s --seed %llu "
                "--iterations 1%s\n",
                suite, (unsigned long long)seed, suite, (unsigned long long)seed,
                c.backpressure > 0 ? (" --backpressure " + std::to_string(c.backpressure)).c_str()
                                   : "");
    t.failed = true;
    ok = false;
    if (cosim.mismatches() == 0) ++t.mismatches;  // a counter mismatch
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
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    for (const auto& [sname, rs] : scenes)
      for (const PassPlan& plan : pass_plans()) {
        const bool ok = run_iteration("scenes", c, seed, t, [&](Cosim& cs) {
          cs.begin_frame(rs.viewport.width, rs.viewport.height, rs.viewport.depth_bits,
                         rs.background);
          for (const PassState& p : plan.passes)
            draw_pass(cs, sname + "/" + plan.name + "/" + p.name, p.rop, pass_fragments(rs, p));
        });
        if (!ok) return t;
      }
  }
  return t;
}

RopState random_state(Rng& r) {
  RopState s;
  s.depth_test = !r.chance(0.15);
  s.depth_func = DepthFunc(r.below(8));
  s.depth_write = r.chance(0.6);
  s.blend = BlendMode(r.below(3));
  const uint32_t m = r.below(4);
  s.color_mask = m == 0 ? uint8_t(r.below(16)) : uint8_t(kMaskRgba);
  return s;
}

uint8_t pick_alpha(Rng& r) {
  static const uint8_t special[] = {0, 1, 254, 255};
  return r.chance(0.5) ? special[r.below(4)] : uint8_t(r.below(256));
}

uint8_t pick_channel(Rng& r) {
  return r.chance(0.2) ? (r.chance(0.5) ? 0 : 255) : uint8_t(r.below(256));
}

// A random stream of `n` fragments on a w x h frame; `hot` > 0 makes runs on 1..hot pixels.
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
      for (int i = 0; i < k; ++i)  // neighbours, so the hot pixels share a tile mostly
        spots.emplace_back(uint16_t(std::min(w - 1, bx + int(r.below(3)))),
                           uint16_t(std::min(h - 1, by + int(r.below(2)))));
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
    f.prim = uint32_t(out.size() / 16);
    out.push_back(f);
  }
  return out;
}

// random: constrained-random states and streams, several passes per small frame.
Tally suite_random(const Config& c) {
  Tally t;
  const uint64_t total = c.fragments ? c.fragments : 300000;
  const int iters = c.iterations ? c.iterations : std::max<int>(1, int(total / 6000));
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
        const RopState st = random_state(r);
        draw_pass(cs, "random-" + std::to_string(p + 1), st,
                  random_stream(r, w, h, per_pass, 4, 0.3, zpool));
      }
    });
    if (!ok) break;
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
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("hazard", c, seed, t, [&](Cosim& cs) {
      Rng r(seed);
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{10, 20, 30, 40});
      std::vector<uint32_t> zpool(4);
      for (uint32_t& z : zpool) z = r.below(depth_max(24));
      const int passes = 4;
      for (int p = 0; p < passes; ++p) {
        RopState st = random_state(r);
        // Mostly states where back-to-back fragments change the pixel: the RMW path.
        if (r.chance(0.7)) {
          static const DepthFunc busy[] = {DepthFunc::kAlways, DepthFunc::kLequal,
                                           DepthFunc::kGequal, DepthFunc::kNotequal};
          st.depth_func = busy[r.below(4)];
          st.blend = r.chance(0.5) ? BlendMode::kAlpha : BlendMode::kAdditive;
        }
        cs.label_pass("hazard-" + std::to_string(p + 1));
        cs.begin_pass(st);
        cs.draw(random_stream(r, kRtlTileW, kRtlTileH, per_iter / passes, 4, 0.9, zpool));
        const auto t0 = std::chrono::steady_clock::now();
        const PassStats s = cs.end_pass();  // the RTL simulation (the golden ran in draw)
        rtl_sec += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        frags += s.fragments_in;
        cycles += s.cycles;
      }
    });
    if (!ok) break;
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

// blend: all 2^24 (s, a, d) of the alpha blend through the whole pipeline. Per pixel, a
// fragment with alpha 255 first sets the destination (m(x, 255) = x, m(d, 0) = 0: a replace),
// then the fragment under test blends onto it; each pixel is tested once per pass, and the
// R, G and B channels carry three triples (d split in thirds). The A channel sees only
// d = 255 here; the random suite covers it.
Tally suite_blend(const Config& c) {
  Tally t;
  constexpr int kW = kRtlTileW, kH = kRtlTileH, kPix = kW * kH;
  const int iters = c.iterations ? c.iterations : 1;
  for (int it = 0; it < iters; ++it) {
    const bool ok = run_iteration("blend", c, c.seed + it, t, [&](Cosim& cs) {
      cs.begin_frame(kW, kH, 24, Rgba8{0, 0, 0, 0});
      RopState st;
      st.depth_test = false;
      st.blend = BlendMode::kAlpha;
      std::vector<Fragment> f;
      f.reserve(2 * kPix);
      // Enumerate (a, s, d) with d in [0, 86) for R, +86 for G, +172 for B (clamped).
      uint64_t idx = 0;
      const uint64_t total = 256ull * 256 * 86;
      int pass = 0;
      while (idx < total) {
        f.clear();
        for (int base = 0; base < kPix && idx < total; base += 8) {
          const int n = int(std::min<uint64_t>(8, std::min<uint64_t>(kPix - base, total - idx)));
          for (int k = 0; k < n; ++k) {  // preload the destinations
            const uint64_t v = idx + k;
            const uint8_t d = uint8_t(v % 86);
            Fragment p;
            p.x = uint16_t((base + k) % kW);
            p.y = uint16_t((base + k) / kW);
            p.color = Rgba8{d, uint8_t(std::min(255, d + 86)), uint8_t(std::min(255, d + 172)), 255};
            f.push_back(p);
          }
          for (int k = 0; k < n; ++k) {  // the blends under test
            const uint64_t v = idx + k;
            const uint8_t s = uint8_t(v / 86 % 256), a = uint8_t(v / (86 * 256));
            Fragment b;
            b.x = uint16_t((base + k) % kW);
            b.y = uint16_t((base + k) / kW);
            b.color = Rgba8{s, uint8_t(255 - s), uint8_t(s ^ 0x5a), a};
            f.push_back(b);
          }
          idx += uint64_t(n);
        }
        draw_pass(cs, "blend-" + std::to_string(++pass), st, f);
      }
    });
    if (!ok) break;
  }
  t.note = "2^24 (s, a, d) alpha-blend triples per iteration, R/G/B channels";
  return t;
}

struct Suite {
  const char* name;
  const char* about;
  Tally (*run)(const Config&);
};

const Suite kSuites[] = {
    {"scenes", "every built-in scene x every pass plan at 96x72", suite_scenes},
    {"random", "constrained-random states and streams, small frames, several passes", suite_random},
    {"hazard", "runs of fragments on 1-4 pixels mixed with random ones; fragments per clock",
     suite_hazard},
    {"blend", "the alpha blend over all 2^24 (s, a, d) through the pipeline", suite_blend},
};

}  // namespace

int main(int argc, char** argv) {
  // Verilator-style plusargs: +trace dumps the whole run to out/tb_trace.fst.
  std::vector<std::string> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "+trace") {
      args.emplace_back("--trace");
      args.emplace_back("out/tb_trace.fst");
    } else {
      args.push_back(a);
    }
  }
  std::vector<const char*> cargv;
  for (const std::string& a : args) cargv.push_back(a.c_str());

  Config c;
  std::vector<std::string> suites;
  std::string replay;
  bool list = false;
  CLI::App app{"zblend_tb: the RTL (Verilated zb_rop) against the golden model, bit for bit"};
  app.add_option("--suite", suites, "suite(s) to run, repeatable or comma-separated (default all)")
      ->delimiter(',');
  app.add_flag("--list-suites", list, "list the suites and exit");
  app.add_option("--seed", c.seed, "base seed; iteration i uses seed+i (printed on failure)");
  app.add_option("--iterations", c.iterations, "iterations per suite (default: the suite's)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--fragments", c.fragments, "scale: about this many fragments (random, hazard)");
  app.add_option("--backpressure", c.backpressure, "probability of stall and of a valid gap")
      ->check(CLI::Range(0.0, 0.95));
  app.add_option("--trace", c.trace, "FST of the whole run (also +trace)");
  app.add_option("--mismatch-fst", c.mismatch_fst, "FST written around the first mismatch");
  app.add_option("--replay", replay, "replay a trace file (zblend trace) through the cosim");
  app.add_flag("-v,--verbose", c.verbose, "one line per iteration");
  try {
    app.parse(int(cargv.size()), cargv.data());
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  if (list) {
    for (const Suite& s : kSuites) std::printf("%-8s %s\n", s.name, s.about);
    return 0;
  }

  if (!replay.empty()) {
    try {
      const Trace tr = read_trace(replay);
      Cosim cs(cosim_options(c, c.seed));
      cs.begin_frame(tr.width, tr.height, tr.depth_bits, tr.clear_color);
      for (const TracePass& p : tr.passes) draw_pass(cs, p.name, p.state, p.fragments);
      std::printf("replay %s: %llu passes, %llu fragments, %llu pixels compared, 0 mismatches\n",
                  replay.c_str(), (unsigned long long)cs.passes(),
                  (unsigned long long)cs.fragments(), (unsigned long long)cs.pixels_compared());
      const std::string w = cs.nothing_checked_warning();
      if (!w.empty()) {
        std::printf("%s\n", w.c_str());
        return 1;
      }
      return 0;
    } catch (const MismatchError& e) {
      std::printf("%sreplay %s: FAILED\n", e.what(), replay.c_str());
      return 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "zblend_tb: %s\n", e.what());
      return 2;
    }
  }

  std::vector<const Suite*> chosen;
  if (suites.empty()) {
    for (const Suite& s : kSuites) chosen.push_back(&s);
  } else {
    for (const std::string& n : suites) {
      const Suite* found = nullptr;
      for (const Suite& s : kSuites)
        if (n == s.name) found = &s;
      if (!found) {
        std::fprintf(stderr, "zblend_tb: unknown suite '%s' (see --list-suites)\n", n.c_str());
        return 2;
      }
      chosen.push_back(found);
    }
  }

  int passed = 0, failed = 0;
  for (const Suite* s : chosen) {
    const auto t0 = std::chrono::steady_clock::now();
    Tally t;
    try {
      t = s->run(c);
    } catch (const std::exception& e) {
      std::printf("suite %s: error: %s\n", s->name, e.what());
      t.failed = true;
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool nothing = t.fragments == 0 || t.pixels == 0;
    if (nothing) std::printf("warning: suite %s checked nothing\n", s->name);
    const bool ok = !t.failed && !nothing;
    std::printf("suite %-7s %s  iterations %llu  fragments %llu  pixels compared %llu  "
                "mismatches %llu  %.2f s  %.3g fragments/s (cosim)  cycles %llu stream + %llu "
                "tile io\n",
                s->name, ok ? "PASS" : "FAIL", (unsigned long long)t.iterations,
                (unsigned long long)t.fragments, (unsigned long long)t.pixels,
                (unsigned long long)t.mismatches, sec, sec > 0 ? double(t.fragments) / sec : 0.0,
                (unsigned long long)t.stream_cycles, (unsigned long long)t.io_cycles);
    if (!t.note.empty()) std::printf("  %s: %s\n", s->name, t.note.c_str());
    std::fflush(stdout);
    (ok ? passed : failed)++;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
