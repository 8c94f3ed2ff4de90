// The golden model of the per-pixel datapath (raster operations): per fragment, fetch, depth
// test, blend, write mask, write. Bit-exact specification of the RTL; see docs/datapath.md.
#pragma once

#include <array>
#include <cstdint>

#include "arithmetic.h"
#include "backend.h"

namespace zb {

// True when depth `z` passes `func` against the stored depth `stored`: the datapath's compare
// on unorm depths, and the same on exact depths (the OpenGL oracle's replay).
template <class Depth>
constexpr bool depth_compare(DepthFunc func, Depth z, Depth stored) {
  switch (func) {
    case DepthFunc::kNever: return false;
    case DepthFunc::kLess: return z < stored;
    case DepthFunc::kEqual: return z == stored;
    case DepthFunc::kLequal: return z <= stored;
    case DepthFunc::kGreater: return z > stored;
    case DepthFunc::kNotequal: return z != stored;
    case DepthFunc::kGequal: return z >= stored;
    case DepthFunc::kAlways: return true;
  }
  return false;
}

inline bool depth_test(DepthFunc func, uint32_t z, uint32_t stored) {
  return depth_compare(func, z, stored);
}

// The colour the blend unit produces from source `s` and destination `d`.
Rgba8 blend(BlendMode mode, Rgba8 s, Rgba8 d);
// The same under a declared arithmetic (arithmetic.h): the alpha and additive blends by its
// rule, every other mode as blend() (they are zblend's own operations).
Rgba8 blend(const Arithmetic& r, BlendMode mode, Rgba8 s, Rgba8 d);

// Merges `blended` into `d` under the colour write mask.
Rgba8 apply_color_mask(uint8_t mask, Rgba8 blended, Rgba8 d);

// The pixel after compositing a polygon pixel (depth z, colour p, k of N samples covered) onto
// the stored ("background") pixel, by the four cases of US 5,123,085 claim 1
// (docs/datapath.md "Coverage blend"). 0 <= k, cs <= n.
struct CoveragePixel {
  Rgba8 color;
  uint32_t depth = 0;
  uint8_t coverage = 0;
};
CoveragePixel composite_coverage(uint32_t z, Rgba8 p, int k, uint32_t zs, Rgba8 b, int cs, int n);

// The displayed pixel of a coverage-aa frame: the stored colour, which already carries the
// background by coverage (datapath.md "Resolve"). The coverage plane is not needed for display.
Rgba8 resolve_coverage(Rgba8 stored, int coverage, int n);

// The writes one fragment makes to its pixel: the golden model's write log, which the
// lock-step scoreboard (tb/scoreboard.h) holds the RTL's retire port to.
struct PixelWrites {
  bool depth = false, coverage = false, color = false;
  bool accum = false;  // accumulate mode: the accumulation and revealage written
  uint32_t z = 0;     // the depth written
  uint8_t cov = 0;    // the coverage count written
  Rgba8 rgba;         // the colour written, after the write mask
  std::array<uint32_t, 4> acc{};  // the accumulation written (R, G, B, A)
  uint32_t reveal = 0;            // the revealage written
  bool layers = false;  // layers mode: the pixel's layers written
  int layer_at = -1;    // where the fragment went: 0..K-1, K merged into the last, -1 none
  PixelLayers lay;      // the layers written
};

// Whether two write logs agree on the planes one retire stage writes: X4 depth and coverage,
// X11 (x11) colour, the accumulation word and the layers. The lock-step scoreboard's rule and
// the pixel history's.
bool same_stage_writes(bool x11, const PixelWrites& a, const PixelWrites& b);

// The four terms (R, G, B, A) an accumulate-mode fragment of depth z and colour c adds to the
// accumulation before the saturating add (docs/datapath.md "7. Accumulate blend").
std::array<uint32_t, 4> wboit_terms(uint32_t z, Rgba8 c, int depth_bits, const WboitFormat& format);

// The accumulation and revealage of a pixel after an accumulate-mode fragment of depth z and
// colour c (docs/datapath.md "7. Accumulate blend").
struct WboitPixel {
  std::array<uint32_t, 4> acc{};
  uint32_t reveal = 0;
};
WboitPixel accumulate_wboit(uint32_t z, Rgba8 c, const std::array<uint32_t, 4>& acc,
                            uint32_t reveal, int depth_bits, const WboitFormat& format);

class GoldenRop final : public Backend {
 public:
  const char* name() const override { return "golden"; }
  using Backend::begin_frame;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                   int coverage_samples, const WboitFormat& wboit) override;
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  PassStats end_pass() override;
  void frame_op(const FrameOp& op) override;
  void load_region(const RegionLoad& r) override { apply_region_load(fb_, r); }
  const Framebuffer& framebuffer() const override { return fb_; }

  // One fragment through the datapath; returns what it wrote. Throws std::invalid_argument
  // when its coverage exceeds the frame's sample count.
  PixelWrites process(const Fragment& f);

  // The blend arithmetic a DUT declares (the conformance path); zblend's by default. Kept
  // across frames.
  void set_arithmetic(const Arithmetic& r) {
    arith_ = r;
    declared_ = !r.is_zblend();
  }
  Arithmetic arithmetic() const { return arith_; }

 private:
  // One fragment; its writes into *w when kLog (process), none when not (draw).
  template <bool kLog>
  void run(const Fragment& f, PixelWrites* w);
  template <bool kLog>
  void run_coverage(const Fragment& f, PixelWrites* w);

  Framebuffer fb_;
  RopState state_;
  PassStats stats_;
  Arithmetic arith_;
  bool declared_ = false;  // arith_ is not zblend's: the colour path asks it
};

}  // namespace zb
