// The suite's generated streams (suite version 6): each family aimed at goals of the reach
// (reach.h) that scenes and random streams meet by chance or not at all. Every stream is drawn
// from a fixed seed; the export measures the reach and refuses a suite that leaves a goal of
// its defaults unhit.
#pragma once

#include <cstdint>

#include "io/trace.h"

namespace zb::conformance {

// Every pass state of one blend mode and peel setting (9 depth settings x depth write x 16
// masks = 288 passes), each meeting a stored depth below, equal to and above its fragment's on a
// pixel of its own, with stored and fragment values drawn so that the blend, the mask and the
// depth write show in the planes (reach.h `visible`); with the peel test, the fragment behind the
// peel plane where it is less or greater, not behind where equal.
Trace states_trace(BlendMode blend, bool peel, int depth_bits, int samples);

// Depth pairs that differ in exactly one bit, at every bit of the width, both ways, under the six
// ordering and equality functions; then the corners 0, 1, max - 1, max against each other.
Trace depth_bits_trace(int depth_bits, int samples);

// Each channel at 0, 1, 127, 128, 254 and 255 under each of the 16 masks, in one colour blend
// (replace, alpha, additive or under), stored values drawn so that every channel changes.
Trace values_trace(BlendMode blend, int depth_bits, int samples);

// The coverage blend at the corners 0, 1, N - 1, N of the fragment's count and the stored one,
// nearer, equal and behind.
Trace coverage_values_trace(int depth_bits, int samples);

// Accumulation corners: sums driven to saturation in every channel, alpha at its corners, a
// resolve at the end.
Trace accumulate_values_trace(int depth_bits, int samples);

// A 192 x 192 frame (whole tiles of 16, 32 and 64), fragments at each tile's corners, edge
// middles and inside, at every tile of each size: every origin, the last pixel of every tile.
Trace tiles_trace(int depth_bits, int samples);

// Same-pixel runs at distances 1 to 16 (a run cycling over k pixels) in one read-modify-write
// blend; with kAlpha a second pass of replace under lequal with depth write, nearer each round
// (the depth plane's own read-modify-write).
Trace same_pixel_trace(BlendMode blend, int depth_bits, int samples);

// The most layers a pixel the kit's tests keep (mlab-K's K): zb_rop's LAYERS in its adapter
// (conformance/sv/zb_conf_adapter.sv) and the reference DUT's, so the plan's layers bins too.
constexpr int kKitLayers = 4;

// Layers mode (suite version 7) at K = 1 to kKitLayers, each case on a pixel of its own, spread
// over every tile of each size: a fragment at every position among 0 to K layers (full: the
// merge there), at a layer's depth with a smaller, a larger and the same colour word, the same
// fragments in every order, long runs of merges with high alphas and alpha 0, layers behind and
// in front of an opaque surface; then passes with the colour mask 0, a partial mask with depth
// written, the depth test off. Each layers pass resolved (frame operation 5) before the next.
Trace layers_trace(int depth_bits, int samples);

}  // namespace zb::conformance
