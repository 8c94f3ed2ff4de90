// tiles: the tile planes' fast-clear bookkeeping. Passes from a menu that includes passes
// writing nothing at all (so a plane is fast-cleared twice with no store between) and
// accumulate passes (the accumulation plane), clears, peel copies and resolves between them, on one or two tiles, some passes touching one tile only; depths
// beside the last depth clear value; frames a few rows high or one or two tiles high; half of
// them ending on a renamed copy.
#include <algorithm>
#include <string>
#include <vector>

#include "rop/fixed.h"
#include "suites.h"

namespace zb::tb {

Tally suite_tiles(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 12;
  WorkCounter progress(c, iters);
  const uint32_t zmax = depth_max(24);
  Config reread = c;
  reread.cosim.rtl.reread_stores = true;  // and every store must leave the planes as they were
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
      // Half the frames end on a renamed copy (a copy of depth to peel, then a clear of depth:
      // docs/rtl.md "Renamed copies"), half of those with one more pass on the first tile only:
      // the tile schedule trades the banks in that pass's setup there and, on a second tile, in
      // a cycle of its own before the store.
      if (r.chance(0.5)) {
        cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
        cs.frame_op({FrameOpKind::kClearDepth, {}, r.chance(0.5) ? zmax : r.below(zmax), false});
        if (r.chance(0.5)) {
          RopState st;
          st.peel_test = true;
          std::vector<Fragment> f;
          for (int y = 0; y < h; y += 3)
            for (int x = 0; x < std::min(w, kRtlTileW); x += 2) {
              Fragment g;
              g.x = uint16_t(x);
              g.y = uint16_t(y);
              g.z = r.below(zmax + 1u);
              g.color = Rgba8{pick_channel(r), pick_channel(r), pick_channel(r), pick_alpha(r)};
              g.prim = uint32_t(f.size() / 16);
              f.push_back(g);
            }
          draw_pass(cs, "tiles-after-rename", st, f);
        }
      }
    });
    if (!ok) break;
    progress.add();
  }
  return t;
}

}  // namespace zb::tb
