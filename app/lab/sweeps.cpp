// What the sweeps share: one method's image, the method list, an opaque-only scene.
#include "sweeps.h"

#include <algorithm>
#include <stdexcept>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "rop/rop.h"

namespace zb::lab {

Framebuffer render_method(const RasterizedScene& rs, const std::string& method) {
  if (method == kReferenceMethod) return render_reference(rs);
  const PassPlan* plan = find_plan(method);
  if (!plan) throw std::invalid_argument("unknown method '" + method + "'");
  GoldenRop rop;
  return render(rs, *plan, rop).framebuffer;
}

std::vector<std::string> methods_or_all(const std::vector<std::string>& methods) {
  return methods.empty() ? method_names() : methods;
}

Scene opaque_only(Scene scene) {
  auto& objs = scene.objects;
  objs.erase(std::remove_if(objs.begin(), objs.end(),
                            [&](const Object& o) {
                              return o.material < scene.materials.size() &&
                                     scene.materials[o.material].transparent();
                            }),
             objs.end());
  return scene;
}

}  // namespace zb::lab
