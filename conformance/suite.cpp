#include "suite.h"

#include <algorithm>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rtl_params.h"
#include "scene/builtin_scenes.h"
#include "generate.h"
#include "streams.h"

namespace zb::conformance {
namespace {

// The configs, base first. Each other config changes one width of the base.
const Config kBase{"d24-c16", 24, 16, {}};
const Config kCoverage4{"d24-c4", 24, 4, {}};
const Config kDepth16{"d16-c16", 16, 16, {}};
const Config kDepth32{"d32-c16", 32, 16, {}};

// Scenes: every built-in at a small frame. The other depth widths run the scenes and methods
// where the width decides something: equal depths (coplanar, the peel's equal test), the edges'
// depth offset in depth units (parts, hidden-line), coverage's nearer-or-equal cases.
constexpr int kSceneWidth = 32, kSceneHeight = 24;
const char* const kWidthScenes[] = {"cad", "parts", "coplanar"};
const char* const kWidthMethods[] = {"three-pass", "coverage-aa", "hidden-line", "depth-peel-4"};

// Synthetic streams: fixed seeds and sizes.
constexpr uint64_t kHazardSeed = 1;
constexpr int kHazardPasses = 4;
constexpr size_t kHazardFragments = 300;  // per pass
constexpr uint64_t kRandomSeed = 1;
constexpr int kRandomWidth = 48, kRandomHeight = 40;
constexpr int kRandomPasses = 24;
constexpr size_t kRandomFragments = 150;  // per pass: many passes, many states

// The quick tier: the greedy ranking of the reach (`zblend conformance reach --rank`, at zb_rop's
// 64 x 64 tile): the fewest tests that keep every bin the whole suite reaches, there and at 16 x 16
// (CTest conformance_export_reproducible holds both).
const char* const kQuick[] = {
    "states-alpha", "states-replace", "states-additive", "states-alpha-peel",
    "states-replace-peel", "states-additive-peel", "states-coverage-peel", "states-under",
    "states-under-peel", "states-accumulate-peel", "states-coverage", "states-accumulate",
    "values-replace", "random-c4", "depth-bits-d32", "depth-bits", "values-coverage",
    "depth-bits-d16", "particles-mlab-4", "tiles", "values-coverage-c4", "cad-coverage-aa",
    "cad-depth-peel-2", "particles-facing-additive", "layers-cases", "hazard",
    "glass-torus-back-front", "values-accumulate", "glass-torus-facing-additive",
    "particles-back-front", "sphere-torus-wboit", "values-additive", "sphere-torus-mlab-2"};

// A plan that came with suite version 3 (its accumulate passes and resolve read and write the
// accumulation plane): its tests follow the base config's earlier ones, so no name moves.
bool uses_blend(const PassPlan& p, BlendMode b) {
  for (const PassState& s : p.passes)
    if (s.rop.blend == b) return true;
  return false;
}
bool uses_accumulation(const PassPlan& p) { return uses_blend(p, BlendMode::kAccumulate); }

// A test's name: what it runs, then the widths where its config differs from the base.
std::string named(const std::string& what, const Config& c) {
  std::string name = what;
  if (c.depth_bits != kBase.depth_bits) name += "-d" + std::to_string(c.depth_bits);
  if (c.coverage_samples != kBase.coverage_samples) name += "-c" + std::to_string(c.coverage_samples);
  return name;
}

TestSpec scene_test(const Config& c, const std::string& scene, const std::string& method) {
  TestSpec t;
  t.name = named(scene + "-" + method, c);
  t.config = c;
  t.scene = scene;
  t.method = method;
  t.width = kSceneWidth;
  t.height = kSceneHeight;
  return t;
}

TestSpec hazard_test(const Config& c) {
  TestSpec t;
  t.name = named("hazard", c);
  t.config = c;
  t.kind = TestKind::kHazard;
  t.seed = kHazardSeed;
  t.width = kRtlTileW;  // the stimulus's frame: one RTL tile
  t.height = kRtlTileH;
  return t;
}

TestSpec random_test(const Config& c, RandomMix mix = RandomMix::kAll) {
  TestSpec t;
  const char* what = mix == RandomMix::kWboit ? "random-wboit"
                     : mix == RandomMix::kCore ? "random-core" : "random";
  t.name = named(what, c);
  t.mix = mix;
  t.config = c;
  t.kind = TestKind::kRandom;
  t.seed = kRandomSeed;
  t.width = kRandomWidth;
  t.height = kRandomHeight;
  return t;
}

TestSpec generated_test(const Config& c, Family family, BlendMode blend = BlendMode::kReplace,
                        bool peel = false) {
  TestSpec t;
  t.config = c;
  t.kind = TestKind::kGenerated;
  t.family = family;
  t.blend = blend;
  t.peel = peel;
  std::string what = to_string(family);
  if (family == Family::kStates || family == Family::kValues || family == Family::kSamePixel)
    what += std::string("-") + to_string(blend);
  if (peel) what += "-peel";
  t.name = named(what, c);
  const Trace tr = test_trace(t);  // the frame is the family's
  t.width = tr.width;
  t.height = tr.height;
  return t;
}

// Version 6's generated tests of a config, at the end of its group.
void add_generated(std::vector<TestSpec>& all, const Config& c) {
  if (&c == &kBase) {
    for (unsigned b = 0; b < kCoreBlendModes; ++b)
      for (bool peel : {false, true})
        all.push_back(generated_test(c, Family::kStates, BlendMode(b), peel));
    all.push_back(generated_test(c, Family::kDepthBits));
    for (BlendMode b : {BlendMode::kReplace, BlendMode::kAlpha, BlendMode::kAdditive, BlendMode::kUnder})
      all.push_back(generated_test(c, Family::kValues, b));
    all.push_back(generated_test(c, Family::kCoverageValues));
    all.push_back(generated_test(c, Family::kAccumValues));
    all.push_back(generated_test(c, Family::kTiles));
    for (BlendMode b : {BlendMode::kAlpha, BlendMode::kAdditive, BlendMode::kCoverage,
                        BlendMode::kUnder, BlendMode::kAccumulate})
      all.push_back(generated_test(c, Family::kSamePixel, b));
  } else if (&c == &kCoverage4) {
    all.push_back(generated_test(c, Family::kCoverageValues));
  } else {
    all.push_back(generated_test(c, Family::kDepthBits));
  }
}

// Version 8: at 16 and 32 bits, what a DUT of one depth width needs to meet every blend it has
// (a ROP with a 16-bit depth buffer ran 8 tests of version 7): cad with opaque, the states,
// values and same-pixel runs of the replace, alpha and additive blends, and the tiles.
void add_narrow(std::vector<TestSpec>& all, const Config& c) {
  all.push_back(scene_test(c, "cad", "opaque"));
  for (BlendMode b : {BlendMode::kReplace, BlendMode::kAlpha, BlendMode::kAdditive})
    all.push_back(generated_test(c, Family::kStates, b));
  for (BlendMode b : {BlendMode::kReplace, BlendMode::kAlpha, BlendMode::kAdditive})
    all.push_back(generated_test(c, Family::kValues, b));
  for (BlendMode b : {BlendMode::kAlpha, BlendMode::kAdditive})
    all.push_back(generated_test(c, Family::kSamePixel, b));
  all.push_back(generated_test(c, Family::kTiles));
}

}  // namespace

const char* to_string(TestKind k) {
  switch (k) {
    case TestKind::kScene: return "scene";
    case TestKind::kHazard: return "hazard";
    case TestKind::kRandom: return "random";
    case TestKind::kGenerated: return "generated";
  }
  return "?";
}

const char* to_string(Family f) {
  switch (f) {
    case Family::kStates: return "states";
    case Family::kDepthBits: return "depth-bits";
    case Family::kValues: return "values";
    case Family::kCoverageValues: return "values-coverage";
    case Family::kAccumValues: return "values-accumulate";
    case Family::kTiles: return "tiles";
    case Family::kSamePixel: return "same-pixel";
    case Family::kLayers: return "layers-cases";
  }
  return "?";
}

std::vector<TestSpec> suite_tests(bool quick) {
  std::vector<TestSpec> all;
  for (const SceneInfo& s : builtin_scenes())
    for (const PassPlan& p : pass_plans())
      if (!uses_accumulation(p) && !uses_blend(p, BlendMode::kLayers))
        all.push_back(scene_test(kBase, s.name, p.name));
  all.push_back(hazard_test(kBase));
  all.push_back(random_test(kBase));
  for (const SceneInfo& s : builtin_scenes())
    for (const PassPlan& p : pass_plans())
      if (uses_accumulation(p)) all.push_back(scene_test(kBase, s.name, p.name));
  all.push_back(random_test(kBase, RandomMix::kWboit));  // version 4
  all.push_back(random_test(kBase, RandomMix::kCore));   // version 5
  add_generated(all, kBase);                             // version 6
  // Version 7: mlab-K's layers (a profile's blend.layers and layers.K).
  for (const SceneInfo& s : builtin_scenes())
    for (const PassPlan& p : pass_plans())
      if (uses_blend(p, BlendMode::kLayers)) all.push_back(scene_test(kBase, s.name, p.name));
  all.push_back(generated_test(kBase, Family::kLayers));
  all.push_back(generated_test(kBase, Family::kSamePixel, BlendMode::kLayers));
  all.push_back(hazard_test(kCoverage4));
  all.push_back(random_test(kCoverage4));
  add_generated(all, kCoverage4);
  for (const Config* c : {&kDepth16, &kDepth32}) {
    for (const char* scene : kWidthScenes)
      for (const char* method : kWidthMethods) all.push_back(scene_test(*c, scene, method));
    all.push_back(random_test(*c, RandomMix::kCore));  // version 5
    add_generated(all, *c);
    all.push_back(generated_test(*c, Family::kLayers));  // version 7
    add_narrow(all, *c);                                 // version 8
  }
  for (TestSpec& t : all)
    t.quick = std::find(std::begin(kQuick), std::end(kQuick), t.name) != std::end(kQuick);
  if (quick)
    all.erase(std::remove_if(all.begin(), all.end(), [](const TestSpec& t) { return !t.quick; }),
              all.end());
  return all;
}

std::vector<TestSpec> seeded_tests(uint64_t seed) {
  std::vector<TestSpec> all;
  auto add = [&](const Config& c, RandomMix mix) {
    TestSpec t = random_test(c, mix);
    t.seed = seed;
    t.seeded = true;
    t.name += "-s" + std::to_string(seed);
    all.push_back(t);
  };
  add(kBase, RandomMix::kAll);
  add(kBase, RandomMix::kWboit);
  add(kBase, RandomMix::kCore);
  add(kCoverage4, RandomMix::kAll);
  add(kDepth16, RandomMix::kCore);
  add(kDepth32, RandomMix::kCore);
  return all;
}

std::string build_warning() {
  if (kRtlTileW == 64 && kRtlCoverageSamples == 16) return "";
  return "this build's RTL tile is " + std::to_string(kRtlTileW) + " and its coverage samples " +
         std::to_string(kRtlCoverageSamples) + " (a default build's: 64 and 16): its hazard tests "
         "differ from a default build's suite";
}

Trace test_trace(const TestSpec& t) {
  const Config& c = t.config;
  Trace trace;
  switch (t.kind) {
    case TestKind::kScene: {
      const PassPlan* plan = find_plan(t.method);
      const std::optional<Scene> scene = builtin_scene(t.scene);
      if (!plan || !scene)
        throw ConformanceError("test " + t.name + ": no scene '" + t.scene + "' or method '" +
                               t.method + "'");
      const Viewport vp{t.width, t.height, c.depth_bits, c.coverage_samples, c.wboit};
      trace = make_trace(rasterize_scene(*scene, vp), *plan);
      break;
    }
    case TestKind::kHazard:
      if (c.depth_bits != 24)  // the stimulus draws 24-bit depths
        throw ConformanceError("test " + t.name + ": the hazard stream needs 24-bit depth");
      trace = hazard_trace(t.seed, c.coverage_samples, kHazardPasses, kHazardFragments);
      break;
    case TestKind::kRandom:
      trace = random_trace(t.seed, t.width, t.height, c.depth_bits, c.coverage_samples,
                           kRandomPasses, kRandomFragments, t.mix);
      break;
    case TestKind::kGenerated: {
      const int b = c.depth_bits, n = c.coverage_samples;
      switch (t.family) {
        case Family::kStates: trace = states_trace(t.blend, t.peel, b, n); break;
        case Family::kDepthBits: trace = depth_bits_trace(b, n); break;
        case Family::kValues: trace = values_trace(t.blend, b, n); break;
        case Family::kCoverageValues: trace = coverage_values_trace(b, n); break;
        case Family::kAccumValues: trace = accumulate_values_trace(b, n); break;
        case Family::kTiles: trace = tiles_trace(b, n); break;
        case Family::kSamePixel: trace = same_pixel_trace(t.blend, b, n); break;
        case Family::kLayers: trace = layers_trace(b, n); break;
      }
      break;
    }
  }
  trace.wboit = c.wboit;
  // The stream carries a clear depth as the DUT gets it: clamped to the far depth, as
  // apply_frame_op does.
  auto clamp = [&](std::vector<FrameOp>& ops) {
    for (FrameOp& op : ops)
      if (op.kind == FrameOpKind::kClearDepth) op.depth = std::min(op.depth, depth_max(c.depth_bits));
  };
  for (TracePass& p : trace.passes) clamp(p.frame_ops);
  clamp(trace.final_ops);
  return trace;
}

}  // namespace zb::conformance
