#include "rop.h"

#include "blend.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace zb {

namespace {

// A blend weighted by the source's alpha, `f(s, a, d)` on R, G, B and on alpha (s = a).
template <class F>
Rgba8 by_channel(F f, Rgba8 s, Rgba8 d) {
  return {f(s.r, s.a, d.r), f(s.g, s.a, d.g), f(s.b, s.a, d.b), f(s.a, s.a, d.a)};
}

}  // namespace

Rgba8 blend(BlendMode mode, Rgba8 s, Rgba8 d) {
  switch (mode) {
    case BlendMode::kReplace:
      return s;
    case BlendMode::kAlpha:
      return by_channel([](uint8_t x, uint8_t a, uint8_t y) { return blend_alpha(x, a, y); }, s, d);
    case BlendMode::kAdditive:
      return by_channel([](uint8_t x, uint8_t a, uint8_t y) { return blend_additive(x, a, y); }, s, d);
    case BlendMode::kCoverage:  // needs the depths and coverages: composite_coverage
    case BlendMode::kAccumulate:  // writes the accumulation planes: accumulate_wboit
    case BlendMode::kLayers:      // writes the layers: insert_layer
      return s;
    case BlendMode::kUnder:
      return {blend_under(s.r, s.a, d.r, d.a), blend_under(s.g, s.a, d.g, d.a),
              blend_under(s.b, s.a, d.b, d.a), blend_under_alpha(s.a, d.a)};
  }
  return s;
}

Rgba8 blend(const Arithmetic& r, BlendMode mode, Rgba8 s, Rgba8 d) {
  switch (mode) {
    case BlendMode::kAlpha:
      return by_channel([&r](uint8_t x, uint8_t a, uint8_t y) { return blend_alpha(r, x, a, y); }, s, d);
    case BlendMode::kAdditive:
      return by_channel([&r](uint8_t x, uint8_t a, uint8_t y) { return blend_additive(r, x, a, y); }, s, d);
    default:
      return blend(mode, s, d);
  }
}

namespace {

// w of the N samples from p, the rest from d, every channel (alpha too).
Rgba8 proportionate(Rgba8 p, Rgba8 d, uint32_t w, int n) {
  return {blend_coverage(p.r, d.r, w, n), blend_coverage(p.g, d.g, w, n),
          blend_coverage(p.b, d.b, w, n), blend_coverage(p.a, d.a, w, n)};
}

}  // namespace

// US 5,123,085, claim 1, "the step of compositing": the polygon pixel (z, p, k) onto the
// background pixel (zs, b, cs). The combined coverage is min(N, k + cs) in every case.
CoveragePixel composite_coverage(uint32_t z, Rgba8 p, int k, uint32_t zs, Rgba8 b, int cs,
                                 int n) {
  const int combined = std::min(n, k + cs);
  CoveragePixel out;
  if (z < zs) {
    // "if the depth value of the polygon pixel is less than ...: a first proportionate blend
    // ... dependent upon the extent of coverage of the polygon pixel"; depth of the polygon.
    out.color = proportionate(p, b, uint32_t(k), n);
    out.depth = z;
    out.coverage = uint8_t(combined);
  } else if (z > zs) {
    // "greater than ...: a second proportionate blend ... dependent upon the extent of
    // coverage of the background pixel"; the background keeps its cs samples and its depth.
    out.color = proportionate(b, p, uint32_t(cs), n);
    out.depth = zs;
    out.coverage = uint8_t(combined);
  } else if (k + cs >= n) {
    // "equal ... and the combination ... represents full coverage: the color of the polygon
    // pixel", full coverage.
    out.color = p;
    out.depth = zs;
    out.coverage = uint8_t(n);
  } else {
    // "equal ... does not indicate full coverage: the first proportionate blend".
    out.color = proportionate(p, b, uint32_t(k), n);
    out.depth = z;
    out.coverage = uint8_t(combined);
  }
  return out;
}

