// Pass plans: each method as data, a list of passes with their state.
#pragma once

#include <string>
#include <vector>

#include "rop/fragment.h"

namespace zb {

struct PassPlan {
  std::string name;
  std::string source;       // where the method comes from
  std::string description;
  std::vector<PassState> passes;
  std::vector<FrameOp> final_ops;  // frame operations after the last pass (a resolve)
};

// depth-peel-K (Everitt 2001): the plans registered are K = 2, 4 and 8; any K >= 1 is built
// by make_depth_peel_plan (docs/datapath.md "Depth peeling").
constexpr int kDepthPeelLayers[] = {2, 4, 8};
PassPlan make_depth_peel_plan(int k);

// mlab-K, one-pass transparency in K layers a pixel (docs/datapath.md "8. Layers"): the
// plans registered are K = 2 and 4, the simulated zb_rop's LAYERS (4: its layers plane is
// already seven times its colour plane); any K of 1..kMaxLayers is built by make_mlab_plan.
constexpr int kMlabLayers[] = {2, 4};
PassPlan make_mlab_plan(int k);

// hidden-line's edge passes: depth offset (raster.md "Depth offset"), visible and hidden colours.
// The polygon offset the plans had first: 2 units + 1.0 x the slope of every face at either end,
// unclamped; on grazing faces it lifts edges through nearer faces (the silhouette leak).
constexpr DepthOffset kEdgeSlopeOffset{2, 256, 0, false};
// The offset from the edge's own faces: each edge fragment lifted to its own faces' depth at
// the pixel centre and no further (the knee of docs/sweeps.md "offset": from 0 to 16 units
// the gaps stay the same, and more only adds leaks).
constexpr DepthOffset kEdgeFacesOffset{0, 0, 0, true};
constexpr DepthOffset kEdgeOffset = kEdgeFacesOffset;  // the plans' default
constexpr Rgba8 kEdgeColor{0, 0, 0, 255};
constexpr Rgba8 kHiddenEdgeColor{190, 190, 190, 255};

// hidden-line (dim = false) or hidden-line-dim with the edges moved by `offset`: the
// registered plans are these with kEdgeOffset.
PassPlan make_hidden_line_plan(bool dim, const DepthOffset& offset);

// True when `plan` draws edges in a dimmed style where they fail the depth test (a pass of
// edges with depth GREATER, as hidden-line-dim).
bool dims_hidden_edges(const PassPlan& plan);

// Every pass plan, in the order methods are listed.
const std::vector<PassPlan>& pass_plans();

// The plan called `name`, or nullptr.
const PassPlan* find_plan(const std::string& name);

// The name of the exact floating-point ground truth, which is not a pass plan.
constexpr const char* kReferenceMethod = "reference";

// Every method name: the pass plans, then the reference.
std::vector<std::string> method_names();

}  // namespace zb
