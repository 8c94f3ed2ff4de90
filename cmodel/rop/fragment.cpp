#include "fragment.h"

namespace zb {

uint16_t pack_state(const RopState& s) {
  return static_cast<uint16_t>((s.depth_test ? 1u : 0u) | (unsigned(s.depth_func) & 7u) << 1 |
                               (s.depth_write ? 1u : 0u) << 4 | (unsigned(s.blend) & 7u) << 5 |
                               (unsigned(s.color_mask) & 15u) << 8 |
                               (s.peel_test ? 1u : 0u) << 12 |
                               ((unsigned(s.layers) - 1u) & 7u) << 13);
}

bool unpack_state(uint16_t bits, RopState& out) {
  const unsigned blend = (bits >> 5) & 7u;
  if (blend >= kBlendModes) return false;
  out.depth_test = bits & 1u;
  out.depth_func = static_cast<DepthFunc>((bits >> 1) & 7u);
  out.depth_write = (bits >> 4) & 1u;
  out.blend = static_cast<BlendMode>(blend);
  out.color_mask = static_cast<uint8_t>((bits >> 8) & 15u);
  out.peel_test = (bits >> 12) & 1u;
  out.layers = static_cast<uint8_t>(((bits >> 13) & 7u) + 1u);
  return true;
}

bool unpack_core_state(uint64_t bits, RopState& out) {
  return bits >> kCoreStateBits == 0 && unpack_state(uint16_t(bits), out) &&
         out.blend != BlendMode::kLayers;
}

const char* to_string(DepthFunc f) {
  switch (f) {
    case DepthFunc::kNever: return "never";
    case DepthFunc::kLess: return "less";
    case DepthFunc::kEqual: return "equal";
    case DepthFunc::kLequal: return "lequal";
    case DepthFunc::kGreater: return "greater";
    case DepthFunc::kNotequal: return "notequal";
    case DepthFunc::kGequal: return "gequal";
    case DepthFunc::kAlways: return "always";
  }
  return "?";
}

const char* to_string(BlendMode b) {
  switch (b) {
    case BlendMode::kReplace: return "replace";
    case BlendMode::kAlpha: return "alpha";
    case BlendMode::kAdditive: return "additive";
    case BlendMode::kCoverage: return "coverage";
    case BlendMode::kUnder: return "under";
    case BlendMode::kAccumulate: return "accumulate";
    case BlendMode::kLayers: return "layers";
  }
  return "?";
}

const char* to_string(PrimFilter f) {
  switch (f) {
    case PrimFilter::kOpaque: return "opaque";
    case PrimFilter::kTransparent: return "transparent";
    case PrimFilter::kAll: return "all";
    case PrimFilter::kEdges: return "edges";
  }
  return "?";
}

const char* to_string(Cull c) {
  switch (c) {
    case Cull::kNone: return "none";
    case Cull::kFront: return "front";
    case Cull::kBack: return "back";
  }
  return "?";
}

const char* to_string(FacingFilter f) {
  switch (f) {
    case FacingFilter::kAll: return "all";
    case FacingFilter::kToward: return "toward";
    case FacingFilter::kAway: return "away";
  }
  return "?";
}

}  // namespace zb
