#include "fragment.h"

namespace zb {

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
  }
  return "?";
}

const char* to_string(PrimFilter f) {
  switch (f) {
    case PrimFilter::kOpaque: return "opaque";
    case PrimFilter::kTransparent: return "transparent";
    case PrimFilter::kAll: return "all";
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

}  // namespace zb
