#include "passes.h"

#include <string>

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
                   {pass("all", PrimFilter::kAll, less(true, BlendMode::kReplace))}, {}});
  plans.push_back({"unsorted", "prior art, one transparent pass",
                   "opaque pass, then transparent primitives in submit order blended with "
                   "z-write off",
                   {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)),
                    pass("transparent", PrimFilter::kTransparent,
                         less(false, BlendMode::kAlpha))}, {}});
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
                         less(true, BlendMode::kAlpha))}, {}});
  // US 5,923,333, claim 1: (a) opaque primitives to the z-buffer and frame buffer; (b)
  // "disabling writes to said z-buffer, culling all front-facing primitives of said transparent
  // objects", rasterizing the back-facing ones, culling pixels behind opaque objects and alpha
  // blending the rest; (c) the same with the back-facing primitives culled. Culling is by
  // winding (ScreenTriangle::front), in the feeder.
  {
    PassState back =
        pass("transparent-back", PrimFilter::kTransparent, less(false, BlendMode::kAlpha));
    back.cull = Cull::kFront;
    PassState front =
        pass("transparent-front", PrimFilter::kTransparent, less(false, BlendMode::kAlpha));
    front.cull = Cull::kBack;
    plans.push_back({"back-front", "US 5,923,333",
                     "opaque; transparent back faces (front faces culled), z-write off, blend; "
                     "transparent front faces (back faces culled), z-write off, blend",
                     {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)), back,
                      front}, {}});
  }
  // CN 103021015: the vertex stage decides from the vertex normal and the camera whether each
  // vertex faces the viewer (Fragment::facing, raster.md "Facing"). "First pass: ... points to
  // be drawn are output normally; points not to be drawn output alpha 0 ... the faces turned
  // away from the viewer. Second pass: z-test off, draw the front faces. The second pass is
  // drawn onto the frame buffer additively."
  {
    PassState away =
        pass("transparent-away", PrimFilter::kTransparent, less(false, BlendMode::kAlpha));
    away.zero_alpha_toward = true;
    RopState additive = less(false, BlendMode::kAdditive);
    additive.depth_test = false;
    PassState toward = pass("transparent-toward", PrimFilter::kTransparent, additive);
    toward.facing = FacingFilter::kToward;
    plans.push_back({"facing-additive", "CN 103021015",
                     "opaque; transparent with fragments facing the viewer at alpha 0 (the "
                     "away-facing part blends); the facing part again, z-test off, additive",
                     {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)), away,
                      toward}, {}});
  }
  // US 5,123,085: "each pixel in the frame buffer being identified by a color value, a z buffer
  // value and a representation indicative of coverage"; every polygon pixel is composited with
  // the background pixel by the four depth cases. One pass over all primitives, in submit
  // order, coverage fragments (raster.md "Coverage"); material alpha is not a weight (the
  // patent's polygons are opaque): it is blended as a fourth channel by coverage.
  plans.push_back({"coverage-aa", "US 5,123,085",
                   "one pass, all primitives: per-pixel colour, depth and sample coverage, "
                   "composited by the four depth cases (nearer, farther, equal full, equal "
                   "partial)",
                   {pass("coverage", PrimFilter::kAll, less(true, BlendMode::kCoverage))}, {}});
  // McGuire and Bavoil 2013, "Weighted Blended Order-Independent Transparency": the opaque
  // pass, then every transparent fragment in front of the opaque depth added to the
  // accumulation (premultiplied colour and alpha, each times the weight a * F(z)) and its
  // 1 - a multiplied into the revealage; the resolve puts the accumulation's average over the
  // opaque colour by the revealage (docs/datapath.md "7. Accumulate blend").
  plans.push_back({"wboit", "McGuire and Bavoil 2013",
                   "opaque; transparent added to the accumulation weighted by alpha and depth, "
                   "revealage multiplied by 1 - alpha, z-write off; resolve: the weighted "
                   "average over the opaque colour by the revealage",
                   {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)),
                    pass("transparent-accumulate", PrimFilter::kTransparent,
                         less(false, BlendMode::kAccumulate))},
                   {FrameOp{FrameOpKind::kResolveWboit, Rgba8{}, 0, false}}});
  plans.push_back(make_hidden_line_plan(false, kEdgeOffset));
  plans.push_back(make_hidden_line_plan(true, kEdgeOffset));
  for (int k : kDepthPeelLayers) plans.push_back(make_depth_peel_plan(k));
  for (int k : kMlabLayers) plans.push_back(make_mlab_plan(k));
  return plans;
}

}  // namespace

