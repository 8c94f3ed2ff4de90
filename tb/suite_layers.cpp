// layers: mlab-K's layers (docs/datapath.md "8. Layers") through the pipeline, on one tile. The
// layers word is read at E5 and written at E11, as the colour, so the streams put a pixel's
// fragments at issue distances 4 to 7 (same_pixel.h) and in runs on one pixel: inserts at every
// position, merges once a pixel holds K, equal depths (a small pool) with equal and different
// colour words (a small colour pool), alpha 0. Each iteration draws an opaque pass, then layers
// passes of K = 1 to the model's LAYERS under random depth functions, masks and peel tests,
// each closed by its resolve on the tile's store (they never leave the tile), then a pass of the
// alpha blend, whose store must not resolve the layers again. Faint fragments (alpha 1 to 8) let
// the resolve's deeper steps meet a large 255 - A. Before that alpha pass, a last layers pass
// fills the tile: every pixel LAYERS + 1 fragments, so every lane, slot and channel of the resolve
// multiplies random operands (the rounding's rare cases) and every pixel merges. A merge pass
// then gives every pixel 2K + 2 fragments with the depth test off, alphas uniform or faint, so
// each of the three merges' multipliers meets thousands of random operand pairs.
#include <fmt/core.h>

#include <algorithm>

#include "rop/fixed.h"
#include "same_pixel.h"
#include "suites.h"

namespace zb::tb {

namespace {

constexpr int kLayersPasses = 3;  // an iteration's layers passes

RopState layers_state(Rng& r) {
  static const DepthFunc funcs[] = {DepthFunc::kLess, DepthFunc::kLess, DepthFunc::kLequal,
                                    DepthFunc::kAlways, DepthFunc::kGreater};
  RopState s;
  s.blend = BlendMode::kLayers;
  s.layers = uint8_t(1 + r.below(uint32_t(RtlRop::model_layers())));
  s.depth_test = r.chance(0.85);
  s.depth_func = funcs[r.below(5)];
  s.depth_write = r.chance(0.1);
  s.color_mask = r.chance(0.9) ? uint8_t(kMaskRgba) : uint8_t(r.below(16));
  s.peel_test = r.chance(0.15);
  return s;
}

// Colours from a pool of three now and then, so equal depths meet equal colour words; faint
// ones now and then.
void pool_colours(Rng& r, std::vector<Fragment>& f) {
  const Rgba8 pool[3] = {{200, 30, 30, 128}, {30, 200, 30, 128}, {30, 30, 200, 90}};
  for (Fragment& x : f) {
    if (r.chance(0.3)) x.color = pool[r.below(3)];
    else if (r.chance(0.15)) x.color.a = uint8_t(1 + r.below(8));
  }
}

// Every pixel of the tile `n` times, each round in a shuffled order.
std::vector<Fragment> fill(SamePixelStreams& d, int n) {
  std::vector<int> order(static_cast<size_t>(kPixels));
  for (int i = 0; i < kPixels; ++i) order[size_t(i)] = i;
  std::vector<Fragment> out;
  for (int round = 0; round < n; ++round) {
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[d.r.below(uint32_t(i))]);
    for (int px : order) out.push_back(d.at(px));
  }
  for (size_t i = 0; i < out.size(); ++i) out[i].prim = uint32_t(i / 16);
  return out;
}

// Every colour and alpha random, the alpha above 0: half of them uniform, half faint.
void merge_colours(Rng& r, std::vector<Fragment>& f) {
  for (Fragment& x : f) {
    x.color = Rgba8{uint8_t(r.below(256)), uint8_t(r.below(256)), uint8_t(r.below(256)),
                    uint8_t(r.chance(0.5) ? 1 + r.below(255) : 1 + r.below(16))};
  }
}

}  // namespace

Tally suite_layers(const Config& c) {
  if (RtlRop::model_layers() == 0) {
    Tally t;
    t.note = "skipped: the Verilated zb_rop has no layers unit (LAYERS 0, or the mutant netlist)";
    return t;
  }
  return same_pixel_suite(
      "layers", "layers", c, kLayersPasses, 0x1a7e5ull, 4,
      [&](Cosim& cs, Rng& r, SamePixelStreams& d, size_t per_pass, int p, uint64_t dist[4]) {
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        const RopState st = layers_state(r);
        std::vector<Fragment> f = d.stream(per_pass);
        pool_colours(r, f);
        if (st.color_mask != 0) count_distances(f, dist);
        draw_pass(cs, fmt::format("layers-{}-k{}", p + 1, int(st.layers)), st, f);
        cs.frame_op({FrameOpKind::kResolveLayers, {}, 0, false});
        if (p == kLayersPasses - 1) {
          RopState full = layers_state(r);  // every slot in use: K = LAYERS
          full.color_mask = kMaskRgba;
          full.layers = uint8_t(RtlRop::model_layers());
          std::vector<Fragment> all = fill(d, full.layers + 1);
          pool_colours(r, all);
          draw_pass(cs, fmt::format("layers-fill-k{}", int(full.layers)), full, all);
          cs.frame_op({FrameOpKind::kResolveLayers, {}, 0, false});
          RopState merge;  // no depth test: every fragment inserts; K random
          merge.blend = BlendMode::kLayers;
          merge.depth_test = false;
          merge.layers = uint8_t(1 + r.below(uint32_t(RtlRop::model_layers())));
          std::vector<Fragment> many = fill(d, 2 * merge.layers + 2);
          merge_colours(r, many);
          draw_pass(cs, fmt::format("layers-merge-k{}", int(merge.layers)), merge, many);
          cs.frame_op({FrameOpKind::kResolveLayers, {}, 0, false});
          RopState alpha;  // the layers resolved: this store must not resolve them again
          alpha.blend = BlendMode::kAlpha;
          draw_pass(cs, "layers-after", alpha, d.stream(per_pass / 4));
        }
      });
}

}  // namespace zb::tb
