// Benchmarks of the golden model: the datapath alone in fragments per second, and whole frames.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>

#include "pipeline/frame_render.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"

namespace {

// Spans of 32 fragments along a row at random places of a w x h frame (the rasterizer's
// order, without its cost), random depths and colours.
std::vector<zb::Fragment> span_fragments(size_t n, int w, int h) {
  constexpr int kSpan = 32;
  std::mt19937 rng(1);
  std::vector<zb::Fragment> out(n);
  for (size_t i = 0; i < n; i += kSpan) {
    const int x0 = int(rng() % uint32_t(w - kSpan)), y = int(rng() % uint32_t(h));
    for (size_t k = i; k < std::min(n, i + kSpan); ++k) {
      zb::Fragment& f = out[k];
      f.x = uint16_t(x0 + int(k - i));
      f.y = uint16_t(y);
      f.z = rng() & 0xffffff;
      f.color = {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
    }
  }
  return out;
}

// The datapath alone, per blend mode, on 2^20 fragments in spans over a 1024x32 frame: one band
// of render_frame (frame_render.h), whose planes stay in the cache as they do there. Depth
// function ALWAYS with z-write, so that every fragment runs the whole path (depth read and
// write, colour read, blend, colour write); coverage mode: coverage counts 0..16 and the three
// depth cases.
void BM_GoldenDatapath(benchmark::State& state, zb::BlendMode mode) {
  auto frags = span_fragments(1 << 20, 1024, zb::kDefaultBandRows);
  if (mode == zb::BlendMode::kCoverage)
    for (size_t i = 0; i < frags.size(); ++i) frags[i].coverage = uint8_t(i * 7 % 17);
  zb::RopState rop;
  rop.depth_func = zb::DepthFunc::kAlways;
  rop.blend = mode;
  zb::GoldenRop golden;
  golden.begin_frame(1024, zb::kDefaultBandRows, zb::kDefaultDepthBits, {255, 255, 255, 255});
  for (auto _ : state) {
    golden.begin_pass(rop);
    golden.draw(frags);
    benchmark::DoNotOptimize(golden.end_pass());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(frags.size()));
}
BENCHMARK_CAPTURE(BM_GoldenDatapath, replace, zb::BlendMode::kReplace)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GoldenDatapath, alpha, zb::BlendMode::kAlpha)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GoldenDatapath, additive, zb::BlendMode::kAdditive)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GoldenDatapath, coverage, zb::BlendMode::kCoverage)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GoldenDatapath, under, zb::BlendMode::kUnder)->Unit(benchmark::kMillisecond);

// The frame's planes alone, allocated and cleared: the part of a frame's cost that grows with
// the frame whatever the scene touches.
void BM_FrameBuffers(benchmark::State& state) {
  const int n = int(state.range(0));
  for (auto _ : state) {
    zb::Framebuffer fb(n, n, zb::kDefaultDepthBits, {255, 255, 255, 255});
    benchmark::DoNotOptimize(fb.color.data());
  }
}
BENCHMARK(BM_FrameBuffers)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Arg(4096)->Unit(benchmark::kMillisecond);

// A whole frame: geometry, raster and every pass of a method.
void BM_Frame(benchmark::State& state, const char* scene_name, const char* method) {
  const zb::Scene scene = *zb::builtin_scene(scene_name);
  const zb::PassPlan& plan = *zb::find_plan(method);
  const zb::Viewport vp{int(state.range(0)), int(state.range(1)), zb::kDefaultDepthBits};
  size_t fragments = 0;
  for (auto _ : state) {
    const zb::RasterizedScene rs = zb::rasterize_scene(scene, vp);
    zb::GoldenRop rop;
    benchmark::DoNotOptimize(zb::render(rs, plan, rop));
    fragments = rs.fragments.size();
  }
  state.counters["raster_fragments"] = double(fragments);
}
BENCHMARK_CAPTURE(BM_Frame, cad_three_pass, "cad", "three-pass")
    ->Args({1024, 768})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
