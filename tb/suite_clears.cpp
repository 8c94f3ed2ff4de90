// clears: directed fast-clear sequences across tile runs (docs/rtl.md "Tile port"). A plane's
// write-back of a store's last beat lands after the next run's fast clear (the driver starts
// the next tile's setup at the store's last edge); then passes that read depth but store
// nothing, each after a depth clear, so the plane is cleared again with no store between; then
// a probe that tests depth against the last clear value at every pixel, the last beat's too.
// A word left current with an older clear value, or a plane whose clears flip the epoch back,
// changes the probe's results. The tiles suite re-reads every store, which puts cycles between
// a store and the next clear: this suite never does. A last iteration loads one tile's stored
// depth and fast-clears the next, in two passes that store nothing, then the same with the peel
// plane (two_tiles).
#include <algorithm>

#include "rop/fixed.h"
#include "suites.h"

namespace zb::tb {

namespace {

constexpr DepthFunc kTests[] = {DepthFunc::kLess,    DepthFunc::kLequal,   DepthFunc::kGreater,
                                DepthFunc::kGequal,  DepthFunc::kEqual,    DepthFunc::kNotequal};

RopState depth_reader(Rng& r, bool writes_color, bool writes_depth) {
  RopState s;
  s.depth_test = true;
  s.depth_func = kTests[r.below(6)];
  s.depth_write = writes_depth;
  s.blend = BlendMode::kReplace;
  s.color_mask = writes_color ? kMaskRgba : 0;
  return s;
}

// Fragments on `w` x `h`: every pixel (with odds `all` of 1), else one row in eight; depths on
// or beside one of `near` (a clear value a word may wrongly hold) or anywhere.
std::vector<Fragment> fragments(Rng& r, int w, int h, bool all, const std::vector<uint32_t>& near,
                                uint32_t zmax) {
  std::vector<Fragment> f;
  for (int y = 0; y < h; ++y) {
    if (!all && r.below(8) != 0 && y != h - 1) continue;
    for (int x = 0; x < w; ++x) {
      Fragment g;
      g.x = uint16_t(x);
      g.y = uint16_t(y);
      const int64_t v = near[r.below(uint32_t(near.size()))];
      g.z = r.chance(0.8) ? uint32_t(std::clamp<int64_t>(v - 1 + r.below(3), 0, zmax))
                          : r.below(zmax + 1u);
      g.color = Rgba8{uint8_t(r.below(256)), uint8_t(r.below(256)), uint8_t(r.below(256)),
                      uint8_t(r.below(256))};
      g.prim = uint32_t(f.size() / 16);
      f.push_back(g);
    }
  }
  return f;
}

// Tile 0 holds stored depth, tile 1 only its clear; then two passes over both that read depth
// and write nothing, so each loads tile 0 and fast-clears tile 1 with no store between. A depth
// plane whose all-fresh flag a load leaves set keeps tile 1's epoch in the second pass and reads
// tile 0's words there: only the pass counts show it, as nothing is written. Then the peel plane
// the same way, a copy of that depth.
void two_tiles(Cosim& cs, Rng& r, uint32_t zmax) {
  const int w = 2 * kRtlTileW, h = kRtlTileH;
  cs.begin_frame(w, h, 24, Rgba8{5, 6, 7, 8});
  std::vector<uint32_t> values{r.below(zmax + 1u)};
  cs.frame_op({FrameOpKind::kClearDepth, {}, values[0], false});
  std::vector<Fragment> first = fragments(r, kRtlTileW, h, true, values, zmax);
  for (const Fragment& f : first) values.push_back(f.z);
  draw_pass(cs, "clears-tile0", depth_reader(r, true, true), first);
  for (int k = 0; k < 2; ++k)
    draw_pass(cs, "clears-two-silent", depth_reader(r, false, false),
              fragments(r, w, h, true, values, zmax));
  // The same for the peel plane: tile 0's a copy of stored depth, tile 1's of its clear.
  cs.frame_op({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
  for (int k = 0; k < 2; ++k) {
    RopState peel = depth_reader(r, false, false);
    peel.peel_test = true;
    draw_pass(cs, "clears-two-silent-peel", peel, fragments(r, w, h, true, values, zmax));
  }
}

}  // namespace

Tally suite_clears(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 6;
  const uint32_t zmax = depth_max(24);
  WorkCounter progress(c, uint64_t(iters) + 1);
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    const bool ok = run_iteration("clears", c, seed, t, [&](Cosim& cs) {
      Rng r(seed ^ 0xc1ea75ull);
      // Whole tiles (the last beat in the frame), one or two: two put the first tile's store
      // and the second's clear in one pass as well.
      const int w = kRtlTileW * (1 + int(r.below(2))), h = kRtlTileH;
      cs.begin_frame(w, h, 24, Rgba8{5, 6, 7, 8});
      auto clear_depth = [&](uint32_t v) {
        cs.frame_op({FrameOpKind::kClearDepth, {}, v, false});
      };
      std::vector<uint32_t> values;  // every depth clear value of the frame so far
      auto fresh_value = [&] {
        uint32_t v;
        do v = r.chance(0.2) ? (r.chance(0.5) ? 0 : zmax) : r.below(zmax + 1u);
        while (std::find(values.begin(), values.end(), v) != values.end());
        values.push_back(v);
        return v;
      };
      for (int round = 0; round < 3; ++round) {
        // A store whose depth words are mostly fresh: a cleared plane, depth written rarely.
        clear_depth(fresh_value());
        draw_pass(cs, "clears-store", depth_reader(r, true, r.chance(0.25)),
                  fragments(r, w, h, false, values, zmax));
        // Clears with no store between: passes that read depth and write nothing.
        for (int k = 1 + int(r.below(2)); k > 0; --k) {
          clear_depth(fresh_value());
          draw_pass(cs, "clears-silent", depth_reader(r, false, false),
                    fragments(r, w, h, false, values, zmax));
        }
        // The probe: a new clear value, every pixel tested against it and coloured by the test.
        clear_depth(fresh_value());
        draw_pass(cs, "clears-probe", depth_reader(r, true, r.chance(0.5)),
                  fragments(r, w, h, true, values, zmax));
      }
    });
    if (!ok) return t;
    progress.add();
  }
  const uint64_t seed = c.seed + uint64_t(iters);
  if (run_iteration("clears", c, seed, t, [&](Cosim& cs) {
        Rng r(seed ^ 0x2711e5ull);
        two_tiles(cs, r, zmax);
      }))
    progress.add();
  return t;
}

}  // namespace zb::tb
