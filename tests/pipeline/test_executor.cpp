// The plan executor and the feeder (pipeline/executor.h, feeder.h): the one place a plan is run,
// checked against the plan's own data with a backend that records every call and a source
// whose fragments are known.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pipeline/executor.h"
#include "pipeline/passes.h"
#include "rop/rop.h"

namespace zb {
namespace {

// Records the calls it receives, as text, and draws on a golden model.
class Recorder final : public Backend {
 public:
  const char* name() const override { return "recorder"; }
  using Backend::begin_frame;
  void begin_frame(int w, int h, int, Rgba8, int, const WboitFormat&) override {
    log.push_back("frame " + std::to_string(w) + "x" + std::to_string(h));
  }
  void label_pass(const std::string& n) override { log.push_back("label " + n); }
  void begin_pass(const RopState&) override { log.push_back("begin"); }
  using Backend::draw;
  void draw(const Fragment* f, size_t n) override {
    drawn.insert(drawn.end(), f, f + n);
  }
  PassStats end_pass() override {
    log.push_back("end " + std::to_string(drawn.size()));
    PassStats s;
    s.fragments_in = drawn.size();
    drawn.clear();
    return s;
  }
  void frame_op(const FrameOp& op) override {
    log.push_back(std::string("op ") + to_string(op.kind) + (op.background ? " placeholder" : ""));
    ops.push_back(op);
  }
  const Framebuffer& framebuffer() const override { return fb_; }

  std::vector<std::string> log;
  std::vector<Fragment> drawn;
  std::vector<FrameOp> ops;

 private:
  Framebuffer fb_;
};

// Two triangles (one opaque front-facing, one transparent back-facing) of two fragments each,
// and one edge of three; coverage samples marked by coverage = 1.
class KnownSource final : public FragmentSource {
 public:
  KnownSource() {
    tris[0].prim = 0;
    tris[0].front = true;
    tris[1].prim = 1;
    tris[1].transparent = true;
    tris[1].front = false;
    line.prim = 0;
    line.depth_slope = 512;
  }
  void triangles(size_t, const PassState& pass, FragmentKind kind, std::vector<Fragment>& out,
                 const TriangleDone& done) override {
    for (const ScreenTriangle& t : tris) {
      if (!pass_draws(pass, t)) continue;
      const size_t from = out.size();
      for (int k = 0; k < 2; ++k) {
        Fragment f;
        f.prim = t.prim;
        f.x = static_cast<uint16_t>(k);
        f.z = 1000;
        f.facing = k == 0;
        f.coverage = kind == FragmentKind::kCoverage ? 1 : 0;
        out.push_back(f);
      }
      done(t, from);
    }
  }
  void lines(std::vector<Fragment>& out, const LineDone& done) override {
    const size_t from = out.size();
    for (int k = 0; k < 3; ++k) {
      Fragment f;
      f.z = 1000;
      out.push_back(f);
    }
    done(line, from);
  }
  uint32_t slope(const ScreenTriangle& t) override { return t.prim == 0 ? 256 : 0; }

  ScreenTriangle tris[2];
  ScreenLine line;
};

TEST(Executor, RunsThePlanInItsOrder) {
  const PassPlan plan = make_depth_peel_plan(2);
  Recorder rec;
  KnownSource src;
  const std::vector<PassStats> stats =
      run_plan(plan, Viewport{8, 4}, Rgba8{1, 2, 3, 4}, src, rec);
  // The expected log, from the plan's data alone.
  std::vector<std::string> want = {"frame 8x4"};
  for (const PassState& p : plan.passes) {
    for (const FrameOp& op : p.frame_ops) want.push_back(std::string("op ") + to_string(op.kind));
    want.push_back("label " + p.name);
    want.push_back("begin");
    size_t n = 0;
    for (const ScreenTriangle& t : src.tris) n += pass_draws(p, t) ? 2 : 0;
    want.push_back("end " + std::to_string(n));
  }
  for (const FrameOp& op : plan.final_ops) want.push_back(std::string("op ") + to_string(op.kind));
  EXPECT_EQ(rec.log, want);
  ASSERT_EQ(stats.size(), plan.passes.size());
  // The background placeholder reaches the backend as the background.
  for (const FrameOp& op : rec.ops) {
    if (op.kind == FrameOpKind::kResolveUnder) {
      EXPECT_EQ(op.value, (Rgba8{1, 2, 3, 4}));
    }
  }
}

std::vector<Fragment> fed(const PassState& pass) {
  KnownSource src;
  std::vector<Fragment> out, buffer;
  feed_pass(src, 0, pass, [&](const Fragment* f, size_t n) { out.insert(out.end(), f, f + n); },
            buffer);
  return out;
}

TEST(Feeder, FiltersCullsAndRewrites) {
  PassState opaque;
  opaque.filter = PrimFilter::kOpaque;
  EXPECT_EQ(fed(opaque).size(), 2u);

  PassState back;
  back.cull = Cull::kFront;  // only the back-facing transparent triangle
  ASSERT_EQ(fed(back).size(), 2u);
  EXPECT_EQ(fed(back)[0].prim, 1u);

  PassState toward;
  toward.facing = FacingFilter::kToward;  // one fragment of each triangle faces the viewer
  EXPECT_EQ(fed(toward).size(), 2u);

  PassState zero;
  zero.zero_alpha_toward = true;
  zero.constant_color = true;
  zero.color = {9, 9, 9, 200};
  for (const Fragment& f : fed(zero)) EXPECT_EQ(f.color.a, f.facing ? 0 : 200);
}

TEST(Feeder, OffsetsBySlopeAndDrawsEdgesAndCoverage) {
  PassState offset;
  offset.offset = DepthOffset{2, 256, 0};  // 2 units + 1.0 x slope
  const std::vector<Fragment> tri = fed(offset);
  ASSERT_EQ(tri.size(), 4u);
  EXPECT_EQ(tri[0].z, 1000u - 2 - 256);  // prim 0: slope 256
  EXPECT_EQ(tri[2].z, 1000u - 2);        // prim 1: slope 0

  PassState edges;
  edges.filter = PrimFilter::kEdges;
  edges.offset = DepthOffset{2, 256, 0};
  const std::vector<Fragment> line = fed(edges);
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line[0].z, 1000u - 2 - 512);  // the line's own slope

  PassState coverage;
  coverage.rop.blend = BlendMode::kCoverage;
  for (const Fragment& f : fed(coverage)) EXPECT_EQ(f.coverage, 1);
}

}  // namespace
}  // namespace zb