// US 5,359,704, claim 1: (a) mask the frame buffer; (b, c) scan-convert the faces, updating
// the depth buffer "only when the obtained depth value is smaller"; (d) unmask; (e) move the
// display "a distance in front of visible faces"; (f) depth-test and draw "all tessellation
// edges". The distance is a depth offset (raster.md "Depth offset"); edges pass on LEQUAL.
// "... with hidden lines eliminated or displayed in a line style different from that of
// visible lines": hidden-line-dim draws the edges that fail the test (GREATER) dimmed first.
PassPlan make_hidden_line_plan(bool dim, const DepthOffset& offset) {
  RopState faces_rop = less(true, BlendMode::kReplace);
  faces_rop.color_mask = 0;
  const PassState faces = pass("faces-depth-only", PrimFilter::kAll, faces_rop);
  RopState edge_rop = less(false, BlendMode::kReplace);
  edge_rop.depth_func = DepthFunc::kLequal;
  PassState visible = pass("edges-visible", PrimFilter::kEdges, edge_rop);
  visible.offset = offset;
  visible.constant_color = true;
  visible.color = kEdgeColor;
  if (!dim)
    return {"hidden-line", "US 5,359,704",
            "faces to depth only (colour masked); every tessellation edge once, moved toward "
            "the viewer by a depth offset, depth LEQUAL: hidden lines removed",
            {faces, visible}, {}};
  PassState hidden = visible;
  hidden.name = "edges-hidden-dim";
  hidden.rop.depth_func = DepthFunc::kGreater;
  hidden.color = kHiddenEdgeColor;
  return {"hidden-line-dim", "US 5,359,704",
          "hidden-line with hidden edges kept in a second style: edges failing the test "
          "(GREATER) drawn dimmed before the visible ones",
          {faces, hidden, visible}, {}};
}

bool dims_hidden_edges(const PassPlan& plan) {
  for (const PassState& p : plan.passes)
    if (p.filter == PrimFilter::kEdges && p.rop.depth_func == DepthFunc::kGreater) return true;
  return false;
}

// Everitt 2001, "Interactive Order-Independent Transparency": each peel finds, per pixel, the
// nearest transparent layer strictly behind the previous peel's (the second depth compare,
// RopState::peel_test, against the peel plane) and in front of the opaque surface, and
// accumulates it front to back (BlendMode::kUnder) into a premultiplied colour plane cleared
// to 0. Finally the visible opaque surface is accumulated under the layers and the result resolved
// over the background. Exact for up to k transparent layers per pixel.
PassPlan make_depth_peel_plan(int k) {
  PassPlan plan;
  plan.name = "depth-peel-" + std::to_string(k);
  plan.source = "Everitt 2001";
  plan.description = std::to_string(k) +
                     " peels, each: opaque depth, nearest transparent layer behind the last "
                     "(second depth compare), that layer accumulated front to back; then the "
                     "opaque surface under them and a resolve over the background";
  FrameOp clear_color{FrameOpKind::kClearColor, Rgba8{0, 0, 0, 0}, 0, false};
  FrameOp clear_depth{FrameOpKind::kClearDepth, Rgba8{}, FrameOp::kFar, false};
  FrameOp copy_peel{FrameOpKind::kCopyDepthToPeel, Rgba8{}, 0, false};
  RopState depth_only = less(true, BlendMode::kReplace);
  depth_only.color_mask = 0;
  for (int i = 1; i <= k; ++i) {
    const std::string n = "peel-" + std::to_string(i);
    PassState opaque = pass(n + "-opaque-depth", PrimFilter::kOpaque, depth_only);
    if (i == 1) opaque.frame_ops = {clear_color, clear_depth};
    else opaque.frame_ops = {copy_peel, clear_depth};
    // The first peel needs no second compare (the peel plane is not yet meaningful); later
    // ones keep only fragments strictly behind the previous layer.
    RopState find = depth_only;
    find.peel_test = i > 1;
    RopState accumulate = less(false, BlendMode::kUnder);
    accumulate.depth_func = DepthFunc::kEqual;
    accumulate.peel_test = i > 1;
    plan.passes.push_back(opaque);
    plan.passes.push_back(pass(n + "-layer-depth", PrimFilter::kTransparent, find));
    plan.passes.push_back(pass(n + "-layer-under", PrimFilter::kTransparent, accumulate));
  }
  // The opaque surface: its depth first, then only the visible fragment accumulated (an
  // under blend in submit order would keep the first opaque fragment, not the nearest).
  PassState opaque_depth = pass("opaque-depth", PrimFilter::kOpaque, depth_only);
  opaque_depth.frame_ops = {clear_depth};
  RopState visible = less(false, BlendMode::kUnder);
  visible.depth_func = DepthFunc::kEqual;
  plan.passes.push_back(opaque_depth);
  plan.passes.push_back(pass("opaque-under", PrimFilter::kOpaque, visible));
  plan.final_ops = {FrameOp{FrameOpKind::kResolveUnder, Rgba8{}, 0, true}};
  return plan;
}

// Salvi and Vaidyanathan 2014, "Multi-Layer Alpha Blending", kept in tile memory as Bjorge et
// al. 2014 do: the opaque pass, then every transparent fragment in front of the opaque depth
// inserted into the pixel's K layers by depth, the two farthest merged when a K+1-th arrives;
// the resolve composites the layers front to back over the opaque colour, on the tile's way
// out. Exact (as depth-peel-K) for up to K layers a pixel, in any submit order.
PassPlan make_mlab_plan(int k) {
  PassPlan plan;
  plan.name = "mlab-" + std::to_string(k);
  plan.source = "Salvi and Vaidyanathan 2014";
  plan.description = "opaque; transparent inserted by depth into " + std::to_string(k) +
                     " layers a pixel, the two farthest merged beyond " + std::to_string(k) +
                     ", z-write off; resolve: the layers front to back over the opaque colour";
  RopState insert = less(false, BlendMode::kLayers);
  insert.layers = uint8_t(k);
  plan.passes = {pass("opaque", PrimFilter::kOpaque, less(true, BlendMode::kReplace)),
                 pass("transparent-layers", PrimFilter::kTransparent, insert)};
  plan.final_ops = {FrameOp{FrameOpKind::kResolveLayers, Rgba8{}, 0, false}};
  return plan;
}

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