// The paper's terms C_i * w and a_i * w, with C_i = m(s, a) premultiplied and w = a * F(z).
std::array<uint32_t, 4> wboit_terms(uint32_t z, Rgba8 c, int depth_bits,
                                    const WboitFormat& format) {
  const uint32_t weight = c.a * wboit_depth_weight(z, depth_bits, format.weight_bits);
  const int shift = wboit_term_shift(format);
  const uint8_t p[4] = {mul_unorm8(c.r, c.a), mul_unorm8(c.g, c.a), mul_unorm8(c.b, c.a), c.a};
  std::array<uint32_t, 4> terms{};
  for (int ch = 0; ch < 4; ++ch) terms[size_t(ch)] = wboit_term(p[ch], weight, shift);
  return terms;
}

// The accumulation: the terms added, revealage times (1 - a_i).
WboitPixel accumulate_wboit(uint32_t z, Rgba8 c, const std::array<uint32_t, 4>& acc,
                            uint32_t reveal, int depth_bits, const WboitFormat& format) {
  const std::array<uint32_t, 4> terms = wboit_terms(z, c, depth_bits, format);
  WboitPixel out;
  for (size_t ch = 0; ch < 4; ++ch)
    out.acc[ch] = wboit_accumulate(acc[ch], terms[ch], format.acc_bits);
  out.reveal = wboit_reveal(reveal, c.a);
  return out;
}

bool same_stage_writes(bool x11, const PixelWrites& w, const PixelWrites& g) {
  if (!x11)
    return w.depth == g.depth && (!w.depth || w.z == g.z) && w.coverage == g.coverage &&
           (!w.coverage || w.cov == g.cov);
  return w.color == g.color && (!w.color || w.rgba == g.rgba) && w.accum == g.accum &&
         (!w.accum || (w.acc == g.acc && w.reveal == g.reveal)) && w.layers == g.layers &&
         (!w.layers || w.lay == g.lay);
}

Rgba8 resolve_coverage(Rgba8 stored, int /*coverage*/, int /*n*/) { return stored; }

Rgba8 apply_color_mask(uint8_t mask, Rgba8 blended, Rgba8 d) {
  return {(mask & kMaskR) ? blended.r : d.r, (mask & kMaskG) ? blended.g : d.g,
          (mask & kMaskB) ? blended.b : d.b, (mask & kMaskA) ? blended.a : d.a};
}

void GoldenRop::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                            int coverage_samples, const WboitFormat& wboit) {
  if (!valid_coverage_samples(coverage_samples))
    throw std::invalid_argument("golden: coverage samples " + std::to_string(coverage_samples) +
                                " is not a power of two from 1 to " +
                                std::to_string(kMaxCoverageSamples));
  if (!valid_wboit_format(wboit))
    throw std::invalid_argument(
        "golden: accumulation " + std::to_string(wboit.acc_bits) + " bits, revealage " +
        std::to_string(wboit.rev_bits) + " bits, weight " + std::to_string(wboit.weight_bits) +
        " bits: out of range (accumulation " + std::to_string(kMinAccBits) + ".." +
        std::to_string(kMaxAccBits) + ", revealage " + std::to_string(kMinRevBits) + ".." +
        std::to_string(kMaxRevBits) + ", weight " + std::to_string(kMinWeightBits) + ".." +
        std::to_string(kMaxWeightBits) + ")");
  fb_ = Framebuffer(width, height, depth_bits, clear_color, coverage_samples, wboit);
}

void GoldenRop::begin_pass(const RopState& state) {
  if (state.blend == BlendMode::kLayers && (state.layers < 1 || state.layers > kMaxLayers))
    throw std::invalid_argument("golden: " + std::to_string(state.layers) +
                                " layers a pixel: out of range (1.." +
                                std::to_string(kMaxLayers) + ")");
  state_ = state;
  stats_ = PassStats{};
}

void GoldenRop::draw(const Fragment* fragments, size_t count) {
  for (size_t i = 0; i < count; ++i) run<false>(fragments[i], nullptr);
}

PassStats GoldenRop::end_pass() { return stats_; }

void GoldenRop::frame_op(const FrameOp& op) { apply_frame_op(fb_, op); }

PixelWrites GoldenRop::process(const Fragment& f) {
  PixelWrites w;
  run<true>(f, &w);
  return w;
}

