// Benchmarks of the golden model: the datapath alone in fragments per second, and whole frames.
#include <benchmark/benchmark.h>

#include <random>

#include "passes.h"
#include "render.h"
#include "rop.h"
#include "scenes.h"

namespace {

std::vector<zb::Fragment> random_fragments(size_t n, int w, int h) {
  std::mt19937 rng(1);
  std::vector<zb::Fragment> out(n);
  for (zb::Fragment& f : out) {
    f.x = uint16_t(rng() % uint32_t(w));
    f.y = uint16_t(rng() % uint32_t(h));
    f.z = rng() & 0xffffff;
    f.color = {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
  }
  return out;
}

// The datapath alone: depth LESS, alpha blend, z-write on, random pixels of 1024x768.
void BM_GoldenDatapath(benchmark::State& state) {
  const auto frags = random_fragments(1 << 20, 1024, 768);
  zb::RopState rop;
  rop.blend = zb::BlendMode::kAlpha;
  zb::GoldenRop golden;
  golden.begin_frame(1024, 768, zb::kDefaultDepthBits, {255, 255, 255, 255});
  for (auto _ : state) {
    golden.begin_pass(rop);
    golden.draw(frags);
    benchmark::DoNotOptimize(golden.end_pass());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(frags.size()));
}
BENCHMARK(BM_GoldenDatapath)->Unit(benchmark::kMillisecond);

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
