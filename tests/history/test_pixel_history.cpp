// A pixel's history (cmodel/history/): a pixel worked by hand, every pixel of small frames under
// every method replayed to the framebuffer, and the replay catching a history with a write left
// out, in memory and through its JSON.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "history/history_report.h"
#include "history/pixel_history.h"
#include "io/trace.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"

namespace zb {
namespace {

constexpr int kW = 16, kH = 16;

// A square over the whole 16 x 16 frame at depth z, in two triangles.
std::vector<ScreenTriangle> square(uint32_t z, Rgba8 color, uint32_t prim) {
  auto v = [z](int x, int y) {
    ScreenVertex s;
    s.x = x * kSubpixelOne;
    s.y = y * kSubpixelOne;
    s.z = z;
    s.z_exact = double(z) / depth_max(kDefaultDepthBits);
    return s;
  };
  ScreenTriangle a, b;
  a.v[0] = v(0, 0), a.v[1] = v(kW, 0), a.v[2] = v(kW, kH);
  b.v[0] = v(0, 0), b.v[1] = v(kW, kH), b.v[2] = v(0, kH);
  a.color = b.color = color;
  a.transparent = b.transparent = color.a < 255;
  a.prim = prim;
  b.prim = prim + 1;
  return {a, b};
}

// An opaque blue square behind a red one of alpha 128, on a white background.
RasterizedScene two_squares() {
  std::vector<ScreenTriangle> t = square(0x800000, Rgba8{0, 0, 255, 255}, 0);
  const std::vector<ScreenTriangle> front = square(0x400000, Rgba8{255, 0, 0, 128}, 2);
  t.insert(t.end(), front.begin(), front.end());
  return rasterize_triangles(t, Viewport{kW, kH}, Rgba8{255, 255, 255, 255});
}

// three-pass at pixel (5, 9), by hand from docs/datapath.md: m(x, y) = (t + (t >> 8) + 128) >> 8
// with t = x * y; alpha blend min(255, m(s, a) + m(d, 255 - a)) per channel.
//   pass 0 (opaque, replace): blue writes (0,0,255,255) and depth 0x800000.
//   pass 1 (transparent, no depth write): red passes, 0x400000 < 0x800000:
//     R m(255,128) + m(0,127) = 128; G 0; B m(0,128) + m(255,127) = 0 + 127;
//     A m(128,128) + m(255,127) = 64 + 127 = 191.
//   pass 2 (transparent, depth write): red passes again and writes its depth:
//     R 128 + m(128,127) = 128 + 64 = 192; G 0; B m(127,127) = 63; A 64 + m(191,127) = 64 + 95.
TEST(PixelHistory, ThreePassPixelByHand) {
  const FrameHistory f = record_history(two_squares(), *find_plan("three-pass"), {{5, 9}});
  ASSERT_EQ(f.pixels.size(), 1u);
  const PixelHistory& h = f.pixels[0];
  EXPECT_EQ(h.first.color, (Rgba8{255, 255, 255, 255}));
  EXPECT_EQ(h.first.depth, depth_max(kDefaultDepthBits));
  ASSERT_EQ(h.events.size(), 3u);  // one fragment of one square per pass

  const HistoryEvent& opaque = h.events[0];
  EXPECT_EQ(opaque.pass, 0u);
  EXPECT_EQ(opaque.fragment.fragment.color, (Rgba8{0, 0, 255, 255}));
  EXPECT_TRUE(opaque.fragment.depth_passed);
  EXPECT_TRUE(opaque.fragment.writes.depth);
  EXPECT_EQ(opaque.fragment.writes.z, 0x800000u);
  EXPECT_EQ(opaque.after.color, (Rgba8{0, 0, 255, 255}));

  const HistoryEvent& back = h.events[1];
  EXPECT_EQ(back.pass, 1u);
  EXPECT_TRUE(back.fragment.depth_tested);
  EXPECT_TRUE(back.fragment.depth_passed);
  EXPECT_FALSE(back.fragment.writes.depth);
  EXPECT_EQ(back.fragment.blended, (Rgba8{128, 0, 127, 191}));
  EXPECT_EQ(back.after.depth, 0x800000u);

  const HistoryEvent& front = h.events[2];
  EXPECT_EQ(front.pass, 2u);
  EXPECT_EQ(front.before.color, (Rgba8{128, 0, 127, 191}));
  EXPECT_EQ(front.fragment.writes.rgba, (Rgba8{192, 0, 63, 159}));
  EXPECT_EQ(front.fragment.writes.z, 0x400000u);
  EXPECT_EQ(h.final_value.color, (Rgba8{192, 0, 63, 159}));
  EXPECT_EQ(h.final_value.depth, 0x400000u);

  // The exact reference there: red (alpha 128/255) over blue, in double, rounded once:
  // R 255 * 128/255 = 128, B 255 * 127/255 = 127. three-pass blends red twice.
  ASSERT_TRUE(h.reference.has_value());
  ASSERT_EQ(h.reference->layers.size(), 2u);
  EXPECT_EQ(h.reference->layers[0].color, (Rgba8{255, 0, 0, 128}));
  EXPECT_EQ(h.reference->layers[1].color, (Rgba8{0, 0, 255, 255}));
  EXPECT_EQ(h.reference->behind, 0u);
  EXPECT_EQ(h.reference->color, (Rgba8{128, 0, 127, 255}));
  EXPECT_GT(h.delta_e, 5.0);

  const std::string text = history_text(f, h);
  EXPECT_NE(text.find("depth less 0x400000"), std::string::npos) << text;
  EXPECT_NE(text.find("composited: colour (128,0,127,255)"), std::string::npos) << text;
  // Pass 1's roundings, as worked out above.
  EXPECT_NE(text.find("roundings: R m(255,128)+m(0,127)=128+0=128, G m(0,128)+m(0,127)=0+0=0, "
                      "B m(0,128)+m(255,127)=0+127=127, A m(128,128)+m(255,127)=64+127=191\n"),
            std::string::npos) << text;
  EXPECT_NE(text.find("= (128,0,127,191)"), std::string::npos) << text;
  EXPECT_NE(text.find("final  colour (192,0,63,159)"), std::string::npos) << text;
}

// A fragment that fails the depth test is in the history with nothing written.
TEST(PixelHistory, AFailedDepthTestWritesNothing) {
  const FrameHistory f = record_history(two_squares(), *find_plan("opaque"), {{0, 0}});
  const PixelHistory& h = f.pixels[0];
  // opaque draws every triangle with replace: blue at 0x800000, then red nearer, which wins.
  ASSERT_EQ(h.events.size(), 2u);
  EXPECT_TRUE(h.events[1].fragment.depth_passed);
  const FrameHistory g = record_history(two_squares(), *find_plan("opaque"), {{0, 0}});
  EXPECT_EQ(g.pixels[0].final_value, h.final_value);

  // Drawn the other way round, the far one fails.
  std::vector<ScreenTriangle> t = square(0x400000, Rgba8{255, 0, 0, 255}, 0);
  const std::vector<ScreenTriangle> far = square(0x800000, Rgba8{0, 0, 255, 255}, 2);
  t.insert(t.end(), far.begin(), far.end());
  const FrameHistory r = record_history(rasterize_triangles(t, Viewport{kW, kH}, Rgba8{}),
                                        *find_plan("opaque"), {{3, 3}});
  ASSERT_EQ(r.pixels[0].events.size(), 2u);
  const FragmentRecord& lost = r.pixels[0].events[1].fragment;
  EXPECT_FALSE(lost.depth_passed);
  EXPECT_FALSE(lost.writes.color || lost.writes.depth);
  EXPECT_NE(history_text(r, r.pixels[0]).find(": fail; nothing written"), std::string::npos);
}

Fragment at(int x, int y, uint32_t z, Rgba8 c, uint8_t coverage = 0) {
  Fragment f;
  f.x = uint16_t(x), f.y = uint16_t(y), f.z = z, f.color = c, f.coverage = coverage;
  return f;
}

// The coverage blend's cases and the accumulate blend's terms, step by step, by hand from
// docs/datapath.md (N = 4 samples, 24-bit depth cleared to ZMAX = 0xffffff, A = 16, R = 8, W = 4).
//   coverage at (1, 1) on (0,0,0,255), cs 0:
//     z 0x400000 < ZMAX, nearer, w = k = 3: R (3*200+1*0+2)>>2 = 150, G (300+2)>>2 = 75, B 0,
//       A (765+255+2)>>2 = 255; coverage min(4, 3+0) = 3.
//     z 0x800000 > 0x400000, farther, w = cs = 3 on the stored colour: R (3*150+1*0+2)>>2 = 113,
//       G (225+2)>>2 = 56, B (0+255+2)>>2 = 64; coverage min(4, 2+3) = 4.
//   accumulate at (2, 2) from acc 0, r 255:
//     z 0x7fffff: u = 0x800000 >> 16 = 128, F = 128^3 >> 20 = 2, w = 128*2 = 256, S = 4+20-16 = 8;
//       R p = m(255,128) = 128, term 128*256>>8 = 128; G p = m(128,128) = 64, term 64; B 0;
//       A p = 128, term 128; revealage k = 127, t = 127, (255*127+128)>>8 = 127.
//     z 0x3fffff: u = 192, F = 7077888 >> 20 = 6, w = 255*6 = 1530; B p = m(255,255) = 255,
//       term 255*1530>>8 = 1524, acc 0+1524 = 1524; A acc 128+1524 = 1652; revealage t = 0: 0.
TEST(PixelHistory, CoverageAndAccumulateStepsByHand) {
  Trace t;
  t.width = t.height = 4;
  t.coverage_samples = 4;
  t.clear_color = Rgba8{0, 0, 0, 255};
  TracePass cov;
  cov.state.blend = BlendMode::kCoverage;
  cov.fragments = {at(1, 1, 0x400000, {200, 100, 0, 255}, 3), at(1, 1, 0x800000, {0, 0, 255, 255}, 2)};
  TracePass acc;
  acc.state.blend = BlendMode::kAccumulate;
  acc.state.depth_write = false;
  acc.fragments = {at(2, 2, 0x7fffff, {255, 128, 0, 128}), at(2, 2, 0x3fffff, {0, 0, 255, 255})};
  t.passes = {cov, acc};
  const FrameHistory f = record_history(t, {{1, 1}, {2, 2}});
  const std::string c = history_text(f, f.pixels[0]), a = history_text(f, f.pixels[1]);
  EXPECT_NE(c.find("case nearer (z < Zs): w=k=3, coverage min(N,k+cs)=min(4,3+0)=3; "
                   "R (3*200+1*0+2)>>2=150; G (3*100+1*0+2)>>2=75; B (3*0+1*0+2)>>2=0; "
                   "A (3*255+1*255+2)>>2=255"), std::string::npos) << c;
  EXPECT_NE(c.find("case farther (z > Zs): stored keeps its cs=3, coverage min(N,k+cs)=min(4,2+3)=4; "
                   "R (3*150+1*0+2)>>2=113; G (3*75+1*0+2)>>2=56; B (3*0+1*255+2)>>2=64"),
            std::string::npos) << c;
  EXPECT_EQ(f.pixels[0].final_value.color, (Rgba8{113, 56, 64, 255}));
  EXPECT_NE(a.find("u=128 F=max(1,u^3>>20)=2 w=a*F=128*2=256 S=8; R p=m(255,128)=128, p*w>>S=128, "
                   "acc 0+128=128; G p=m(128,128)=64, p*w>>S=64, acc 0+64=64; B p=m(0,128)=0, p*w>>S=0, "
                   "acc 0+0=0; A p=a=128, p*w>>S=128, acc 0+128=128; revealage k=255-a=127 "
                   "t=k+(k>>7)=127 (255*t+128)>>8=127"), std::string::npos) << a;
  EXPECT_NE(a.find("u=192 F=max(1,u^3>>20)=6 w=a*F=255*6=1530 S=8"), std::string::npos) << a;
  EXPECT_NE(a.find("B p=m(255,255)=255, p*w>>S=1524, acc 0+1524=1524; A p=a=255, p*w>>S=1524, "
                   "acc 128+1524=1652; revealage k=255-a=0 t=k+(k>>7)=0 (127*t+128)>>8=0"),
            std::string::npos) << a;
  EXPECT_EQ(f.pixels[1].final_value.acc, (std::array<uint32_t, 4>{128, 64, 1524, 1652}));
  EXPECT_EQ(f.pixels[1].final_value.reveal, 0u);
}

// mlab-K's insert, merge and resolve, step by step, by hand from docs/datapath.md "8. Layers"
// (K = 2, at (1, 1) over an opaque blue at 0x800000):
//   f1 z 0x300000 (200,0,0,128): p = m(200,128) = 100: (100,0,0) a 128 at position 0;
//   f2 z 0x100000 (0,200,0,128): (0,100,0) a 128, nearer: at position 0;
//   f3 z 0x200000 (0,0,200,64): (0,0,m(200,64) = 50) a 64 goes between: K full, the two farthest
//     (f3 front, f1 back) merge, t = 255 - 64 = 191: R 0 + m(100,191) = 75, G 0, B 50 + 0 = 50,
//     A 64 + m(128,191) = 160, z 0x200000;
//   resolve: layer 0 under t = 255: (0,100,0,128); layer 1 under t = 127: R m(75,127) = 37,
//     G 100, B m(50,127) = 25, A 128 + m(160,127) = 208; over (0,0,255,255) with 47:
//     B 25 + m(255,47) = 72, A 255: (37,100,72,255).
TEST(PixelHistory, LayersStepsByHand) {
  Trace t;
  t.width = t.height = 4;
  t.clear_color = Rgba8{0, 0, 0, 255};
  TracePass opaque;
  opaque.fragments = {at(1, 1, 0x800000, {0, 0, 255, 255})};
  TracePass layers;
  layers.state.blend = BlendMode::kLayers;
  layers.state.layers = 2;
  layers.state.depth_write = false;
  layers.fragments = {at(1, 1, 0x300000, {200, 0, 0, 128}), at(1, 1, 0x100000, {0, 200, 0, 128}),
                      at(1, 1, 0x200000, {0, 0, 200, 64})};
  t.passes = {opaque, layers};
  t.final_ops = {FrameOp{FrameOpKind::kResolveLayers, Rgba8{}, 0, false}};
  const FrameHistory f = record_history(t, {{1, 1}});
  const std::string s = history_text(f, f.pixels[0]);
  EXPECT_NE(s.find("layer p=m(s,a) (100,0,0) a 128; inserted at position 0 (1 of 2 layers in use)"),
            std::string::npos) << s;
  EXPECT_NE(s.find("layer p=m(s,a) (0,100,0) a 128; inserted at position 0 (2 of 2 layers in use)"),
            std::string::npos) << s;
  EXPECT_NE(s.find("layer p=m(s,a) (0,0,50) a 64; inserted at 1; K = 2 full: the two farthest "
                   "merged into slot 1, z 0x200000 (0.125000) (F's); R 0+m(100,191)=75; G 0+m(0,191)=0; "
                   "B 50+m(0,191)=50; A 64+m(128,191)=160"), std::string::npos) << s;
  EXPECT_NE(s.find("roundings: layer 0 under t=255: (0,100,0,128); layer 1 under t=127: "
                   "(37,100,25,208); over (0,0,255,255) with 255-A=47"),
            std::string::npos) << s;
  EXPECT_EQ(f.pixels[0].final_value.color, (Rgba8{37, 100, 72, 255}));
  EXPECT_EQ(f.pixels[0].final_value.layers.n, 0);
  // Through its JSON: the layers come back and the history replays.
  const FrameHistory back = parse_history_json(history_json(f, "trace", "mlab-2"));
  ASSERT_EQ(back.pixels.size(), 1u);
  EXPECT_FALSE(replay_error(back.pixels[0], back).has_value());
  EXPECT_EQ(history_text(back, back.pixels[0]), s);
}

// Every pixel of a small frame of each built-in scene under every method: each history replays
// (record_history throws otherwise) and ends at the golden model's own framebuffer, rendered
// without a recorder.
TEST(PixelHistory, EveryPixelOfSmallFramesReplaysToTheFramebuffer) {
  constexpr int w = 24, h = 18;
  std::vector<std::pair<int, int>> all;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) all.emplace_back(x, y);
  size_t fragments = 0, ops = 0;
  for (const char* scene : {"cad", "crossing-quads", "parts"}) {
    const RasterizedScene rs = rasterize_scene(*builtin_scene(scene), Viewport{w, h});
    for (const PassPlan& plan : pass_plans()) {
      const FrameHistory f = record_history(rs, plan, all);
      GoldenRop golden;
      const Framebuffer fb = render(rs, plan, golden).framebuffer;
      for (const PixelHistory& p : f.pixels) {
        const PixelValue v = PixelValue::of(fb, fb.index(p.x, p.y));
        ASSERT_EQ(p.final_value, v) << scene << " " << plan.name << " (" << p.x << ", " << p.y << ")";
        for (const HistoryEvent& e : p.events)
          (e.kind == HistoryEvent::Kind::kFragment ? fragments : ops) += 1;
      }
    }
  }
  EXPECT_GT(fragments, 10000u);  // the frames are not empty
  EXPECT_GT(ops, 1000u);         // depth peeling's frame operations are in them
}

// A few scattered pixels, so the recorder drops every other pixel's fragments: their histories
// still end at a full golden render's planes, from a scene and from the same frame's trace (a
// datapath step that read a neighbour would show here). The stream indices count every fragment.
TEST(PixelHistory, ScatteredPixelsEndAsInAFullRender) {
  constexpr int w = 40, h = 30;
  std::vector<std::pair<int, int>> some;
  for (int k = 0; k < w * h; k += 37) some.emplace_back(k % w, k / w);
  size_t events = 0;
  for (const char* scene : {"cad", "parts"}) {
    const RasterizedScene rs = rasterize_scene(*builtin_scene(scene), Viewport{w, h});
    for (const PassPlan& plan : pass_plans()) {
      GoldenRop golden;
      const Framebuffer fb = render(rs, plan, golden).framebuffer;
      const Trace trace = make_trace(rs, plan);
      for (const FrameHistory& f : {record_history(rs, plan, some), record_history(trace, some)}) {
        ASSERT_EQ(f.pixels.size(), some.size());
        for (const PixelHistory& p : f.pixels) {
          ASSERT_EQ(p.final_value, PixelValue::of(fb, fb.index(p.x, p.y)))
              << scene << " " << plan.name << " (" << p.x << ", " << p.y << ")";
          for (const HistoryEvent& e : p.events) {
            if (e.kind != HistoryEvent::Kind::kFragment) continue;
            const std::vector<Fragment>& stream = trace.passes[e.pass].fragments;
            ASSERT_LT(e.fragment.index, stream.size());
            const Fragment& g = stream[e.fragment.index];
            EXPECT_TRUE(g.x == p.x && g.y == p.y && g.z == e.fragment.fragment.z);
            ++events;
          }
        }
      }
    }
  }
  EXPECT_GT(events, 1000u);
}

// The first history with a write in it, of depth-peel-2 on `cad` (frame operations too).
std::pair<FrameHistory, size_t> peel_history() {
  const RasterizedScene rs = rasterize_scene(*builtin_scene("cad"), Viewport{32, 24});
  std::vector<std::pair<int, int>> all;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) all.emplace_back(x, y);
  FrameHistory f = record_history(rs, *find_plan("depth-peel-2"), all);
  for (size_t p = 0; p < f.pixels.size(); ++p)
    for (const HistoryEvent& e : f.pixels[p].events)
      if (e.kind == HistoryEvent::Kind::kFragment && e.fragment.writes.color) return {f, p};
  return {f, f.pixels.size()};
}