// Stages as in the RTL: fetch the stored depth, test, fetch the destination colour, blend,
// mask, write. "If the depth test is disabled ... the depth buffer is not updated" (GL 4.6,
// 14.9.4): a disabled test passes every fragment and never writes depth. With kLog the writes
// go to *w; draw() runs without it, so the frame's loop builds no write log.
template <bool kLog>
void GoldenRop::run(const Fragment& f, PixelWrites* w) {
  if (state_.blend == BlendMode::kCoverage) return run_coverage<kLog>(f, w);
  const size_t i = fb_.index(f.x, f.y);
  ++stats_.fragments_in;

  bool pass = true;
  if (state_.depth_test) {
    ++stats_.depth_reads;
    pass = depth_test(state_.depth_func, f.z, fb_.depth[i]);
  }
  // Peel test: the second compare, strictly behind the previous layer (z > peel).
  if (state_.peel_test && !(f.z > fb_.peel[i])) pass = false;
  if (!pass) return;
  ++stats_.fragments_passed;

  if (state_.depth_test && state_.depth_write) {
    fb_.depth[i] = f.z;
    if constexpr (kLog) w->z = f.z, w->depth = true;
    ++stats_.depth_writes;
  }
  if (state_.color_mask == 0) return;

  const bool reads_dest = state_.blend != BlendMode::kReplace || state_.color_mask != kMaskRgba;
  if (reads_dest) ++stats_.color_reads;
  ++stats_.color_writes;
  if (state_.blend == BlendMode::kAccumulate) {
    // The accumulation word is read and written whole; the colour plane is kept.
    fb_.touch_accum();
    const WboitPixel p =
        accumulate_wboit(f.z, f.color, fb_.accum[i], fb_.reveal[i], fb_.depth_bits, fb_.wboit);
    fb_.accum[i] = p.acc;
    fb_.reveal[i] = p.reveal;
    if constexpr (kLog) w->acc = p.acc, w->reveal = p.reveal, w->accum = true;
    return;
  }
  if (state_.blend == BlendMode::kLayers) {
    // The layers word is read and written whole (an alpha of 0 writes it back unchanged).
    fb_.touch_layers();
    const int at = insert_layer(fb_.layers[i], state_.layers, fragment_layer(f.z, f.color));
    if constexpr (kLog) w->layer_at = at, w->lay = fb_.layers[i], w->layers = true;
    return;
  }
  const Rgba8 d = fb_.color[i];
  const Rgba8 b = declared_ ? blend(arith_, state_.blend, f.color, d) : blend(state_.blend, f.color, d);
  fb_.color[i] = apply_color_mask(state_.color_mask, b, d);
  if constexpr (kLog) w->rgba = fb_.color[i], w->color = true;
}

// Coverage mode (datapath.md "Coverage blend"): the depth unit compares three ways instead of
// testing, so every fragment passes and is composited; depth is written (when depth_test and
// depth_write) only in the nearer case; coverage always; colour under the write mask.
template <bool kLog>
void GoldenRop::run_coverage(const Fragment& f, PixelWrites* w) {
  if (f.coverage > fb_.coverage_samples)
    throw std::invalid_argument("golden: fragment coverage " + std::to_string(f.coverage) +
                                " exceeds the " + std::to_string(fb_.coverage_samples) +
                                " samples of the frame");
  const size_t i = fb_.index(f.x, f.y);
  ++stats_.fragments_in;
  ++stats_.fragments_passed;
  ++stats_.depth_reads;
  const CoveragePixel c = composite_coverage(f.z, f.color, f.coverage, fb_.depth[i],
                                             fb_.color[i], fb_.coverage[i],
                                             fb_.coverage_samples);
  if (state_.depth_test && state_.depth_write && c.depth != fb_.depth[i]) {
    fb_.depth[i] = c.depth;
    if constexpr (kLog) w->z = c.depth, w->depth = true;
    ++stats_.depth_writes;
  }
  fb_.coverage[i] = c.coverage;
  if constexpr (kLog) w->cov = c.coverage, w->coverage = true;
  if (state_.color_mask == 0) return;
  ++stats_.color_reads;
  fb_.color[i] = apply_color_mask(state_.color_mask, c.color, fb_.color[i]);
  if constexpr (kLog) w->rgba = fb_.color[i], w->color = true;
  ++stats_.color_writes;
}

}  // namespace zb
