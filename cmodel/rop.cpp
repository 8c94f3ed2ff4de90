#include "rop.h"

namespace zb {

PassStats& PassStats::operator+=(const PassStats& o) {
  fragments_in += o.fragments_in;
  fragments_passed += o.fragments_passed;
  color_reads += o.color_reads;
  color_writes += o.color_writes;
  depth_reads += o.depth_reads;
  depth_writes += o.depth_writes;
  cycles += o.cycles;
  return *this;
}

bool depth_test(DepthFunc func, uint32_t z, uint32_t stored) {
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

Rgba8 blend(BlendMode mode, Rgba8 s, Rgba8 d) {
  switch (mode) {
    case BlendMode::kReplace:
      return s;
    case BlendMode::kAlpha:
      return {blend_alpha(s.r, s.a, d.r), blend_alpha(s.g, s.a, d.g), blend_alpha(s.b, s.a, d.b),
              blend_alpha(s.a, s.a, d.a)};
    case BlendMode::kAdditive:
      return {blend_additive(s.r, s.a, d.r), blend_additive(s.g, s.a, d.g),
              blend_additive(s.b, s.a, d.b), blend_additive(s.a, s.a, d.a)};
  }
  return s;
}

Rgba8 apply_color_mask(uint8_t mask, Rgba8 blended, Rgba8 d) {
  return {(mask & kMaskR) ? blended.r : d.r, (mask & kMaskG) ? blended.g : d.g,
          (mask & kMaskB) ? blended.b : d.b, (mask & kMaskA) ? blended.a : d.a};
}

void GoldenRop::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color) {
  fb_ = Framebuffer(width, height, depth_bits, clear_color);
}

void GoldenRop::begin_pass(const RopState& state) {
  state_ = state;
  stats_ = PassStats{};
}

void GoldenRop::draw(const Fragment* fragments, size_t count) {
  for (size_t i = 0; i < count; ++i) process(fragments[i]);
}

PassStats GoldenRop::end_pass() { return stats_; }

// Stages as in the RTL: fetch the stored depth, test, fetch the destination colour, blend,
// mask, write. "If the depth test is disabled ... the depth buffer is not updated" (GL 4.6,
// 14.9.4): a disabled test passes every fragment and never writes depth.
void GoldenRop::process(const Fragment& f) {
  const size_t i = fb_.index(f.x, f.y);
  ++stats_.fragments_in;

  bool pass = true;
  if (state_.depth_test) {
    ++stats_.depth_reads;
    pass = depth_test(state_.depth_func, f.z, fb_.depth[i]);
  }
  if (!pass) return;
  ++stats_.fragments_passed;

  if (state_.depth_test && state_.depth_write) {
    fb_.depth[i] = f.z;
    ++stats_.depth_writes;
  }
  if (state_.color_mask == 0) return;

  const bool reads_dest = state_.blend != BlendMode::kReplace || state_.color_mask != kMaskRgba;
  if (reads_dest) ++stats_.color_reads;
  const Rgba8 d = fb_.color[i];
  fb_.color[i] = apply_color_mask(state_.color_mask, blend(state_.blend, f.color, d), d);
  ++stats_.color_writes;
}

}  // namespace zb