TEST(PixelHistory, ReplayFailsWithAWriteLeftOut) {
  auto [f, p] = peel_history();
  ASSERT_LT(p, f.pixels.size());
  PixelHistory h = f.pixels[p];
  EXPECT_FALSE(replay_error(h, f).has_value());
  size_t k = 0;
  while (!(h.events[k].kind == HistoryEvent::Kind::kFragment && h.events[k].fragment.writes.color)) ++k;

  PixelHistory dropped = h;  // the write's event left out
  dropped.events.erase(dropped.events.begin() + std::ptrdiff_t(k));
  const auto error = replay_error(dropped, f);
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("colour"), std::string::npos) << *error;

  PixelHistory silent = h;  // the event kept, its colour write not
  silent.events[k].fragment.writes.color = false;
  EXPECT_TRUE(replay_error(silent, f).has_value());

  PixelHistory wrong_op = h;  // a frame operation that is not the one that ran
  for (HistoryEvent& e : wrong_op.events)
    if (e.kind == HistoryEvent::Kind::kFrameOp && e.before != e.after) {
      e.op.kind = e.op.kind == FrameOpKind::kClearColor ? FrameOpKind::kClearDepth : FrameOpKind::kClearColor;
      e.op.value = Rgba8{1, 2, 3, 4};
      break;
    }
  EXPECT_TRUE(replay_error(wrong_op, f).has_value());
}

