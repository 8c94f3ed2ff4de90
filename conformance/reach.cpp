#include "reach.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <deque>
#include <set>

#include <fmt/core.h>

#include "parallel/parallel.h"
#include "rop/blend.h"
#include "rop/layers.h"
#include "rop/rop.h"
#include "generate.h"
#include "suite.h"

namespace zb::conformance {
namespace {

const char* const kRelations[] = {"less", "equal", "greater"};
const char* const kChannels[] = {"r", "g", "b", "a"};
const char* const kBands[] = {"top", "inside", "bottom"};
const char* const kColBands[] = {"left", "inside", "right"};
const char* const kPlaneNames[] = {"colour", "depth", "coverage", "peel", "accum"};
const char* const kOrigins[] = {"first", "row", "column", "inner"};
constexpr uint8_t kChannelCorners[] = {0, 1, 127, 128, 254, 255};
constexpr int kGoalTiles[] = {16, 32, 64};
constexpr int kGoalDepthBits[] = {16, 24, 32};
constexpr int kGoalSamples[] = {4, 16};
constexpr int kRunDistances = 16;  // same-pixel runs under read-modify-write blends
const BlendMode kRmwBlends[] = {BlendMode::kAlpha, BlendMode::kAdditive, BlendMode::kCoverage,
                                BlendMode::kUnder, BlendMode::kAccumulate, BlendMode::kLayers};

int relation(uint32_t z, uint32_t stored) { return z < stored ? 0 : z == stored ? 1 : 2; }

uint8_t channel(Rgba8 c, int k) { return k == 0 ? c.r : k == 1 ? c.g : k == 2 ? c.b : c.a; }

// 0 at the first row or column, 2 at the last, 1 between (the plan's bands).
int band(int local, int size) { return local == 0 ? 0 : local == size - 1 ? 2 : 1; }

int origin_kind(int x0, int y0) { return x0 == 0 ? (y0 == 0 ? 0 : 2) : (y0 == 0 ? 1 : 3); }

std::string state_dims(const RopState& s) {
  return fmt::format("depth={},write={},blend={},mask={:x},peel={}",
                     s.depth_test ? to_string(s.depth_func) : "off", s.depth_write ? 1 : 0,
                     to_string(s.blend), s.color_mask & 15, s.peel_test ? 1 : 0);
}

std::string corner_name(uint32_t z, uint32_t zmax) {
  return z == 0 ? "zero" : z == 1 ? "one" : z == zmax ? "max" : "max_minus_1";
}

bool is_rmw(BlendMode b) {
  return std::find(std::begin(kRmwBlends), std::end(kRmwBlends), b) != std::end(kRmwBlends);
}

// The testbench's fragment order (zb_conf_tb): pass by pass, each tile a pass touches in raster
// order, its fragments in stream order; with the resident schedule, the passes up to the next
// frame operation tile by tile instead, each pass's fragments for the tile in turn. Calls
// visit(pass, fragment index, tile x0, y0, first of its pass on the tile, first since the load).
template <class Visit>
void tb_order(const Trace& t, const DutShape& shape, Visit visit) {
  auto in_tile = [&](const Fragment& f, int x0, int y0) {
    return f.x >= x0 && f.x < x0 + shape.tile_w && f.y >= y0 && f.y < y0 + shape.tile_h;
  };
  auto touches = [&](size_t p, int x0, int y0) {
    const std::vector<Fragment>& frags = t.passes[p].fragments;
    return std::any_of(frags.begin(), frags.end(),
                       [&](const Fragment& f) { return in_tile(f, x0, y0); });
  };
  auto run = [&](size_t p, int x0, int y0, bool& loaded) {
    bool first = true;
    const std::vector<Fragment>& frags = t.passes[p].fragments;
    for (size_t i = 0; i < frags.size(); ++i) {
      if (!in_tile(frags[i], x0, y0)) continue;
      visit(p, i, x0, y0, first, !loaded);
      first = false;
      loaded = true;
    }
  };
  for (size_t begin = 0; begin < t.passes.size();) {
    size_t end = begin + 1;
    if (shape.resident)
      while (end < t.passes.size() && t.passes[end].frame_ops.empty()) ++end;
    for (int y0 = 0; y0 < t.height; y0 += shape.tile_h)
      for (int x0 = 0; x0 < t.width; x0 += shape.tile_w) {
        bool loaded = false;
        for (size_t p = begin; p < end; ++p)
          if (touches(p, x0, y0)) run(p, x0, y0, loaded);
      }
    begin = end;
  }
}

// A layers write's bins, as zb_layers_insert's covers sample it (at X11, with the pixel's
// layers before it): where it went and whether the pixel was full, equal depths and keys, K at
// a merge; alpha 0 writes the word back unchanged.
void count_layers(BinCounts& bins, int k, const PixelLayers& px, const Layer& f) {
  if (f.p.a == 0) {
    ++bins["layers_cases.alpha_zero"];
    return;
  }
  const bool full = px.n == k;
  ++bins[fmt::format("layers_insert[position={},full={}]", layer_position(px, f),
                     full ? "yes" : "no")];
  if (full) {
    ++bins[fmt::format("layers_k[k={}]", k)];
    ++bins["layers_cases.merge"];
  }
  bool eq_z = false, eq_key = false;
  for (int j = 0; j < px.n; ++j) {
    eq_z |= px.layer[size_t(j)].z == f.z;
    eq_key |= px.layer[size_t(j)] == f;
  }
  if (eq_key) ++bins["layers_cases.equal_key"];
  else if (eq_z) ++bins["layers_cases.equal_depth"];
}

// Whether a store resolves the layers (st_resolve_i): a resolve of the layers right after a
// group of passes (the testbench's: one pass, or on resident tiles those since the last frame
// operation) in which some fragment loaded a tile.
bool resolves_layers(const Trace& t, const DutShape& shape) {
  auto resolve_in = [](const std::vector<FrameOp>& ops) {
    return !ops.empty() && ops.front().kind == FrameOpKind::kResolveLayers;
  };
  for (size_t p = 0; p < t.passes.size(); ++p) {
    const bool last = p + 1 == t.passes.size();
    if (!resolve_in(last ? t.final_ops : t.passes[p + 1].frame_ops)) continue;
    for (size_t g = p + 1; g-- > 0;) {
      if (!t.passes[g].fragments.empty()) return true;
      if (!shape.resident || !t.passes[g].frame_ops.empty()) break;
    }
  }
  return false;
}

}  // namespace

std::vector<RopState> pass_states() {
  std::vector<RopState> out;
  for (int d = 0; d < 9; ++d)  // off, then each function
    for (int w = 0; w < 2; ++w)
      for (unsigned b = 0; b < kCoreBlendModes; ++b)
        for (int m = 0; m < 16; ++m)
          for (int p = 0; p < 2; ++p) {
            RopState s;
            s.depth_test = d > 0;
            s.depth_func = d > 0 ? DepthFunc(d - 1) : DepthFunc::kLess;
            s.depth_write = w != 0;
            s.blend = BlendMode(b);
            s.color_mask = uint8_t(m);
            s.peel_test = p != 0;
            out.push_back(s);
          }
  return out;
}

bool visible(const RopState& state, const Fragment& f, const StoredPixel& p, int depth_bits,
             int samples, const WboitFormat& wboit) {
  switch (state.blend) {
    case BlendMode::kAccumulate: {
      const WboitPixel w = accumulate_wboit(f.z, f.color, p.acc, p.reveal, depth_bits, wboit);
      for (int c = 0; c < 4; ++c)
        if (w.acc[size_t(c)] == p.acc[size_t(c)]) return false;
      return w.reveal != p.reveal;
    }
    case BlendMode::kLayers:  // no pass-state goal: the layers' own bins below
      return false;
    case BlendMode::kCoverage: {
      const CoveragePixel c = composite_coverage(f.z, f.color, f.coverage, p.depth, p.color,
                                                 p.coverage, samples);
      for (int k = 0; k < 4; ++k)
        if (channel(c.color, k) == channel(p.color, k)) return false;
      return true;
    }
    default: {
      const Rgba8 b = blend(state.blend, f.color, p.color);
      bool differs_from_source = state.blend == BlendMode::kReplace;
      for (int k = 0; k < 4; ++k) {
        if (channel(b, k) == channel(p.color, k)) return false;
        differs_from_source |= channel(b, k) != channel(f.color, k);
      }
      return differs_from_source;
    }
  }
}

BinCounts trace_reach(const Trace& t, const DutShape& shape) {
  BinCounts bins;
  const uint32_t zmax = depth_max(t.depth_bits);
  const int n = t.coverage_samples;

  // The golden model's decisions, fragment by fragment in stream order (per pixel the
  // testbench's order too): the stored pixel before each, and what it wrote.
  GoldenRop golden;
  golden.begin_frame(t.width, t.height, t.depth_bits, t.clear_color, n, t.wboit);
  const Framebuffer& fb = golden.framebuffer();
  for (const TracePass& pass : t.passes) {
    for (const FrameOp& op : pass.frame_ops) golden.frame_op(op);
    const RopState& s = pass.state;
    golden.begin_pass(s);
    const bool cov_mode = s.blend == BlendMode::kCoverage;
    const std::string dims = state_dims(s);
    for (const Fragment& f : pass.fragments) {
      const size_t i = fb.index(f.x, f.y);
      const StoredPixel before{fb.depth[i], fb.color[i], fb.coverage[i], fb.accum_at(i),
                               fb.reveal_at(i)};
      const uint32_t peel = fb.peel[i];
      const int rel = relation(f.z, before.depth);
      // The layers before the write, copied only in layers mode.
      const PixelLayers layers = s.blend == BlendMode::kLayers ? fb.layers_at(i) : PixelLayers{};
      const PixelWrites w = golden.process(f);
      if (w.layers) count_layers(bins, s.layers, layers, fragment_layer(f.z, f.color));

      if (s.blend != BlendMode::kLayers)  // the plan's cross leaves layers mode out
        ++bins["pass_state[" + dims + "]"];
      if (s.depth_test && !cov_mode)
        ++bins[fmt::format("depth_compare[func={},relation={}]", to_string(s.depth_func),
                           kRelations[rel])];
      if (s.peel_test && !cov_mode) ++bins[f.z > peel ? "peel_compare.behind" : "peel_compare.not_behind"];
      if (cov_mode)
        ++bins[fmt::format("coverage_composite[relation={},sum={}]", kRelations[rel],
                           f.coverage + before.coverage <= n ? "Fits" : "Overflows")];
      if (w.color) {
        for (int k = 0; k < 4; ++k) {
          if (!(s.color_mask >> k & 1)) continue;
          const uint8_t v = channel(w.rgba, k);
          if (v == 0) ++bins[fmt::format("blend_result[blend={},value=Zero]", to_string(s.blend))];
          if (v == 255) ++bins[fmt::format("blend_result[blend={},value=Full]", to_string(s.blend))];
        }
      }
      if (f.z == 0) ++bins["frag_depth.zero"];
      if (f.z == zmax) ++bins["frag_depth.max"];
      if (f.color.a == 0) ++bins["frag_alpha.zero"];
      if (f.color.a == 255) ++bins["frag_alpha.full"];
      if (f.coverage == 0) ++bins["frag_coverage.zero"];
      if (f.coverage == 1) ++bins["frag_coverage.one"];
      if (f.coverage == n) ++bins["frag_coverage.full"];
      if (w.accum) {  // a channel's sum carrying out of its acc_bits (zb_rop's acc_sat)
        const std::array<uint32_t, 4> terms = wboit_terms(f.z, f.color, t.depth_bits, t.wboit);
        for (size_t c = 0; c < 4; ++c)
          if ((uint64_t(before.acc[c]) + terms[c]) >> t.wboit.acc_bits)
            ++bins[fmt::format("accum_saturation[channel={}]", kChannels[c])];
      }

      // The suite's goals.
      const bool shows = visible(s, f, before, t.depth_bits, n, t.wboit);
      const bool peel_shows = !s.peel_test || cov_mode || (rel == 1 ? f.z <= peel : f.z > peel);
      if (peel_shows && shows)
        ++bins[fmt::format("goal.state_relation[{},relation={}]", dims, kRelations[rel])];
      const bool ordering = s.depth_test && !cov_mode && s.depth_func != DepthFunc::kNever &&
                            s.depth_func != DepthFunc::kAlways;
      const bool observable = s.depth_write || (s.color_mask != 0 && s.blend != BlendMode::kAccumulate);
      const uint32_t diff = f.z ^ before.depth;
      if (ordering && observable && diff != 0 && (diff & (diff - 1)) == 0) {
        int bit = 0;
        while ((diff >> bit) != 1) ++bit;
        ++bins[fmt::format("goal.depth_bit[bits={},bit={},order={}]", t.depth_bits, bit,
                           rel == 0 ? "below" : "above")];
      }
      if (s.depth_test && (f.z <= 1 || f.z >= zmax - 1))
        ++bins[fmt::format("goal.depth_value[bits={},value={}]", t.depth_bits, corner_name(f.z, zmax))];
      const bool passes = (!s.depth_test || depth_test(s.depth_func, f.z, before.depth)) &&
                          (!s.peel_test || f.z > peel);
      if (!cov_mode && s.blend != BlendMode::kAccumulate && passes && shows)
        for (int k = 0; k < 4; ++k)
          for (uint8_t v : kChannelCorners)
            if (channel(f.color, k) == v)
              ++bins[fmt::format("goal.channel_value[channel={},value={},mask={:x}]", kChannels[k],
                                 v, s.color_mask & 15)];
      if (cov_mode) {
        auto corner = [&](int c) {
          return c == 0 ? "0" : c == 1 ? "1" : c == n - 1 ? "n_minus_1" : c == n ? "n" : nullptr;
        };
        const char* kc = corner(f.coverage);
        const char* sc = corner(before.coverage);
        if (kc && sc)
          ++bins[fmt::format("goal.coverage_value[samples={},frag={},stored={},relation={}]", n, kc,
                             sc, kRelations[rel])];
      }
      for (int tile : kGoalTiles) {
        ++bins[fmt::format("goal.tile_position[tile={},row={},col={}]", tile,
                           kBands[band(f.y % tile, tile)], kColBands[band(f.x % tile, tile)])];
        ++bins[fmt::format("goal.tile_origin[tile={},origin={}]", tile,
                           kOrigins[origin_kind(f.x / tile, f.y / tile)])];
      }
    }
    golden.end_pass();
  }
  if (resolves_layers(t, shape)) ++bins["layers_cases.resolve_read"];

  for (int tile : kGoalTiles)
    if (t.width % tile == 0 && t.height % tile == 0 && t.width >= 2 * tile && t.height >= 2 * tile)
      ++bins[fmt::format("goal.frame_fills[tile={}]", tile)];

  // The testbench's order at the DUT's tile: positions, origins, loads, stores, state writes,
  // and the same-pixel distances in fragments taken, tile-local as a DUT's addresses are.
  // Every cycle between tiles offers no fragment (the load and store, the wait for idle_o):
  // a gap, so the plan's "Calm" distances are those inside one tile's stream.
  const int window_dist = shape.window + 1;
  // zb_conf_tb's gap generator: xorshift32 from seed ^ 0x9e3779b9, one draw for each cycle the
  // testbench weighs offering a fragment (tight timing draws nothing else).
  uint32_t rng = shape.seed ^ 0x9e3779b9u;
  if (rng == 0) rng = 1;
  auto chance = [&] {
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return int(rng % 100u);
  };
  struct Taken {
    int addr;         // tile-local, as a DUT's addresses are
    bool gap;         // a gap since it was taken
    BlendMode blend;
  };
  std::deque<Taken> hist;  // the last fragments taken, newest last
  auto gap_all = [&] {
    for (Taken& k : hist) k.gap = true;
  };
  tb_order(t, shape, [&](size_t p, size_t i, int x0, int y0, bool first, bool load) {
    const Fragment& f = t.passes[p].fragments[i];
    const RopState& s = t.passes[p].state;
    if (first) {
      ++bins["frame_ops.state_write"];
      if (!load) ++bins["pass_resident.boundary"];  // the state written with the tile resident
      gap_all();  // the wait for idle_o, the state write
    }
    if (load) {
      ++bins["store.first_beat"];
      ++bins["store.last_beat"];
      for (const char* plane : kPlaneNames) {
        ++bins[fmt::format("plane_ops[plane={},op=LoadFirstBeat]", plane)];
        ++bins[fmt::format("plane_ops[plane={},op=LoadLastBeat]", plane)];
      }
    }
    bool gap = false;
    while (shape.gap_pct > 0 && chance() < shape.gap_pct) gap = true;
    if (gap) gap_all();
    const int lx = f.x - x0, ly = f.y - y0;
    const int addr = ly * shape.tile_w + lx;
    ++bins[fmt::format("frag_in_tile[row={},col={}]", kBands[band(ly, shape.tile_h)],
                       kColBands[band(lx, shape.tile_w)])];
    ++bins[fmt::format("tile_origin.{}", kOrigins[origin_kind(x0, y0)])];
    for (size_t back = 1; back <= hist.size(); ++back) {
      const Taken& k = hist[hist.size() - back];
      if (k.addr != addr) continue;
      if (int(back) <= window_dist)
        ++bins[fmt::format("same_pixel[distance={},between={}]", back, k.gap ? "Gap" : "Calm")];
      if (int(back) <= kRunDistances && is_rmw(s.blend) && k.blend == s.blend && !k.gap)
        ++bins[fmt::format("goal.same_pixel_rmw[blend={},distance={}]", to_string(s.blend), back)];
      break;
    }
    hist.push_back({addr, false, s.blend});
    if (hist.size() > size_t(std::max(window_dist, kRunDistances))) hist.pop_front();
  });
  return bins;
}

BinList reach_bins(const DutShape& shape) {
  BinList out;
  std::vector<std::string>& plan = out.plan;
  std::vector<std::string> states;
  for (const RopState& s : pass_states()) states.push_back(state_dims(s));
  for (const std::string& s : states) plan.push_back("pass_state[" + s + "]");
  for (int f = 0; f < 8; ++f)
    for (const char* r : kRelations)
      plan.push_back(fmt::format("depth_compare[func={},relation={}]", to_string(DepthFunc(f)), r));
  plan.push_back("peel_compare.behind");
  plan.push_back("peel_compare.not_behind");
  for (const char* r : kRelations)
    for (const char* sum : {"Fits", "Overflows"})
      plan.push_back(fmt::format("coverage_composite[relation={},sum={}]", r, sum));
  for (unsigned b = 0; b < 5; ++b)
    for (const char* v : {"Zero", "Full"})
      plan.push_back(fmt::format("blend_result[blend={},value={}]", to_string(BlendMode(b)), v));
  for (const char* b : {"frag_depth.zero", "frag_depth.max", "frag_alpha.zero", "frag_alpha.full",
                        "frag_coverage.zero", "frag_coverage.one", "frag_coverage.full"})
    plan.push_back(b);
  for (const char* r : kBands)
    for (const char* c : kColBands) plan.push_back(fmt::format("frag_in_tile[row={},col={}]", r, c));
  for (const char* c : kChannels) plan.push_back(fmt::format("accum_saturation[channel={}]", c));
  for (int d = 1; d <= shape.window + 1; ++d)
    for (const char* between : {"Calm", "Gap"})
      plan.push_back(fmt::format("same_pixel[distance={},between={}]", d, between));
  for (const char* o : kOrigins) plan.push_back(fmt::format("tile_origin.{}", o));
  plan.push_back("store.first_beat");
  plan.push_back("store.last_beat");
  for (const char* p : kPlaneNames)
    for (const char* op : {"LoadFirstBeat", "LoadLastBeat"})
      plan.push_back(fmt::format("plane_ops[plane={},op={}]", p, op));
  plan.push_back("frame_ops.state_write");
  plan.push_back("pass_resident.boundary");
  for (int pos = 0; pos <= kKitLayers; ++pos)
    for (const char* full : {"no", "yes"})
      plan.push_back(fmt::format("layers_insert[position={},full={}]", pos, full));
  for (int k = 1; k <= kKitLayers; ++k) plan.push_back(fmt::format("layers_k[k={}]", k));
  for (const char* c : {"b", "g", "r", "a"})
    plan.push_back(fmt::format("layers_merge_saturation[channel={}]", c));
  for (const char* b : {"equal_depth", "equal_key", "alpha_zero", "merge", "resolve_read"})
    plan.push_back(fmt::format("layers_cases.{}", b));

  std::vector<std::string>& goals = out.goals;
  for (const std::string& s : states)
    for (const char* r : kRelations)
      goals.push_back(fmt::format("goal.state_relation[{},relation={}]", s, r));
  for (int bits : kGoalDepthBits)
    for (int bit = 0; bit < bits; ++bit)
      for (const char* o : {"below", "above"})
        goals.push_back(fmt::format("goal.depth_bit[bits={},bit={},order={}]", bits, bit, o));
  for (int bits : kGoalDepthBits)
    for (const char* v : {"zero", "one", "max_minus_1", "max"})
      goals.push_back(fmt::format("goal.depth_value[bits={},value={}]", bits, v));
  for (const char* c : kChannels)
    for (uint8_t v : kChannelCorners)
      for (int m = 0; m < 16; ++m)
        goals.push_back(fmt::format("goal.channel_value[channel={},value={},mask={:x}]", c, v, m));
  for (int n : kGoalSamples)
    for (const char* k : {"0", "1", "n_minus_1", "n"})
      for (const char* c : {"0", "1", "n_minus_1", "n"})
        for (const char* r : kRelations)
          goals.push_back(fmt::format("goal.coverage_value[samples={},frag={},stored={},relation={}]",
                                      n, k, c, r));
  for (int tile : kGoalTiles) {
    for (const char* r : kBands)
      for (const char* c : kColBands)
        goals.push_back(fmt::format("goal.tile_position[tile={},row={},col={}]", tile, r, c));
    for (const char* o : kOrigins) goals.push_back(fmt::format("goal.tile_origin[tile={},origin={}]", tile, o));
    goals.push_back(fmt::format("goal.frame_fills[tile={}]", tile));
  }
  for (BlendMode b : kRmwBlends)
    for (int d = 1; d <= kRunDistances; ++d)
      goals.push_back(fmt::format("goal.same_pixel_rmw[blend={},distance={}]", to_string(b), d));
  return out;
}

}  // namespace zb::conformance

