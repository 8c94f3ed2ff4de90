// The interface between the rasterizer and the per-pixel datapath: the fragment and the
// pass state. docs/datapath.md documents every field bit by bit; the RTL mirrors them.
#pragma once

#include <cstdint>
#include <string>

#include "fixed.h"

namespace zb {

// One fragment, as the datapath receives it.
struct Fragment {
  uint16_t x = 0;      // pixel column, 0 = left
  uint16_t y = 0;      // pixel row, 0 = top
  uint32_t z = 0;      // window depth, unorm of the frame's depth width; 0 = near
  Rgba8 color;         // flat colour of the primitive, straight alpha
  bool front = true;   // facing of the primitive from its winding: culling
  bool facing = true;  // facing decided per vertex in the vertex stage, interpolated (raster.md)
  uint8_t coverage = 0;  // covered samples of the pixel, coverage-aa (raster.md "Coverage")
  uint32_t prim = 0;   // sideband: source primitive index, for debugging; not seen by the datapath
};

// The eight depth functions, encoded as GL's (GL_NEVER + code). The fragment passes when
// "incoming <func> stored" holds.
enum class DepthFunc : uint8_t {
  kNever = 0, kLess = 1, kEqual = 2, kLequal = 3,
  kGreater = 4, kNotequal = 5, kGequal = 6, kAlways = 7,
};

enum class BlendMode : uint8_t {
  kReplace = 0,   // colour = source
  kAlpha = 1,     // colour = min(255, m(s, a) + m(d, 255 - a)), every channel
  kAdditive = 2,  // colour = min(255, d + m(s, a)), every channel
};

// Colour write mask bits.
enum : uint8_t { kMaskR = 1, kMaskG = 2, kMaskB = 4, kMaskA = 8, kMaskRgba = 15 };

// The state the datapath holds during a pass: the registers loaded between passes.
struct RopState {
  bool depth_test = true;                 // off: every fragment passes and depth is never written
  DepthFunc depth_func = DepthFunc::kLess;
  bool depth_write = true;
  BlendMode blend = BlendMode::kReplace;
  uint8_t color_mask = kMaskRgba;         // kMask* bits; 0 = no colour writes
};

// Which primitives a pass draws. Decided by the feeder, before the datapath.
enum class PrimFilter : uint8_t { kOpaque, kTransparent, kAll };
// Which faces a pass discards (by winding). Decided by the feeder.
enum class Cull : uint8_t { kNone, kFront, kBack };

// One pass of a pass plan.
struct PassState {
  std::string name;
  PrimFilter filter = PrimFilter::kAll;
  Cull cull = Cull::kNone;
  RopState rop;
};

// The pass state register as the RTL receives it (docs/datapath.md, "The pass state"):
// [0] depth_test, [3:1] depth_func, [4] depth_write, [6:5] blend, [10:7] color_mask.
constexpr int kStateBits = 11;
uint16_t pack_state(const RopState& s);
// False when `bits` is not a valid state (bits above kStateBits set, or a reserved blend code).
bool unpack_state(uint16_t bits, RopState& out);

const char* to_string(DepthFunc f);
const char* to_string(BlendMode b);
const char* to_string(PrimFilter f);
const char* to_string(Cull c);

}  // namespace zb
