// Benchmarks of the RTL (the Verilated zb_rop behind zb::RtlRop): simulation speed and
// sustained fragments per clock on the hazard suite's stimulus, and `cad` three-pass on the RTL
// against the golden model. Built twice, on the speed build and on the assertion build; the
// context's rtl_build says which.
#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "rtl_rop.h"
#include "scene/builtin_scenes.h"
#include "stimulus.h"
#include "Vceiling_counter.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The hazard suite's stimulus (seed 1): four passes of runs on 1-4 pixels of one tile, mostly
// in states that read and write the pixel. RtlRop alone, no back-pressure: every cycle of a
// pass offers a fragment, so fragments per streaming cycle is the sustained rate.
void BM_RtlHazard(benchmark::State& state) {
  struct Pass {
    zb::RopState state;
    std::vector<zb::Fragment> fragments;
  };
  zb::tb::HazardStimulus stim(1);
  std::vector<Pass> passes(4);
  for (Pass& p : passes) {
    p.state = stim.next_state();
    p.fragments = stim.next_fragments(size_t(state.range(0)) / passes.size());
  }
  zb::RtlRop rtl;
  rtl.begin_frame(zb::kRtlTileW, zb::kRtlTileH, zb::kRtlDepthBits, {10, 20, 30, 40});
  uint64_t fragments = 0, stream_cycles = 0;
  const uint64_t cycles_before = rtl.total_cycles();
  for (auto _ : state) {
    for (const Pass& p : passes) {
      rtl.begin_pass(p.state);
      rtl.draw(p.fragments);
      const zb::PassStats s = rtl.end_pass();
      fragments += s.fragments_in;
      stream_cycles += s.cycles;
    }
  }
  state.SetItemsProcessed(int64_t(fragments));  // items_per_second: fragments per second
  state.counters["fragments_per_clock"] =
      stream_cycles ? double(fragments) / double(stream_cycles) : 0.0;
  // Every simulated clock, tile load and store included.
  state.counters["cycles_per_second"] = benchmark::Counter(
      double(rtl.total_cycles() - cycles_before), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RtlHazard)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// Verilator's ceiling: a 32-bit counter clocked as RtlRop clocks zb_rop (inputs set, a rising
// and a falling edge, one evaluation each). zb_rop's cycles_per_second over this one's is the
// share of the simulation the design itself takes.
void BM_VerilatorCeiling(benchmark::State& state) {
  VerilatedContext ctx;
  Vceiling_counter top(&ctx);
  top.clk_i = 0;
  top.eval();
  uint64_t cycles = 0;
  for (auto _ : state) {
    for (int i = 0; i < 1 << 20; ++i) {
      top.en_i = i & 1;
      top.clk_i = 1;
      top.eval();
      top.clk_i = 0;
      top.eval();
    }
    cycles += 1 << 20;
  }
  benchmark::DoNotOptimize(top.cnt_o);
  state.counters["cycles_per_second"] = benchmark::Counter(double(cycles), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VerilatorCeiling)->Unit(benchmark::kMillisecond);

// `cad` with three-pass, rasterized once; each iteration renders it on a fresh backend.
struct CadFrame {
  zb::RasterizedScene rs;
  const zb::PassPlan* plan;
  CadFrame(int w, int h)
      : rs(zb::rasterize_scene(*zb::builtin_scene("cad"),
                               zb::Viewport{w, h, zb::kDefaultDepthBits})),
        plan(zb::find_plan("three-pass")) {}
};

void BM_CadThreePassGolden(benchmark::State& state) {
  const CadFrame cad(int(state.range(0)), int(state.range(1)));
  for (auto _ : state) {
    zb::GoldenRop rop;
    benchmark::DoNotOptimize(zb::render(cad.rs, *cad.plan, rop));
  }
  state.counters["raster_fragments"] = double(cad.rs.fragments.size());
}
BENCHMARK(BM_CadThreePassGolden)->Args({640, 480})->Unit(benchmark::kMillisecond);

// The same frame on the RTL, with range(2) models side by side; also times the golden model on
// it (one thread, mean of a few renders) for rtl_over_golden, the ratio of the wall times.
void BM_CadThreePassRtl(benchmark::State& state) {
  const CadFrame cad(int(state.range(0)), int(state.range(1)));
  zb::RtlOptions options;
  options.threads = int(state.range(2));
  double rtl_sec = 0;
  uint64_t stream_cycles = 0, all_cycles = 0, fragments = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    zb::RtlRop rop(options);
    const zb::RenderResult r = zb::render(cad.rs, *cad.plan, rop);
    rtl_sec += seconds_since(t0);
    benchmark::DoNotOptimize(r);
    stream_cycles = fragments = 0;
    for (const zb::PassStats& p : r.passes) {
      stream_cycles += p.cycles;
      fragments += p.fragments_in;
    }
    all_cycles = rop.total_cycles();
  }
  // After the timed loop: not in the benchmark's own time.
  int golden_runs = 0;
  const auto g0 = Clock::now();
  do {
    zb::GoldenRop rop;
    benchmark::DoNotOptimize(zb::render(cad.rs, *cad.plan, rop));
    ++golden_runs;
  } while (golden_runs < 5 || seconds_since(g0) < 0.5);
  const double golden_sec = seconds_since(g0) / golden_runs;
  const double rtl_per_frame = rtl_sec / double(state.iterations());
  state.counters["golden_ms"] = golden_sec * 1e3;
  state.counters["rtl_over_golden"] = rtl_per_frame / golden_sec;
  state.counters["stream_cycles"] = double(stream_cycles);  // per frame
  state.counters["all_cycles"] = double(all_cycles);        // per frame, with tile load/store
  // Streaming cycles include each tile's drain: a real frame's rate, interlock stalls and all.
  state.counters["fragments_per_clock"] = stream_cycles ? double(fragments) / double(stream_cycles) : 0;
  state.counters["fragments_per_second"] = double(fragments) / rtl_per_frame;
}
BENCHMARK(BM_CadThreePassRtl)
    ->ArgNames({"w", "h", "models"})
    ->Args({640, 480, 1})
    ->Args({640, 480, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("rtl_build", zb::RtlRop::build());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