namespace zb::conformance {

std::vector<BinCounts> tests_reach(const std::vector<TestSpec>& tests, const DutShape& shape) {
  std::vector<BinCounts> out(tests.size());
  const int workers = std::min<int>(resolve_threads(0), int(tests.size()));
  std::atomic<size_t> next{0};
  run_workers(workers, [&](int) {
    for (size_t i = next++; i < tests.size(); i = next++) out[i] = trace_reach(test_trace(tests[i]), shape);
  });
  return out;
}

std::vector<std::pair<size_t, size_t>> rank_tests(const std::vector<BinCounts>& reach,
                                                  const std::vector<std::string>& bins) {
  const std::set<std::string> wanted(bins.begin(), bins.end());
  std::set<std::string> hit;
  std::vector<std::pair<size_t, size_t>> order;
  std::vector<bool> taken(reach.size(), false);
  for (;;) {
    size_t best = reach.size(), best_new = 0;
    for (size_t i = 0; i < reach.size(); ++i) {
      if (taken[i]) continue;
      size_t fresh = 0;
      for (const auto& [bin, count] : reach[i]) fresh += wanted.count(bin) && !hit.count(bin);
      if (fresh > best_new) best = i, best_new = fresh;
    }
    if (best == reach.size()) return order;
    taken[best] = true;
    for (const auto& [bin, count] : reach[best])
      if (wanted.count(bin)) hit.insert(bin);
    order.emplace_back(best, best_new);
  }
}

}  // namespace zb::conformance
