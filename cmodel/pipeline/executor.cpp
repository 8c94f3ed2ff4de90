#include "executor.h"

namespace zb {

std::vector<PassStats> run_plan(const PassPlan& plan, const Viewport& vp, Rgba8 background,
                                FragmentSource& source, Backend& backend) {
  backend.begin_frame(vp.width, vp.height, vp.depth_bits, background, vp.coverage_samples,
                      vp.wboit);
  std::vector<PassStats> stats;
  stats.reserve(plan.passes.size());
  std::vector<Fragment> buffer;
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    const PassState& pass = plan.passes[i];
    for (const FrameOp& op : pass.frame_ops) backend.frame_op(resolve_op(op, background));
    backend.label_pass(pass.name);
    backend.begin_pass(pass.rop);
    feed_pass(source, i, pass, [&](const Fragment* f, size_t n) { backend.draw(f, n); }, buffer);
    stats.push_back(backend.end_pass());
  }
  for (const FrameOp& op : plan.final_ops) backend.frame_op(resolve_op(op, background));
  backend.finish_frame(stats);
  return stats;
}

}  // namespace zb
