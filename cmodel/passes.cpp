#include "passes.h"

namespace zb {
namespace {

PassState pass(std::string name, PrimFilter filter, RopState rop) {
  PassState p;
  p.name = std::move(name);
  p.filter = filter;
  p.rop = rop;
  return p;
}

// Depth LESS with the given write enable and blend; all colour channels written.
RopState less(bool depth_write, BlendMode blend) {
  RopState s;
  s.depth_test = true;
  s.depth_func = DepthFunc::kLess;
  s.depth_write = depth_write;
  s.blend = blend;
  s.color_mask = kMaskRgba;
  return s;
}

std::vector<PassPlan> make_plans() {
  std::vector<PassPlan> plans;
  plans.push_back({"opaque", "baseline",
                   "every primitive drawn opaque: depth LESS, z-write on, replace",
                   {pass("all", PrimFilter::kAll, less(true, BlendMode::kReplace))}});
  plans.push_back({"unsorted", "prior art, one transparent pass",
                   "opaque pass, then transparent primitives in submit order blended with "
                   "z-write off",
                   {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)),
                    pass("transparent", PrimFilter::kTransparent,
                         less(false, BlendMode::kAlpha))}});
  // US 7,834,879: "in pass 1 an opaque object alone is drawn while a hidden surface removal is
  // executed by Z buffer algorithm. The Z buffer is updated. Then in pass 2 a semitransparent
  // object alone is blended ... the Z buffer is not updated. Finally in pass 3 the
  // semitransparent object alone is blended ... the Z buffer is updated."
  plans.push_back({"three-pass", "US 7,834,879",
                   "opaque with z-write; transparent blended with z-write off; transparent "
                   "blended again with z-write on",
                   {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)),
                    pass("transparent-no-zwrite", PrimFilter::kTransparent,
                         less(false, BlendMode::kAlpha)),
                    pass("transparent-zwrite", PrimFilter::kTransparent,
                         less(true, BlendMode::kAlpha))}});
  return plans;
}

}  // namespace

const std::vector<PassPlan>& pass_plans() {
  static const std::vector<PassPlan> plans = make_plans();
  return plans;
}

const PassPlan* find_plan(const std::string& name) {
  for (const PassPlan& p : pass_plans())
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const PassPlan& p : pass_plans()) names.push_back(p.name);
  names.emplace_back(kReferenceMethod);
  return names;
}

}  // namespace zb
