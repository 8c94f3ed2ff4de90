// The golden datapath: depth functions, depth write rules, write mask, blend modes, counters.
#include <gtest/gtest.h>

#include "rop/rop.h"

namespace {

using zb::DepthFunc;

TEST(Rop, DepthFunctionsTruthTable) {
  // Rows: function; columns: z < stored, z == stored, z > stored (GL semantics).
  struct Row { DepthFunc f; bool lt, eq, gt; };
  const Row rows[] = {
      {DepthFunc::kNever, false, false, false},  {DepthFunc::kLess, true, false, false},
      {DepthFunc::kEqual, false, true, false},   {DepthFunc::kLequal, true, true, false},
      {DepthFunc::kGreater, false, false, true}, {DepthFunc::kNotequal, true, false, true},
      {DepthFunc::kGequal, false, true, true},   {DepthFunc::kAlways, true, true, true},
  };
  for (const Row& r : rows) {
    EXPECT_EQ(zb::depth_test(r.f, 5, 6), r.lt) << zb::to_string(r.f);
    EXPECT_EQ(zb::depth_test(r.f, 6, 6), r.eq) << zb::to_string(r.f);
    EXPECT_EQ(zb::depth_test(r.f, 7, 6), r.gt) << zb::to_string(r.f);
    EXPECT_EQ(zb::depth_test(r.f, 0, 0xffffffffu), r.lt);
    EXPECT_EQ(zb::depth_test(r.f, 0xffffffffu, 0), r.gt);
  }
}

zb::Fragment frag(uint16_t x, uint16_t y, uint32_t z, zb::Rgba8 c) {
  zb::Fragment f;
  f.x = x;
  f.y = y;
  f.z = z;
  f.color = c;
  return f;
}

TEST(Rop, DepthWriteOnlyWhenTestEnabledAndPassed) {
  zb::GoldenRop rop;
  rop.begin_frame(2, 1, 24, {0, 0, 0, 255});
  zb::RopState s;
  s.depth_test = false;
  s.depth_write = true;
  rop.begin_pass(s);
  rop.process(frag(0, 0, 100, {10, 20, 30, 255}));
  zb::PassStats st = rop.end_pass();
  EXPECT_EQ(rop.framebuffer().depth_at(0, 0), zb::depth_max(24));  // GL: no write, test off
  EXPECT_EQ(rop.framebuffer().color_at(0, 0), (zb::Rgba8{10, 20, 30, 255}));
  EXPECT_EQ(st.depth_reads, 0u);
  EXPECT_EQ(st.depth_writes, 0u);

  s.depth_test = true;
  s.depth_func = DepthFunc::kLess;
  rop.begin_pass(s);
  rop.process(frag(1, 0, 100, {1, 2, 3, 255}));
  rop.process(frag(1, 0, 200, {4, 5, 6, 255}));  // farther: killed
  st = rop.end_pass();
  EXPECT_EQ(rop.framebuffer().depth_at(1, 0), 100u);
  EXPECT_EQ(rop.framebuffer().color_at(1, 0), (zb::Rgba8{1, 2, 3, 255}));
  EXPECT_EQ(st.fragments_in, 2u);
  EXPECT_EQ(st.fragments_passed, 1u);
  EXPECT_EQ(st.fragments_killed(), 1u);
  EXPECT_EQ(st.depth_reads, 2u);
  EXPECT_EQ(st.depth_writes, 1u);
  EXPECT_EQ(st.color_writes, 1u);
  EXPECT_EQ(st.color_reads, 0u);  // replace with the full mask does not read
}

// The write log the lock-step scoreboard expects: exactly the planes and values written.
TEST(Rop, ProcessReportsItsWrites) {
  zb::GoldenRop rop;
  rop.begin_frame(1, 1, 16, {9, 8, 7, 6});
  zb::RopState s;
  s.color_mask = zb::kMaskR | zb::kMaskB;
  rop.begin_pass(s);
  zb::PixelWrites w = rop.process(frag(0, 0, 5, {100, 110, 120, 130}));
  EXPECT_TRUE(w.depth);
  EXPECT_EQ(w.z, 5u);
  EXPECT_FALSE(w.coverage);
  EXPECT_TRUE(w.color);
  EXPECT_EQ(w.rgba, (zb::Rgba8{100, 8, 120, 6}));  // after the mask: what the plane holds
  w = rop.process(frag(0, 0, 7, {1, 1, 1, 1}));    // farther: killed, writes nothing
  EXPECT_FALSE(w.depth || w.coverage || w.color);
  s.depth_write = false;
  s.color_mask = 0;
  rop.begin_pass(s);
  w = rop.process(frag(0, 0, 4, {1, 1, 1, 1}));  // passes, writes nothing
  EXPECT_FALSE(w.depth || w.coverage || w.color);
  s.blend = zb::BlendMode::kCoverage;
  s.depth_write = true;
  s.color_mask = zb::kMaskRgba;
  rop.begin_pass(s);
  zb::Fragment f = frag(0, 0, 3, {50, 60, 70, 255});
  f.coverage = 4;
  w = rop.process(f);  // nearer: depth, coverage and colour
  EXPECT_TRUE(w.depth && w.coverage && w.color);
  EXPECT_EQ(w.z, 3u);
  EXPECT_EQ(w.cov, rop.framebuffer().coverage_at(0, 0));
  EXPECT_EQ(w.rgba, rop.framebuffer().color_at(0, 0));
  f.z = 9;
  w = rop.process(f);  // farther: coverage and colour, no depth
  EXPECT_FALSE(w.depth);
  EXPECT_TRUE(w.coverage && w.color);
}

TEST(Rop, ColorMaskKeepsMaskedChannels) {
  zb::GoldenRop rop;
  rop.begin_frame(1, 1, 16, {9, 8, 7, 6});
  zb::RopState s;
  s.color_mask = zb::kMaskR | zb::kMaskB;
  rop.begin_pass(s);
  rop.process(frag(0, 0, 5, {100, 110, 120, 130}));
  const zb::PassStats st = rop.end_pass();
  EXPECT_EQ(rop.framebuffer().color_at(0, 0), (zb::Rgba8{100, 8, 120, 6}));
  EXPECT_EQ(st.color_reads, 1u);
  EXPECT_EQ(rop.framebuffer().depth_at(0, 0), 5u);

  s.color_mask = 0;  // depth-only pass: depth written, colour untouched and not read
  rop.begin_pass(s);
  rop.process(frag(0, 0, 4, {1, 1, 1, 1}));
  const zb::PassStats st2 = rop.end_pass();
  EXPECT_EQ(rop.framebuffer().color_at(0, 0), (zb::Rgba8{100, 8, 120, 6}));
  EXPECT_EQ(rop.framebuffer().depth_at(0, 0), 4u);
  EXPECT_EQ(st2.color_reads + st2.color_writes, 0u);
}

TEST(Rop, BlendModesPerChannel) {
  const zb::Rgba8 s{200, 100, 0, 128}, d{50, 250, 255, 255};
  EXPECT_EQ(zb::blend(zb::BlendMode::kReplace, s, d), s);
  // Hand-computed: m(200,128)=100, m(50,127)=25 -> 125; m(100,128)=50, m(250,127)=125 -> 175;
  // m(0,128)=0, m(255,127)=127 -> 127; alpha: m(128,128)=64, m(255,127)=127 -> 191.
  EXPECT_EQ(zb::blend(zb::BlendMode::kAlpha, s, d), (zb::Rgba8{125, 175, 127, 191}));
  // Additive: d + m(s, a), saturating: 50+100, 250+50 -> 255, 255+0, 255+64 -> 255.
  EXPECT_EQ(zb::blend(zb::BlendMode::kAdditive, s, d), (zb::Rgba8{150, 255, 255, 255}));
}

}  // namespace
