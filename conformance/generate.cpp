#include "generate.h"

#include <algorithm>
#include <utility>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "reach.h"
#include "stimulus.h"

namespace zb::conformance {
namespace {

// Fixed seeds, one a family, so that a family's bytes never depend on another's draws.
constexpr uint64_t kStatesSeed = 61, kDepthBitsSeed = 62, kValuesSeed = 63, kCoverageSeed = 64,
                   kAccumSeed = 65, kTilesSeed = 66, kSamePixelSeed = 67, kLayersSeed = 68;
constexpr int kDraws = 4096;  // draws for one visible pixel before the generator gives up

const Rgba8 kClear{12, 34, 56, 78};

RopState state_of(bool test, DepthFunc f, bool write, BlendMode b, uint8_t mask, bool peel) {
  RopState s;
  s.depth_test = test;
  s.depth_func = f;
  s.depth_write = write;
  s.blend = b;
  s.color_mask = mask;
  s.peel_test = peel;
  return s;
}

// The setup pass: every listed pixel's depth and colour written as given (depth always, write,
// replace, every channel).
TracePass setup_pass(const std::string& name, std::vector<Fragment> frags) {
  return {name, {}, state_of(true, DepthFunc::kAlways, true, BlendMode::kReplace, kMaskRgba, false),
          std::move(frags)};
}

Trace frame(int w, int h, int depth_bits, int samples) {
  Trace t;
  t.width = w;
  t.height = h;
  t.depth_bits = depth_bits;
  t.coverage_samples = samples;
  t.clear_color = kClear;
  return t;
}

Fragment frag(int i, int w, uint32_t z, Rgba8 c, uint8_t cov = 0) {
  Fragment f;
  f.x = uint16_t(i % w);
  f.y = uint16_t(i / w);
  f.z = z;
  f.color = c;
  f.coverage = cov;
  return f;
}

Rgba8 random_color(tb::Rng& r) {
  return {uint8_t(r.below(256)), uint8_t(r.below(256)), uint8_t(r.below(256)),
          uint8_t(r.below(256))};
}

// Calls draw() until it takes what it drew (returns true), at most kDraws times: whether it did.
template <class Draw>
bool draw_until(Draw draw) {
  for (int k = 0; k < kDraws; ++k)
    if (draw()) return true;
  return false;
}

Rgba8 with_channel(Rgba8 c, int ch, uint8_t v) {
  (ch == 0 ? c.r : ch == 1 ? c.g : ch == 2 ? c.b : c.a) = v;
  return c;
}

int rows_for(int pixels, int w) { return (pixels + w - 1) / w; }

}  // namespace

Trace states_trace(BlendMode blend, bool peel, int depth_bits, int samples) {
  tb::Rng r(kStatesSeed * 16 + uint64_t(blend) * 2 + (peel ? 1 : 0));
  const uint32_t zmax = depth_max(depth_bits);
  std::vector<RopState> states;
  for (const RopState& s : pass_states())
    if (s.blend == blend && s.peel_test == peel) states.push_back(s);
  constexpr int kW = 48;
  const int pixels = int(states.size()) * 3;
  Trace t = frame(kW, rows_for(pixels, kW), depth_bits, samples);
  std::vector<Fragment> peels, stored;
  std::vector<TracePass> passes;
  for (size_t si = 0; si < states.size(); ++si) {
    TracePass pass{"state-" + std::to_string(si), {}, states[si], {}};
    for (int rel = 0; rel < 3; ++rel) {
      const int i = int(si) * 3 + rel;
      const bool found = draw_until([&] {
        StoredPixel sp;
        sp.depth = zmax / 4 + r.below(zmax / 2);
        sp.color = random_color(r);
        sp.reveal = wboit_reveal_one(t.wboit.rev_bits);
        const uint32_t delta = 1 + r.below(4096);
        Fragment f = frag(i, kW, rel == 0 ? sp.depth - delta : rel == 1 ? sp.depth : sp.depth + delta,
                          random_color(r), uint8_t(1 + r.below(uint32_t(std::max(1, samples - 1)))));
        if (!visible(states[si], f, sp, depth_bits, samples, t.wboit)) return false;
        // The peel plane: behind it (z > peel) where less or greater, not where equal.
        const uint32_t p = rel == 1 ? sp.depth + r.below(4096) : f.z - 1 - r.below(delta);
        peels.push_back(frag(i, kW, p, kClear));
        stored.push_back(frag(i, kW, sp.depth, sp.color));
        pass.fragments.push_back(f);
        return true;
      });
      if (!found)
        throw std::logic_error("conformance generator: no visible draw for state " +
                               std::to_string(si));
    }
    passes.push_back(std::move(pass));
  }
  if (peel) {
    t.passes.push_back(setup_pass("peel-values", peels));
    TracePass s = setup_pass("stored", stored);
    s.frame_ops.push_back({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
    t.passes.push_back(std::move(s));
  } else {
    t.passes.push_back(setup_pass("stored", stored));
  }
  for (TracePass& p : passes) t.passes.push_back(std::move(p));
  return t;
}

Trace depth_bits_trace(int depth_bits, int samples) {
  tb::Rng r(kDepthBitsSeed * 64 + uint64_t(depth_bits));
  const uint32_t zmax = depth_max(depth_bits);
  const DepthFunc funcs[] = {DepthFunc::kLess, DepthFunc::kLequal, DepthFunc::kGreater,
                             DepthFunc::kGequal, DepthFunc::kEqual, DepthFunc::kNotequal};
  constexpr int kW = 32;
  const uint32_t corners[] = {0, 1, zmax - 1, zmax};
  const int pixels = int(std::size(funcs)) * 2 * depth_bits + 3 * 16;
  Trace t = frame(kW, rows_for(pixels, kW), depth_bits, samples);
  std::vector<Fragment> stored;
  std::vector<TracePass> passes;
  int i = 0;
  // Fragment and stored colours that differ in every channel: a replace shows.
  auto pair = [&](uint32_t z, uint32_t d, TracePass& pass) {
    Rgba8 s = random_color(r), c = random_color(r);
    for (int k = 0; k < kDraws && (s.r == c.r || s.g == c.g || s.b == c.b || s.a == c.a); ++k)
      c = random_color(r);
    stored.push_back(frag(i, kW, d, s));
    pass.fragments.push_back(frag(i, kW, z, c));
    ++i;
  };
  for (DepthFunc f : funcs) {
    TracePass pass{std::string("bits-") + to_string(f), {},
                   state_of(true, f, true, BlendMode::kReplace, kMaskRgba, false), {}};
    for (int bit = 0; bit < depth_bits; ++bit)
      for (int below = 0; below < 2; ++below) {
        const uint32_t d = uint32_t(r.next()) & zmax;
        const uint32_t z = d ^ (uint32_t{1} << bit);
        pair(z, d, pass);
      }
    passes.push_back(std::move(pass));
  }
  for (DepthFunc f : {DepthFunc::kLess, DepthFunc::kEqual, DepthFunc::kGreater}) {
    TracePass pass{std::string("corners-") + to_string(f), {},
                   state_of(true, f, true, BlendMode::kReplace, kMaskRgba, false), {}};
    for (uint32_t z : corners)
      for (uint32_t d : corners) pair(z, d, pass);
    passes.push_back(std::move(pass));
  }
  t.passes.push_back(setup_pass("stored", stored));
  for (TracePass& p : passes) t.passes.push_back(std::move(p));
  return t;
}

Trace values_trace(BlendMode blend, int depth_bits, int samples) {
  tb::Rng r(kValuesSeed * 8 + uint64_t(blend));
  const uint8_t corners[] = {0, 1, 127, 128, 254, 255};
  constexpr int kW = 32;
  Trace t = frame(kW, rows_for(16 * 4 * int(std::size(corners)) + 4, kW), depth_bits, samples);
  std::vector<Fragment> stored;
  std::vector<TracePass> passes;
  int i = 0;
  const uint32_t z = depth_max(depth_bits) / 2;
  for (int m = 0; m < 16; ++m) {
    TracePass pass{"mask-" + std::to_string(m), {},
                   state_of(false, DepthFunc::kLess, false, blend, uint8_t(m), false), {}};
    for (int ch = 0; ch < 4; ++ch)
      for (uint8_t v : corners) {
        const bool found = draw_until([&] {
          const Rgba8 c = with_channel(random_color(r), ch, v);
          StoredPixel sp;
          sp.depth = z;
          sp.color = random_color(r);
          const Fragment f = frag(i, kW, z, c);
          if (!visible(pass.state, f, sp, depth_bits, samples, t.wboit)) return false;
          stored.push_back(frag(i, kW, z, sp.color));
          pass.fragments.push_back(f);
          return true;
        });
        // A corner no draw can show in this blend (alpha 0 leaves an alpha blend's pixel as it
        // was): the fragment is still sent, onto a pixel drawn at random.
        if (!found) {
          const Rgba8 c = with_channel(random_color(r), ch, v);
          stored.push_back(frag(i, kW, z, random_color(r)));
          pass.fragments.push_back(frag(i, kW, z, c));
        }
        ++i;
      }
    passes.push_back(std::move(pass));
  }
  // Every channel of source and destination at 0 and at 255 together: the blend's own zero
  // and full results (an additive blend writes 0 only from 0 onto 0).
  TracePass ends{"ends", {}, state_of(false, DepthFunc::kLess, false, blend, kMaskRgba, false), {}};
  for (uint8_t sv : {0, 255})
    for (uint8_t dv : {0, 255}) {
      stored.push_back(frag(i, kW, z, Rgba8{dv, dv, dv, dv}));
      ends.fragments.push_back(frag(i, kW, z, Rgba8{sv, sv, sv, sv}));
      ++i;
    }
  passes.push_back(std::move(ends));
  t.passes.push_back(setup_pass("stored", stored));
  for (TracePass& p : passes) t.passes.push_back(std::move(p));
  return t;
}

Trace coverage_values_trace(int depth_bits, int samples) {
  tb::Rng r(kCoverageSeed * 64 + uint64_t(samples));
  const int corners[] = {0, 1, samples - 1, samples};
  constexpr int kW = 16;
  Trace t = frame(kW, rows_for(3 * 16, kW), depth_bits, samples);
  const uint32_t zmax = depth_max(depth_bits);
  const RopState cov = state_of(true, DepthFunc::kLess, true, BlendMode::kCoverage, kMaskRgba, false);
  std::vector<Fragment> stored;
  TracePass counts{"stored-coverage", {}, cov, {}}, test{"coverage-corners", {}, cov, {}};
  int i = 0;
  for (int rel = 0; rel < 3; ++rel)
    for (int k : corners)
      for (int cs : corners) {
        const uint32_t d = zmax / 4 + r.below(zmax / 2), delta = 1 + r.below(4096);
        stored.push_back(frag(i, kW, d, random_color(r)));
        // Onto an empty pixel at its own depth: the coverage plane takes cs, the depth stays.
        counts.fragments.push_back(frag(i, kW, d, random_color(r), uint8_t(cs)));
        test.fragments.push_back(frag(i, kW, rel == 0 ? d - delta : rel == 1 ? d : d + delta,
                                      random_color(r), uint8_t(k)));
        ++i;
      }
  t.passes.push_back(setup_pass("stored", stored));
  t.passes.push_back(std::move(counts));
  t.passes.push_back(std::move(test));
  return t;
}

Trace accumulate_values_trace(int depth_bits, int samples) {
  tb::Rng r(kAccumSeed);
  constexpr int kW = 16;
  Trace t = frame(kW, 4, depth_bits, samples);
  const RopState acc = state_of(false, DepthFunc::kLess, false, BlendMode::kAccumulate, kMaskRgba, false);
  TracePass pass{"accumulate", {}, acc, {}};
  // Pixels 0 to 3: one channel each at 255 near the eye, many times over: its sum saturates.
  for (int round = 0; round < 48; ++round)
    for (int ch = 0; ch < 4; ++ch) {
      Rgba8 c{0, 0, 0, 255};
      if (ch < 3) (ch == 0 ? c.r : ch == 1 ? c.g : c.b) = 255;
      pass.fragments.push_back(frag(ch, kW, r.below(16), c));
    }
  // The others: alpha at its corners, depths across the range.
  const uint8_t alphas[] = {0, 1, 127, 128, 254, 255};
  for (int i = 4; i < kW * 4; ++i) {
    Rgba8 c = random_color(r);
    c.a = alphas[r.below(6)];
    pass.fragments.push_back(frag(i, kW, uint32_t(r.next()) & depth_max(depth_bits), c));
  }
  t.passes.push_back(std::move(pass));
  t.final_ops.push_back({FrameOpKind::kResolveWboit, {}, 0, false});
  return t;
}

Trace tiles_trace(int depth_bits, int samples) {
  tb::Rng r(kTilesSeed);
  constexpr int kSize = 192;  // whole tiles of 16, 32 and 64, at least three each way
  Trace t = frame(kSize, kSize, depth_bits, samples);
  std::vector<Fragment> frags;
  for (int tile : {16, 32, 64})
    for (int y0 = 0; y0 < kSize; y0 += tile)
      for (int x0 = 0; x0 < kSize; x0 += tile)
        for (int ly : {0, tile / 2, tile - 1})
          for (int lx : {0, tile / 2 - 1, tile - 1}) {
            Fragment f;
            f.x = uint16_t(x0 + lx);
            f.y = uint16_t(y0 + ly);
            f.z = uint32_t(r.next()) & depth_max(depth_bits);
            f.color = random_color(r);
            frags.push_back(f);
          }
  t.passes.push_back({"tiles-replace", {},
                      state_of(true, DepthFunc::kLess, true, BlendMode::kReplace, kMaskRgba, false),
                      frags});
  for (Fragment& f : frags) {
    f.z = uint32_t(r.next()) & depth_max(depth_bits);
    f.color = random_color(r);
  }
  t.passes.push_back({"tiles-alpha", {},
                      state_of(true, DepthFunc::kLequal, false, BlendMode::kAlpha, kMaskRgba, false),
                      std::move(frags)});
  return t;
}

Trace same_pixel_trace(BlendMode blend, int depth_bits, int samples) {
  tb::Rng r(kSamePixelSeed * 8 + uint64_t(blend));
  constexpr int kW = 16, kRounds = 3, kMaxRun = 16;
  Trace t = frame(kW, kW, depth_bits, samples);
  const uint32_t zmax = depth_max(depth_bits);
  const bool coverage = blend == BlendMode::kCoverage;
  // Depth tested and written where the blend allows it, so the depth plane's hazard is in play.
  RopState s = state_of(coverage, coverage ? DepthFunc::kLess : DepthFunc::kAlways, coverage,
                        blend, kMaskRgba, false);
  if (blend == BlendMode::kLayers) s.layers = 2;  // each pixel takes three: every one merges
  TracePass pass{std::string("runs-") + to_string(blend), {}, s, {}};
  TracePass depth{"runs-depth", {},
                  state_of(true, DepthFunc::kLequal, true, BlendMode::kReplace, kMaskRgba, false), {}};
  int base = 0;
  for (int k = 1; k <= kMaxRun; ++k) {
    for (int round = 0; round < kRounds; ++round)
      for (int j = 0; j < k; ++j) {
        Rgba8 c = random_color(r);
        c.a = uint8_t(64 + r.below(128));
        pass.fragments.push_back(frag(base + j, kW, zmax / 2 - uint32_t(round) * 16 - r.below(8), c,
                                      uint8_t(1 + r.below(uint32_t(std::max(1, samples - 1))))));
        depth.fragments.push_back(frag(base + j, kW, zmax / 2 - uint32_t(round) * 16 - r.below(8),
                                       random_color(r)));
      }
    base += k;
  }
  t.passes.push_back(std::move(pass));
  if (blend == BlendMode::kAlpha) t.passes.push_back(std::move(depth));
  if (blend == BlendMode::kAccumulate) t.final_ops.push_back({FrameOpKind::kResolveWboit, {}, 0, false});
  if (blend == BlendMode::kLayers) t.final_ops.push_back({FrameOpKind::kResolveLayers, {}, 0, false});
  return t;
}

Trace layers_trace(int depth_bits, int samples) {
  tb::Rng r(kLayersSeed);
  constexpr int kW = 192, kH = 64;  // whole tiles of 16, 32 and 64: layers on every tile
  constexpr int kStride = 37;       // case i on pixel 37 i: every tile of every size gets some
  Trace t = frame(kW, kH, depth_bits, samples);
  const uint32_t zmax = depth_max(depth_bits);
  const uint32_t step = std::max<uint32_t>(4, zmax >> 6);  // between a case's layers
  const uint32_t base = zmax >> 3;
  int next = 0;
  auto pixel = [&] {
    const int i = next++ * kStride % (kW * kH);
    return std::pair<uint16_t, uint16_t>{uint16_t(i % kW), uint16_t(i / kW)};
  };
  auto layer_color = [&](uint8_t a) {
    Rgba8 c = random_color(r);
    c.a = a;
    return c;
  };
  auto put = [&](TracePass& p, std::pair<uint16_t, uint16_t> px, uint32_t z, Rgba8 c) {
    Fragment f;
    f.x = px.first;
    f.y = px.second;
    f.z = std::min(z, zmax - 1);
    f.color = c;
    p.fragments.push_back(f);
  };
  // Opaque surfaces on some pixels (depth written): the layers behind them are killed.
  TracePass opaque = setup_pass("opaque", {});
  auto layers_pass = [&](const std::string& name, int k, DepthFunc func, bool write, uint8_t mask) {
    RopState s = state_of(true, func, write, BlendMode::kLayers, mask, false);
    s.layers = uint8_t(k);
    return TracePass{name, {}, s, {}};
  };
  std::vector<TracePass> passes;
  for (int k = 1; k <= kKitLayers; ++k) {
    TracePass p = layers_pass(fmt::format("layers-k{}", k), k, DepthFunc::kLess, false, kMaskRgba);
    // Every position 0..n among n = 0..K layers: full when n = K (the merge at each place).
    for (int rep = 0; rep < 3; ++rep)
      for (int n = 0; n <= k; ++n)
        for (int pos = 0; pos <= n; ++pos) {
          const auto px = pixel();
          for (int j = 0; j < n; ++j)
            put(p, px, base + step * uint32_t(2 * j + 2), layer_color(uint8_t(40 + r.below(215))));
          put(p, px, base + step * uint32_t(2 * pos + 1), layer_color(uint8_t(40 + r.below(215))));
        }
    // Equal depths: a fragment at a layer's depth with a smaller and a larger colour word, and
    // one with the same key, after n layers (full or not).
    for (int n = 1; n <= k; ++n)
      for (int j = 0; j < n; ++j)
        for (int which = 0; which < 3; ++which) {
          const auto px = pixel();
          std::vector<Rgba8> cs;
          for (int i = 0; i < n; ++i) cs.push_back(layer_color(uint8_t(60 + r.below(150))));
          for (int i = 0; i < n; ++i) put(p, px, base + step * uint32_t(i + 1), cs[size_t(i)]);
          Rgba8 c = cs[size_t(j)];
          if (which == 0) c.a = uint8_t(c.a - 1 - r.below(20));
          if (which == 1) c.a = uint8_t(c.a + 1 + r.below(20));
          put(p, px, base + step * uint32_t(j + 1), c);
        }
    // The same fragments in every order (two at equal depth): at most K, the layers are the
    // same whatever the order; one more and the merge shows the order.
    for (int extra = 0; extra < 2; ++extra) {
      const int n = std::min(k, 3) + extra;
      std::vector<std::pair<uint32_t, Rgba8>> set;
      for (int i = 0; i < n; ++i)
        set.push_back({base + step * uint32_t(i == 1 ? 1 : i + 1), layer_color(uint8_t(50 + r.below(200)))});
      std::vector<int> order(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i) order[size_t(i)] = i;
      do {
        const auto px = pixel();
        for (int i : order) put(p, px, set[size_t(i)].first, set[size_t(i)].second);
      } while (std::next_permutation(order.begin(), order.end()));
    }
    // Long runs: merges on merges, random depths and alphas (high ones saturate the resolve's
    // coverage of the pixel), alpha 0 among them.
    for (int run = 0; run < 8; ++run) {
      const auto px = pixel();
      const int len = 5 + int(r.below(10));
      for (int i = 0; i < len; ++i) {
        const uint8_t a = run < 2 ? uint8_t(230 + r.below(26)) : r.chance(0.15) ? 0 : uint8_t(1 + r.below(255));
        put(p, px, base + r.below(step * 16), layer_color(a));
      }
    }
    // Behind an opaque surface (killed) and in front of it, with alpha 0 on an empty pixel.
    for (int i = 0; i < 4; ++i) {
      const auto px = pixel();
      put(opaque, px, base + step * 3, layer_color(255));
      put(p, px, base + step * 2, layer_color(uint8_t(100 + r.below(100))));
      put(p, px, base + step * 4, layer_color(uint8_t(100 + r.below(100))));
      put(p, px, base + step * 3, layer_color(uint8_t(100 + r.below(100))));
    }
    put(p, pixel(), base + step, layer_color(0));
    passes.push_back(std::move(p));
  }
  // Pass states beside the method's: the mask 0 (no access) and a partial mask (the whole word),
  // depth written in layers mode (lequal: a later fragment behind it is killed), the test off.
  TracePass masked = layers_pass("layers-mask0", 2, DepthFunc::kLess, false, 0);
  TracePass partial = layers_pass("layers-mask-r", 3, DepthFunc::kLequal, true, 1);
  TracePass off = layers_pass("layers-test-off", 4, DepthFunc::kNever, false, kMaskRgba);
  off.state.depth_test = false;
  for (TracePass* p : {&masked, &partial, &off})
    for (int i = 0; i < 12; ++i) {
      const auto px = pixel();
      for (int j = 0; j < 3 + int(r.below(3)); ++j)
        put(*p, px, base + r.below(step * 8), layer_color(uint8_t(1 + r.below(255))));
    }
  passes.push_back(std::move(masked));
  passes.push_back(std::move(partial));
  passes.push_back(std::move(off));
  // The opaque pass first; each layers pass resolved before the next.
  t.passes.push_back(std::move(opaque));
  for (TracePass& p : passes) {
    if (t.passes.size() > 1) p.frame_ops.push_back({FrameOpKind::kResolveLayers, {}, 0, false});
    t.passes.push_back(std::move(p));
  }
  t.final_ops.push_back({FrameOpKind::kResolveLayers, {}, 0, false});
  return t;
}

}  // namespace zb::conformance