TEST(PixelHistory, JsonParsesBackAndReplays) {
  auto [f, p] = peel_history();
  ASSERT_LT(p, f.pixels.size());
  const FrameHistory back = parse_history_json(history_json(f, "cad", "depth-peel-2"));
  ASSERT_EQ(back.pixels.size(), f.pixels.size());
  ASSERT_EQ(back.passes.size(), f.passes.size());
  for (const PixelHistory& h : back.pixels) ASSERT_FALSE(replay_error(h, back).has_value());
  EXPECT_EQ(history_text(back, back.pixels[p]), history_text(f, f.pixels[p]));

  // The same document with one of its events taken out: its replay fails.
  FrameHistory cut = back;
  for (size_t k = 0; k < cut.pixels[p].events.size(); ++k)
    if (cut.pixels[p].events[k].fragment.writes.color) {
      cut.pixels[p].events.erase(cut.pixels[p].events.begin() + std::ptrdiff_t(k));
      break;
    }
  const FrameHistory cut_back = parse_history_json(history_json(cut, "cad", "depth-peel-2"));
  EXPECT_TRUE(replay_error(cut_back.pixels[p], cut_back).has_value());

  EXPECT_THROW(parse_history_json("{}"), std::invalid_argument);
  EXPECT_THROW(parse_history_json("not json"), std::invalid_argument);
  EXPECT_THROW(parse_history_json(R"({"zblend_pixel_history": 1, "width": 2})"), std::invalid_argument);
}

