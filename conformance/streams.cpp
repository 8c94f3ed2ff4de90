#include "streams.h"

#include <algorithm>
#include <string>
#include <vector>

#include "rtl_params.h"
#include "stimulus.h"

namespace zb::conformance {

uint8_t coverage_for_samples(int count, int from, int to) {
  if (count <= 0) return 0;
  if (count >= from) return uint8_t(to);
  const int scaled = (count * to * 2 + from) / (from * 2);  // round half up
  return uint8_t(to >= 2 ? std::clamp(scaled, 1, to - 1) : scaled);
}

Trace hazard_trace(uint64_t seed, int coverage_samples, int passes, size_t per_pass) {
  tb::HazardStimulus stim(seed);
  Trace t;
  t.width = kRtlTileW;
  t.height = kRtlTileH;
  t.depth_bits = 24;  // the stimulus draws 24-bit depths
  t.coverage_samples = coverage_samples;
  t.clear_color = Rgba8{10, 20, 30, 40};  // the hazard suite's
  for (int p = 0; p < passes; ++p) {
    // The suite's order: the state, then its fragments.
    TracePass pass{"hazard-" + std::to_string(p + 1), {}, stim.next_state(), {}};
    pass.fragments = stim.next_fragments(per_pass);
    for (Fragment& f : pass.fragments)
      f.coverage = coverage_for_samples(f.coverage, kRtlCoverageSamples, coverage_samples);
    t.passes.push_back(std::move(pass));
  }
  return t;
}

namespace {

// The random stream's draws: edge values of each field about half the time.
class RandomStream {
 public:
  RandomStream(uint64_t seed, int width, int height, int depth_bits, int samples, RandomMix mix)
      : rng_(seed), w_(width), h_(height), zmax_(depth_max(depth_bits)), n_(samples), mix_(mix) {
    for (uint32_t& z : zpool_) z = depth();
  }

  RopState state() {
    RopState s;
    s.depth_test = !rng_.chance(0.15);
    s.depth_func = DepthFunc(rng_.below(8));
    s.depth_write = rng_.chance(0.6);
    s.blend = BlendMode(rng_.below(kCoreBlendModes));
    s.color_mask = rng_.chance(0.5) ? uint8_t(kMaskRgba) : uint8_t(rng_.below(16));
    s.peel_test = rng_.chance(0.3);
    if (mix_ == RandomMix::kWboit && rng_.chance(0.5)) s.blend = BlendMode::kAccumulate;
    if (mix_ == RandomMix::kCore) {  // drawn after the others: their draws stay as they were
      s.blend = rng_.chance(0.5) ? BlendMode::kReplace : BlendMode::kAlpha;
      s.peel_test = false;
    }
    return s;
  }

  // Before a pass, or after the last: peel copies, depth and colour clears, resolves.
  std::vector<FrameOp> frame_ops() {
    std::vector<FrameOp> ops;
    if (rng_.chance(0.4)) ops.push_back({FrameOpKind::kCopyDepthToPeel, {}, 0, false});
    if (rng_.chance(0.25)) ops.push_back({FrameOpKind::kClearDepth, {}, depth(), false});
    if (rng_.chance(0.15)) ops.push_back({FrameOpKind::kClearColor, color(), 0, false});
    if (rng_.chance(0.15)) ops.push_back({FrameOpKind::kResolveUnder, color(), 0, false});
    if (mix_ == RandomMix::kWboit && rng_.chance(0.2)) ops.push_back({FrameOpKind::kResolveWboit, {}, 0, false});
    return ops;
  }

  std::vector<Fragment> fragments(size_t count) {
    std::vector<Fragment> out(count);
    size_t run = 0;  // fragments left in the current run on a few pixels
    std::vector<std::pair<int, int>> hot;
    for (Fragment& f : out) {
      if (run == 0 && rng_.chance(0.05)) {
        hot.clear();
        const int x = int(rng_.below(uint32_t(w_))), y = int(rng_.below(uint32_t(h_)));
        for (uint32_t k = 1 + rng_.below(4); k > 0; --k) {
          // Neighbours; one draw per statement, so every compiler draws them in this order.
          const int hx = std::min(w_ - 1, x + int(rng_.below(2)));
          const int hy = std::min(h_ - 1, y + int(rng_.below(2)));
          hot.emplace_back(hx, hy);
        }
        run = 4 + rng_.below(40);
      }
      if (run > 0) {
        --run;
        const auto& p = hot[rng_.below(uint32_t(hot.size()))];
        f.x = uint16_t(p.first);
        f.y = uint16_t(p.second);
      } else {
        f.x = uint16_t(rng_.below(uint32_t(w_)));
        f.y = uint16_t(rng_.below(uint32_t(h_)));
      }
      f.z = rng_.chance(0.3) ? zpool_[rng_.below(kPool)] : depth();
      if (rng_.chance(0.05)) zpool_[rng_.below(kPool)] = f.z;
      f.color = color();
      f.front = rng_.chance(0.5);
      const uint8_t edges[] = {0, 1, uint8_t(n_ - 1), uint8_t(n_)};
      f.coverage = rng_.chance(0.5) ? edges[rng_.below(4)] : uint8_t(rng_.below(uint32_t(n_) + 1));
    }
    return out;
  }

  Rgba8 color() {
    const uint8_t alphas[] = {0, 1, 254, 255};
    const uint8_t a = rng_.chance(0.5) ? alphas[rng_.below(4)] : channel();
    return {channel(), channel(), channel(), a};
  }

 private:
  static constexpr uint32_t kPool = 6;

  uint32_t depth() {
    switch (rng_.below(6)) {
      case 0: return 0;
      case 1: return zmax_;
      case 2: return zmax_ - 1;
      default: return uint32_t(rng_.next()) & zmax_;  // zmax_ is 2^bits - 1: uniform
    }
  }
  uint8_t channel() {
    if (rng_.chance(0.2)) return rng_.chance(0.5) ? 0 : 255;
    return uint8_t(rng_.below(256));
  }

  tb::Rng rng_;
  int w_, h_;
  uint32_t zmax_;
  int n_;
  RandomMix mix_;
  uint32_t zpool_[kPool] = {};
};

}  // namespace

Trace random_trace(uint64_t seed, int width, int height, int depth_bits, int coverage_samples,
                   int passes, size_t per_pass, RandomMix mix) {
  RandomStream r(seed, width, height, depth_bits, coverage_samples, mix);
  Trace t;
  t.width = width;
  t.height = height;
  t.depth_bits = depth_bits;
  t.coverage_samples = coverage_samples;
  t.clear_color = r.color();
  for (int p = 0; p < passes; ++p) {
    TracePass pass{"random-" + std::to_string(p + 1), r.frame_ops(), r.state(), {}};
    pass.fragments = r.fragments(per_pass);
    t.passes.push_back(std::move(pass));
  }
  t.final_ops = r.frame_ops();
  return t;
}

}  // namespace zb::conformance
