// The host side shared by every backend: counters summed, frame operations and region loads
// applied.
#include "backend.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "blend.h"

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

void check_region_load(const Framebuffer& fb, const RegionLoad& r) {
  const size_t n = size_t(std::max(r.width, 0)) * size_t(std::max(r.height, 0));
  if (r.x0 < 0 || r.y0 < 0 || r.width < 1 || r.height < 1 || r.x0 + r.width > fb.width ||
      r.y0 + r.height > fb.height)
    throw std::invalid_argument(fmt::format("region load: {}x{} at ({}, {}) is not inside the {}x{} frame",
                                            r.width, r.height, r.x0, r.y0, fb.width, fb.height));
  if (r.color.size() != n || (!r.depth.empty() && r.depth.size() != n))
    throw std::invalid_argument("region load: the planes' sizes are not the region's");
  for (const uint32_t d : r.depth)
    if (d > depth_max(fb.depth_bits))
      throw std::invalid_argument(fmt::format("region load: depth 0x{:x} exceeds {} bits", d, fb.depth_bits));
}

void apply_region_load(Framebuffer& fb, const RegionLoad& r) {
  check_region_load(fb, r);
  for (int y = 0; y < r.height; ++y) {
    const size_t from = size_t(y) * size_t(r.width), to = fb.index(r.x0, r.y0 + y);
    std::copy_n(r.color.begin() + std::ptrdiff_t(from), r.width, fb.color.begin() + std::ptrdiff_t(to));
    if (!r.depth.empty())
      std::copy_n(r.depth.begin() + std::ptrdiff_t(from), r.width, fb.depth.begin() + std::ptrdiff_t(to));
  }
}

void Backend::load_region(const RegionLoad&) {
  throw std::logic_error(fmt::format("{} backend: no region loads", name()));
}

void apply_frame_op(Framebuffer& fb, const FrameOp& op) {
  switch (op.kind) {
    case FrameOpKind::kClearColor:
      std::fill(fb.color.begin(), fb.color.end(), op.value);
      return;
    case FrameOpKind::kClearDepth:
      std::fill(fb.depth.begin(), fb.depth.end(), std::min(op.depth, depth_max(fb.depth_bits)));
      return;
    case FrameOpKind::kCopyDepthToPeel:
      fb.peel = fb.depth;
      return;
    case FrameOpKind::kResolveUnder:
      for (Rgba8& c : fb.color)
        c = {resolve_under(c.r, op.value.r, c.a), resolve_under(c.g, op.value.g, c.a),
             resolve_under(c.b, op.value.b, c.a), resolve_under(c.a, op.value.a, c.a)};
      return;
    case FrameOpKind::kResolveWboit: {
      const uint32_t one = wboit_reveal_one(fb.wboit.rev_bits);
      for (size_t i = 0; i < fb.color.size(); ++i)
        fb.color[i] = resolve_wboit(fb.color[i], fb.accum_at(i), fb.reveal_at(i), one);
      return;
    }
    case FrameOpKind::kResolveLayers:
      for (size_t i = 0; i < fb.layers.size(); ++i) fb.color[i] = resolve_layers(fb.layers[i], fb.color[i]);
      fb.layers.clear();
      fb.layers.shrink_to_fit();
      return;
  }
  throw std::invalid_argument("frame op: unknown kind " + std::to_string(unsigned(op.kind)));
}

const char* to_string(FrameOpKind k) {
  switch (k) {
    case FrameOpKind::kClearColor: return "clear-color";
    case FrameOpKind::kClearDepth: return "clear-depth";
    case FrameOpKind::kCopyDepthToPeel: return "copy-depth-to-peel";
    case FrameOpKind::kResolveUnder: return "resolve-under";
    case FrameOpKind::kResolveWboit: return "resolve-wboit";
    case FrameOpKind::kResolveLayers: return "resolve-layers";
  }
  return "?";
}

}  // namespace zb
