// Test helpers: full-frame layers at constant depth, and blend arithmetic written
// independently of the code under test.
#pragma once

#include <algorithm>
#include <vector>

#include "pipeline/render.h"

namespace zbtest {

// docs/datapath.md's m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x*y, written with divisions.
inline uint32_t m_spec(uint32_t x, uint32_t y) { return (x * y + x * y / 256 + 128) / 256; }

// Source-over with straight alpha, every channel (docs/datapath.md "3. Blend").
inline zb::Rgba8 over(zb::Rgba8 s, zb::Rgba8 d) {
  auto ch = [&](uint32_t sc, uint32_t dc) {
    return uint8_t(std::min(255u, m_spec(sc, s.a) + m_spec(dc, 255u - s.a)));
  };
  return {ch(s.r, d.r), ch(s.g, d.g), ch(s.b, d.b), ch(s.a, d.a)};
}

inline uint32_t sat(uint32_t v) { return std::min(255u, v); }

struct Layer {
  uint32_t z;
  zb::Rgba8 color;
};

// The methods' tests' pixel: a background, an opaque layer, and n transparent layers at distinct
// depths in front of it, each its own colour and alpha.
const zb::Rgba8 kBackground{250, 250, 240, 255};
const Layer kOpaque{12000000, {40, 60, 200, 255}};
inline std::vector<Layer> make_layers(int n) {
  std::vector<Layer> out;
  for (int i = 0; i < n; ++i)
    out.push_back({uint32_t(1000000 + 1000000 * i),
                   {uint8_t(37 * i + 200), uint8_t(91 * i + 20), uint8_t(53 * i + 110),
                    uint8_t(70 + 17 * i)}});
  return out;
}

constexpr int kSize = 4;

// One triangle per layer, each covering the whole kSize x kSize frame at constant depth, in
// the given order.
inline zb::RasterizedScene layer_scene(const std::vector<Layer>& layers, zb::Rgba8 background) {
  std::vector<zb::ScreenTriangle> tris;
  for (const Layer& l : layers) {
    zb::ScreenTriangle t;
    const int32_t far = 2 * kSize * zb::kSubpixelOne;
    t.v[0] = {0, 0, l.z, 0.0};
    t.v[1] = {far, 0, l.z, 0.0};
    t.v[2] = {0, far, l.z, 0.0};
    for (auto& v : t.v) v.z_exact = double(l.z) / zb::depth_max(zb::kDefaultDepthBits);
    t.color = l.color;
    t.transparent = l.color.a < 255;
    t.prim = uint32_t(tris.size());
    tris.push_back(t);
  }
  return zb::rasterize_triangles(std::move(tris), {kSize, kSize, zb::kDefaultDepthBits},
                                 background);
}

}  // namespace zbtest
