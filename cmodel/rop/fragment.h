// The interface between the rasterizer and the per-pixel datapath: the fragment and the
// pass state. docs/datapath.md documents every field bit by bit; the RTL mirrors them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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
  kCoverage = 3,  // US 5,123,085: the four depth cases on colour, depth and coverage
                  // (docs/datapath.md "Coverage blend"); a coverage pass (raster.md "Coverage")
  kUnder = 4,     // front-to-back into a premultiplied colour plane (depth peeling), t = 255 - A_d:
                  // C' = min(255, C_d + m(m(s, a), t)) per RGB, A' = min(255, A_d + m(a, t))
  kAccumulate = 5,  // weighted blended OIT into the accumulation and revealage planes
                    // (docs/datapath.md "7. Accumulate blend"); the colour plane is kept
  kLayers = 6,      // mlab-K: inserted into the pixel's K layers (docs/datapath.md "8. Layers");
                    // the colour plane is kept
};
constexpr unsigned kBlendModes = 7;
// The blends before layers (replace .. accumulate): the random stimulus, the states suites and
// the kit's core draw from these; layers, a unit of its own (off in some builds, a feature of
// the kit's profile), has its own tests.
constexpr unsigned kCoreBlendModes = 6;

// Colour write mask bits.
enum : uint8_t { kMaskR = 1, kMaskG = 2, kMaskB = 4, kMaskA = 8, kMaskRgba = 15 };

// The state the datapath holds during a pass: the registers loaded between passes.
struct RopState {
  bool depth_test = true;                 // off: every fragment passes and depth is never written
  DepthFunc depth_func = DepthFunc::kLess;
  bool depth_write = true;
  BlendMode blend = BlendMode::kReplace;  // kCoverage: depth_func is not used (datapath.md)
  uint8_t color_mask = kMaskRgba;         // kMask* bits; 0 = no colour writes
  // Second depth compare (depth peeling): the fragment passes only if also z > peel[x, y],
  // the frame's peel plane (read-only during a pass). Not used in coverage mode.
  bool peel_test = false;
  // Layers a pixel keeps in layers mode (mlab-K), 1..kMaxLayers; not used in other modes.
  uint8_t layers = 1;
};

// A pass draws coverage fragments (every pixel with a covered sample, Fragment::coverage the
// count) exactly when its blend is kCoverage: the feeder asks the pass state.
constexpr bool is_coverage_pass(const RopState& s) { return s.blend == BlendMode::kCoverage; }

// Which primitives a pass draws. Decided by the feeder, before the datapath. kEdges draws the
// scene's unique tessellation edges as lines (raster.md, "Lines") instead of its triangles.
enum class PrimFilter : uint8_t { kOpaque, kTransparent, kAll, kEdges };
// Which faces a pass discards (by winding). Decided by the feeder.
enum class Cull : uint8_t { kNone, kFront, kBack };
// Which fragments a pass keeps by their per-vertex facing flag (Fragment::facing). Feeder.
enum class FacingFilter : uint8_t { kAll, kToward, kAway };

// Depth offset applied by the feeder (docs/datapath.md, "The feeder"):
// offset = units + ceil(slope_q8 * slope / 256), limited to `clamp` when clamp > 0, where
// `slope` is the primitive's depth slope (raster.md, "Depth offset"); z' = max(0, z - offset).
// With `faces`, an edge's fragment takes, instead of the slope term, how far it lies behind
// its own faces at the pixel centre (raster/edge_lift.h); triangles, their own faces, take 0.
struct DepthOffset {
  uint32_t units = 0;     // constant, in units of the depth format
  uint32_t slope_q8 = 0;  // slope factor, unsigned 8.8 fixed point (256 = 1.0)
  uint32_t clamp = 0;     // largest offset, depth units; 0 = unlimited
  bool faces = false;     // edges: the lift to their own faces instead of the slope term
  bool any() const { return units != 0 || slope_q8 != 0 || faces; }
};

// A frame operation: done by the host on the whole frame between passes (docs/datapath.md
// "Frame operations"); depth peeling's plans use them.
enum class FrameOpKind : uint8_t {
  kClearColor = 0,   // every colour := value
  kClearDepth = 1,   // every depth := depth
  kCopyDepthToPeel = 2,  // peel := depth
  kResolveUnder = 3,     // colour := min(255, C + m(value, 255 - A)) per channel (value = bg)
  kResolveWboit = 4,     // colour := the accumulation's average over it by the revealage
  kResolveLayers = 5,    // colour := the layers front to back over it; the layers emptied
};
constexpr unsigned kFrameOpKinds = 6;

struct FrameOp {
  FrameOpKind kind = FrameOpKind::kClearColor;
  Rgba8 value;        // kClearColor, kResolveUnder
  uint32_t depth = 0;  // kClearDepth; clamped to the frame's depth_max
  // In a plan: render() replaces `value` with the scene's background (the resolve's bg).
  bool background = false;
  // The far depth, as a kClearDepth depth: the frame's depth_max.
  static constexpr uint32_t kFar = 0xffffffffu;
};

// One pass of a pass plan. Everything but `rop` is applied by the feeder, before the datapath.
struct PassState {
  std::string name;
  PrimFilter filter = PrimFilter::kAll;
  Cull cull = Cull::kNone;
  FacingFilter facing = FacingFilter::kAll;
  bool zero_alpha_toward = false;  // fragments with facing = 1 carry alpha 0 (CN 103021015)
  DepthOffset offset;              // moves fragments toward the viewer
  bool constant_color = false;     // every fragment carries `color` (edge colour)
  Rgba8 color{0, 0, 0, 255};
  RopState rop;
  // Frame operations the host does before this pass (FrameOp above; depth peeling). A
  // plan's steps are, per pass, its frame_ops then the pass; then PassPlan::final_ops.
  std::vector<FrameOp> frame_ops;
};

// The pass state register as the RTL receives it (docs/datapath.md, "The pass state"):
// [0] depth_test, [3:1] depth_func, [4] depth_write, [7:5] blend, [11:8] color_mask,
// [12] peel_test, [15:13] layers - 1.
constexpr int kStateBits = 16;
// The register before layers: 13 bits, blend at most 5, frame operations 0 to 4. Version 4
// traces and the conformance kit (no layers feature yet) hold only these.
constexpr int kCoreStateBits = 13;
constexpr unsigned kCoreFrameOpKinds = 5;
uint16_t pack_state(const RopState& s);
// False when `bits` is not a valid state (a blend code above 6: the 16 bits are all fields).
bool unpack_state(uint16_t bits, RopState& out);
// unpack_state of a register before layers: false also for bits 13 and up, or blend 6.
bool unpack_core_state(uint64_t bits, RopState& out);

const char* to_string(DepthFunc f);
const char* to_string(BlendMode b);
const char* to_string(PrimFilter f);
const char* to_string(Cull c);
const char* to_string(FacingFilter f);

}  // namespace zb
