// layers: mlab-K's layers (docs/datapath.md "8. Layers") through the pipeline, on one tile. The
// layers word is read at E5 and written at E11, as the colour, so the streams put a pixel's
// fragments at issue distances 4 to 7 (same_pixel.h) and in runs on one pixel: inserts at every
// position, merges once a pixel holds K, equal depths (a small pool) with equal and different
// colour words (a small colour pool), alpha 0. Each iteration draws an opaque pass, then layers
// passes of K = 1 to the model's LAYERS under random depth functions, masks and peel tests,
// each closed by its resolve on the tile's store (they never leave the tile).
#include <fmt/core.h>

#include <algorithm>

#include "rop/fixed.h"
#include "same_pixel.h"
#include "suites.h"

namespace zb::tb {

namespace {

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

// Colours from a pool of three now and then, so equal depths meet equal colour words.
void pool_colours(Rng& r, std::vector<Fragment>& f) {
  const Rgba8 pool[3] = {{200, 30, 30, 128}, {30, 200, 30, 128}, {30, 30, 200, 90}};
  for (Fragment& x : f)
    if (r.chance(0.3)) x.color = pool[r.below(3)];
}

}  // namespace

Tally suite_layers(const Config& c) {
  Tally t;
  if (RtlRop::model_layers() == 0) {
    t.note = "skipped: the Verilated zb_rop has no layers unit (LAYERS 0, or the mutant netlist)";
    return t;
  }
  const int iters = c.iterations ? c.iterations : 6;
  constexpr int kPasses = 3;
  const size_t per_pass =
      c.fragments ? std::max<uint64_t>(1, c.fragments / uint64_t(iters) / kPasses) : 3000;
  uint64_t dist[4] = {};
  WorkCounter progress(c, uint64_t(iters));
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("layers", c, seed, t, [&](Cosim& cs) {
      Rng r(seed ^ 0x1a7e5ull);
      SamePixelStreams d{r, std::vector<uint32_t>(4)};
      for (uint32_t& z : d.zpool) z = r.below(depth_max(24));
      cs.begin_frame(kRtlTileW, kRtlTileH, 24, Rgba8{20, 40, 60, 255}, kRtlCoverageSamples,
                     kRtlWboit);
      RopState opaque;  // the opaque depth and colour the layers are tested and resolved over
      opaque.depth_test = true;
      opaque.depth_write = true;
      draw_pass(cs, "layers-opaque", opaque, d.stream(per_pass / 2));
      for (int p = 0; p < kPasses; ++p) {
        if (r.chance(0.3)) cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        const RopState st = layers_state(r);
        std::vector<Fragment> f = d.stream(per_pass);
        pool_colours(r, f);
        if (st.color_mask != 0) count_distances(f, dist);
        draw_pass(cs, fmt::format("layers-{}-k{}", p + 1, int(st.layers)), st, f);
        cs.frame_op({FrameOpKind::kResolveLayers, {}, 0, false});
      }
    });
    if (!ok) break;
    progress.add();
  }
  t.note = fmt::format(
      "same-pixel issue distances 4/5/6/7 in layers passes (the schedule without "
      "back-pressure): {}/{}/{}/{}",
      dist[0], dist[1], dist[2], dist[3]);
  if (!t.failed && std::find(std::begin(dist), std::end(dist), 0u) != std::end(dist))
    t.note += "; warning: a distance was never reached";
  return t;
}

}  // namespace zb::tb
