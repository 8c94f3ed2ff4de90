// Perceptual colour difference: CIEDE2000 between sRGB colours.
#pragma once

#include <cstdint>

#include "rop/fixed.h"

namespace zb {

// CIE 1976 L*a*b*, relative to the D65 white of sRGB.
struct Lab {
  double L = 0;
  double a = 0;
  double b = 0;
};

// An 8-bit sRGB channel to linear light in [0, 1] (IEC 61966-2-1 transfer curve).
double srgb8_to_linear(uint8_t v);

// An sRGB colour (alpha ignored) to CIELAB: sRGB curve, linear RGB to XYZ with the sRGB
// primaries, then CIELAB against the D65 white that RGB (1, 1, 1) maps to.
Lab srgb8_to_lab(Rgba8 c);

// The inverse: CIELAB to 8-bit sRGB (rounded); false when the colour lies outside the sRGB
// gamut (a channel beyond 0..1 in linear light, by more than rounding).
bool lab_to_srgb8(const Lab& lab, Rgba8& out);

// CIEDE2000 colour difference (CIE 142-2001) with kL = kC = kH = 1, as written out by Sharma,
// Wu and Dalal (2005), including their rules for hue angle and mean hue.
double ciede2000(const Lab& x, const Lab& y);

// CIEDE2000 between two sRGB colours; 0 when their RGB is equal.
double delta_e2000(Rgba8 x, Rgba8 y);

}  // namespace zb