// The RTL's retires as the text shows them: cycles; a write that is not the golden model's, a
// retire missing, an extra one, a fragment with none, a final value that differs.
TEST(PixelHistory, RtlRetiresInTheText) {
  FrameHistory f = record_history(two_squares(), *find_plan("opaque"), {{2, 2}});
  PixelHistory& h = f.pixels[0];
  ASSERT_EQ(h.events.size(), 2u);
  const HistoryEvent& a = h.events[0];
  h.rtl_ran = true;
  h.rtl_final = h.final_value;
  const auto i = uint32_t(a.fragment.index);
  h.rtl.push_back({false, false, false, a.pass, i, i, 100, 108, a.fragment.writes});
  h.rtl.push_back({true, false, false, a.pass, i, i, 100, 115, a.fragment.writes});
  std::string t = history_text(f, h);
  EXPECT_NE(t.find("rtl: #" + std::to_string(i) + " accepted at cycle 100; X4 at cycle 108; X11 at cycle 115\n"), std::string::npos) << t;
  EXPECT_NE(t.find("rtl: no retire of this fragment seen"), std::string::npos) << t;  // the second
  EXPECT_NE(t.find("rtl    the same on every plane"), std::string::npos) << t;
  EXPECT_EQ(t.find("MISMATCH"), std::string::npos);

  h.rtl[1].writes.rgba.r ^= 1;  // X11 wrote another colour
  h.rtl[0].missing = true;
  h.rtl.push_back({true, true, false, 0, 0, 0, 0, 130, a.fragment.writes});
  h.rtl_final.color.r ^= 1;
  t = history_text(f, h);
  EXPECT_NE(t.find("X4 MISSING: never retired"), std::string::npos) << t;
  EXPECT_NE(t.find("X11 at cycle 115 MISMATCH: the RTL wrote colour"), std::string::npos) << t;
  EXPECT_NE(t.find("rtl: EXTRA X11 write at cycle 130"), std::string::npos) << t;
  EXPECT_NE(t.find("rtl    DIFFERS"), std::string::npos) << t;
}

TEST(PixelHistory, PixelsOutsideTheFrameOrTwiceAreRefused) {
  const RasterizedScene rs = two_squares();
  EXPECT_THROW(record_history(rs, *find_plan("opaque"), {{kW, 0}}), std::invalid_argument);
  EXPECT_THROW(record_history(rs, *find_plan("opaque"), {{1, 1}, {1, 1}}), std::invalid_argument);
}

}  // namespace
}  // namespace zb
