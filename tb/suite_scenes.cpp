// scenes: every built-in scene with every pass plan, 96x72.
#include <string>
#include <utility>
#include <vector>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "scene/builtin_scenes.h"
#include "suites.h"

namespace zb::tb {

Tally suite_scenes(const Config& c) {
  Tally t;
  const int iters = c.iterations ? c.iterations : 1;
  std::vector<std::pair<std::string, RasterizedScene>> scenes;
  for (const SceneInfo& info : builtin_scenes())
    scenes.emplace_back(info.name, rasterize_scene(*builtin_scene(info.name), Viewport{96, 72, 24}));
  WorkCounter progress(c, uint64_t(iters) * scenes.size() * pass_plans().size());
  for (int it = 0; it < iters; ++it) {
    const uint64_t seed = c.seed + it;
    for (const auto& [sname, rs] : scenes)
      for (const PassPlan& plan : pass_plans()) {
        const bool ok = run_iteration("scenes", c, seed, t, [&](Cosim& cs) {
          cs.begin_frame(rs.viewport.width, rs.viewport.height, rs.viewport.depth_bits,
                         rs.background, rs.viewport.coverage_samples);
          for (const PassState& p : plan.passes) {
            for (const FrameOp& op : p.frame_ops) cs.frame_op(resolve_op(op, rs.background));
            draw_pass(cs, sname + "/" + plan.name + "/" + p.name, p.rop, pass_fragments(rs, p));
          }
          for (const FrameOp& op : plan.final_ops) cs.frame_op(resolve_op(op, rs.background));
        });
        if (!ok) return t;
        progress.add();
      }
  }
  return t;
}

}  // namespace zb::tb
