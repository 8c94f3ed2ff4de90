// The golden model of the per-pixel datapath (raster operations): per fragment, fetch, depth
// test, blend, write mask, write. Bit-exact specification of the RTL; see docs/datapath.md.
#pragma once

#include "backend.h"

namespace zb {

// True when the fragment depth `z` passes `func` against the stored depth `stored`.
bool depth_test(DepthFunc func, uint32_t z, uint32_t stored);

// The colour the blend unit produces from source `s` and destination `d`.
Rgba8 blend(BlendMode mode, Rgba8 s, Rgba8 d);

// Merges `blended` into `d` under the colour write mask.
Rgba8 apply_color_mask(uint8_t mask, Rgba8 blended, Rgba8 d);

class GoldenRop final : public Backend {
 public:
  const char* name() const override { return "golden"; }
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color) override;
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  PassStats end_pass() override;
  const Framebuffer& framebuffer() const override { return fb_; }

  // One fragment through the datapath.
  void process(const Fragment& f);

 private:
  Framebuffer fb_;
  RopState state_;
  PassStats stats_;
};

}  // namespace zb
