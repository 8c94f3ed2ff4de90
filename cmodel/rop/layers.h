// K layers a pixel, for one-pass transparency (mlab-K; docs/datapath.md "8. Layers"): each
// transparent fragment inserted by depth into the pixel's sorted layers, the two farthest
// merged when a K+1-th arrives, and a front-to-back resolve over the opaque colour. The golden
// model's unit; its pass plan, the RTL unit and the kit follow (issue 60).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "fixed.h"

namespace zb {

constexpr int kMaxLayers = 8;

// A layer: its depth, its colour premultiplied by its alpha (R, G, B) and its alpha (A).
struct Layer {
  uint32_t z = 0;
  Rgba8 p;
  bool operator==(const Layer& o) const { return z == o.z && p == o.p; }
};

// The order the layers are kept in: nearer first; at equal depth by the colour word (A, R, G, B
// as one number), so the same fragments give the same layers in any submit order.
bool layer_before(const Layer& a, const Layer& b);

// A fragment's layer: p = m(s, a) per colour channel, A = a.
Layer fragment_layer(uint32_t z, Rgba8 s);

// `front` over `back` as one layer: min(255, p_f + m(p_b, 255 - A_f)) per channel, alpha
// min(255, A_f + m(A_b, 255 - A_f)), the front's depth.
Layer merge_layers(const Layer& front, const Layer& back);

// A pixel's layers, nearest first; n of at most k used.
struct PixelLayers {
  std::array<Layer, kMaxLayers> layer{};
  int n = 0;
  // Equal layers in use, and every slot beyond them as well (empty: zero).
  bool operator==(const PixelLayers& o) const { return n == o.n && layer == o.layer; }
  bool operator!=(const PixelLayers& o) const { return !(*this == o); }
};

// "2 layers: z 0x0f4240 p(12,200,3) a 120; z ..." ("no layers"), depths in depth_bits' hex digits.
std::string layers_text(const PixelLayers& px, int depth_bits);

// Where `f` goes among `px`'s layers: after every layer whose key is at most its own.
int layer_position(const PixelLayers& px, const Layer& f);

// In a pixel `px` holding k layers, the two farthest of the k + 1 once `f` joins at `at`
// (layer_position): the front and the back of their merge.
std::pair<Layer, Layer> farthest_two(const PixelLayers& px, int k, const Layer& f, int at);

// Inserts `f` (alpha above 0; an alpha of 0 changes nothing) into `px`, which holds at most k
// (1..kMaxLayers) layers: at its place in layer_before's order; with k layers already, the two
// farthest of the k + 1 are merged (merge_layers). Returns the position it went to (k: merged
// into the last).
int insert_layer(PixelLayers& px, int k, const Layer& f);

// One step of the resolve's chain: `p` (premultiplied, alpha A) under `acc`, t = 255 - acc_A:
// min(255, acc_c + m(p_c, t)) every channel.
Rgba8 layer_under(Rgba8 acc, Rgba8 p);

// The layers front to back over the opaque colour: the under blend's chain ("6. Under blend")
// from (0, 0, 0, 0), then over `opaque` as the resolve under does. With no layer, `opaque`.
Rgba8 resolve_layers(const PixelLayers& px, Rgba8 opaque);

}  // namespace zb
