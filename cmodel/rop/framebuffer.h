// The pixel buffers a frame renders into: colour RGBA8, depth and coverage, row-major, row 0 at
// the top.
#pragma once

#include <cstddef>
#include <array>
#include <cstdint>
#include <vector>

#include "blend.h"
#include "fixed.h"
#include "layers.h"

namespace zb {

struct Framebuffer {
  int width = 0;
  int height = 0;
  int depth_bits = kDefaultDepthBits;
  int coverage_samples = kDefaultCoverageSamples;  // N of the sample pattern
  std::vector<Rgba8> color;
  std::vector<uint32_t> depth;
  // Covered samples per pixel, 0..N (coverage_bits(N) wide in hardware); cleared to 0 with the
  // frame, written only by coverage passes (docs/datapath.md "Coverage blend").
  std::vector<uint8_t> coverage;
  // Peel depth plane (depth peeling, docs/datapath.md "Peel test"): read-only during a pass,
  // written only by the frame operation CopyDepthToPeel; cleared to 0 with the frame.
  std::vector<uint32_t> peel;
  // Weighted blended OIT (docs/datapath.md "7. Accumulate blend"): per pixel four
  // accumulation channels (R, G, B, A; wboit.acc_bits wide, cleared to 0) and the revealage
  // (wboit.rev_bits unorm, cleared to 1.0); written only by accumulate passes. Allocated by
  // the first write (touch_accum): a frame that never accumulates holds none, 20 B a pixel
  // less. Read them through accum_at and reveal_at.
  WboitFormat wboit;
  std::vector<std::array<uint32_t, 4>> accum;
  std::vector<uint32_t> reveal;
  // mlab-K's layers (docs/datapath.md "8. Layers"), per pixel, nearest first; written only by
  // layers passes and emptied by their resolve (ResolveLayers). Allocated by the first write
  // (touch_layers), as the accumulation is. Read them through layers_at.
  std::vector<PixelLayers> layers;

  Framebuffer() = default;
  Framebuffer(int w, int h, int bits, Rgba8 clear_color,
              int samples = kDefaultCoverageSamples, WboitFormat wb = {})
      : width(w), height(h), depth_bits(bits), coverage_samples(samples),
        color(static_cast<size_t>(w) * h, clear_color),
        depth(static_cast<size_t>(w) * h, depth_max(bits)),
        coverage(static_cast<size_t>(w) * h, 0),
        peel(static_cast<size_t>(w) * h, 0),
        wboit(wb) {}

  // The accumulation planes, allocated at their clear values if they were not.
  void touch_accum() {
    if (!accum.empty()) return;
    accum.assign(static_cast<size_t>(width) * height, std::array<uint32_t, 4>{});
    reveal.assign(static_cast<size_t>(width) * height, wboit_reveal_one(wboit.rev_bits));
  }

  void touch_layers() {
    if (layers.empty()) layers.assign(static_cast<size_t>(width) * height, PixelLayers{});
  }

  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
  Rgba8 color_at(int x, int y) const { return color[index(x, y)]; }
  uint32_t depth_at(int x, int y) const { return depth[index(x, y)]; }
  int coverage_at(int x, int y) const { return coverage[index(x, y)]; }
  uint32_t peel_at(int x, int y) const { return peel[index(x, y)]; }
  std::array<uint32_t, 4> accum_at(size_t i) const {
    return accum.empty() ? std::array<uint32_t, 4>{} : accum[i];
  }
  uint32_t reveal_at(size_t i) const {
    return reveal.empty() ? wboit_reveal_one(wboit.rev_bits) : reveal[i];
  }
  PixelLayers layers_at(size_t i) const { return layers.empty() ? PixelLayers{} : layers[i]; }
};

}  // namespace zb
