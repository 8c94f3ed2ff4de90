// The plan executor: the one place a pass plan is run on a backend. render() (render.h) runs it
// over a whole frame's stored fragments, render_frame() (frame_render.h) over each band.
#pragma once

#include <vector>

#include "feeder.h"
#include "passes.h"
#include "rop/backend.h"

namespace zb {

// Runs `plan` on `backend` over a frame of vp.width x vp.height: begin_frame; per pass its frame
// operations, begin_pass, the feeder over `source`, end_pass; then the final operations. The
// plan's background placeholder stands for `background`. Returns each pass's counters.
std::vector<PassStats> run_plan(const PassPlan& plan, const Viewport& vp, Rgba8 background,
                                FragmentSource& source, Backend& backend);

}  // namespace zb
