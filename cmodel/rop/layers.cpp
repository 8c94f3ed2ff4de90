#include "layers.h"

#include <stdexcept>

#include <fmt/core.h>

#include "blend.h"

namespace zb {

namespace {

uint32_t colour_word(Rgba8 c) {
  return uint32_t{c.a} << 24 | uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b;
}

uint8_t sat_add(uint8_t x, uint8_t y) {
  const uint32_t v = uint32_t{x} + y;
  return static_cast<uint8_t>(v > 255u ? 255u : v);
}

}  // namespace

bool layer_before(const Layer& a, const Layer& b) {
  return a.z != b.z ? a.z < b.z : colour_word(a.p) < colour_word(b.p);
}

Layer fragment_layer(uint32_t z, Rgba8 s) {
  return {z, Rgba8{mul_unorm8(s.r, s.a), mul_unorm8(s.g, s.a), mul_unorm8(s.b, s.a), s.a}};
}

Layer merge_layers(const Layer& front, const Layer& back) {
  const uint8_t t = static_cast<uint8_t>(255 - front.p.a);
  return {front.z, Rgba8{sat_add(front.p.r, mul_unorm8(back.p.r, t)),
                         sat_add(front.p.g, mul_unorm8(back.p.g, t)),
                         sat_add(front.p.b, mul_unorm8(back.p.b, t)),
                         sat_add(front.p.a, mul_unorm8(back.p.a, t))}};
}

int layer_position(const PixelLayers& px, const Layer& f) {
  int at = 0;
  while (at < px.n && !layer_before(f, px.layer[size_t(at)])) ++at;
  return at;
}

std::pair<Layer, Layer> farthest_two(const PixelLayers& px, int k, const Layer& f, int at) {
  const Layer& last = px.layer[size_t(k - 1)];
  if (at == k) return {last, f};
  return {at == k - 1 ? f : px.layer[size_t(k - 2)], last};
}

int insert_layer(PixelLayers& px, int k, const Layer& f) {
  if (k < 1 || k > kMaxLayers || px.n < 0 || px.n > k)
    throw std::invalid_argument("insert_layer: k or the layer count out of range");
  if (f.p.a == 0) return -1;
  const int at = layer_position(px, f);
  if (px.n < k) {
    for (int i = px.n; i > at; --i) px.layer[size_t(i)] = px.layer[size_t(i - 1)];
    px.layer[size_t(at)] = f;
    ++px.n;
    return at;
  }
  // k + 1 layers: the new one at `at`, the two farthest merged into slot k - 1.
  const auto [front, back] = farthest_two(px, k, f, at);
  for (int i = k - 1; i > at; --i) px.layer[size_t(i)] = px.layer[size_t(i - 1)];
  if (at < k) px.layer[size_t(at)] = f;
  px.layer[size_t(k - 1)] = merge_layers(front, back);
  return at;
}

std::string layers_text(const PixelLayers& px, int depth_bits) {
  if (px.n == 0) return "no layers";
  std::string s = fmt::format("{} layer{}:", px.n, px.n == 1 ? "" : "s");
  const int zd = (depth_bits + 3) / 4;
  for (int i = 0; i < px.n; ++i) {
    const Layer& l = px.layer[size_t(i)];
    s += fmt::format("{} z 0x{:0{}x} p({},{},{}) a {}", i ? ";" : "", l.z, zd, l.p.r, l.p.g, l.p.b,
                     l.p.a);
  }
  return s;
}

Rgba8 layer_under(Rgba8 acc, Rgba8 p) {
  const uint8_t t = static_cast<uint8_t>(255 - acc.a);
  return Rgba8{sat_add(acc.r, mul_unorm8(p.r, t)), sat_add(acc.g, mul_unorm8(p.g, t)),
               sat_add(acc.b, mul_unorm8(p.b, t)), sat_add(acc.a, mul_unorm8(p.a, t))};
}

Rgba8 resolve_layers(const PixelLayers& px, Rgba8 opaque) {
  Rgba8 acc{0, 0, 0, 0};
  for (int i = 0; i < px.n; ++i) acc = layer_under(acc, px.layer[size_t(i)].p);
  return Rgba8{resolve_under(acc.r, opaque.r, acc.a), resolve_under(acc.g, opaque.g, acc.a),
               resolve_under(acc.b, opaque.b, acc.a), resolve_under(acc.a, opaque.a, acc.a)};
}

}  // namespace zb
