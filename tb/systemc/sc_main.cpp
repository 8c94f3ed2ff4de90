// zblend_systemc: the golden model and the Verilated RTL as SystemC modules on one clock, fed one
// stream (a method's passes on a scene, or a trace file), compared after every pass.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <systemc>

#include "cli.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rtl_params.h"
#include "scene/builtin_scenes.h"
#include "scene_options.h"
#include "io/trace.h"
#include "zb_cosim_sc.h"
#include "zb_golden_sc.h"
#include "zb_rtl_sc.h"

namespace {

using zb::cli::UsageError;

struct Options {
  std::string scene = "cad";
  std::string method = "three-pass";
  int width = 640, height = 480;
  std::string trace;
  bool quiet = false;
};

// The streams to run: the trace file, or each method's trace on the scene.
std::vector<std::pair<std::string, zb::Trace>> make_traces(const Options& o) {
  std::vector<std::pair<std::string, zb::Trace>> out;
  if (!o.trace.empty()) {
    try {
      out.emplace_back(o.trace, zb::read_trace(o.trace));
    } catch (const zb::TraceError& e) {
      throw UsageError(fmt::format("--trace: {}", e.what()));
    }
    const zb::Trace& t = out.back().second;
    if (t.depth_bits != zb::kRtlDepthBits || t.coverage_samples != zb::kRtlCoverageSamples ||
        t.wboit != zb::kRtlWboit)
      throw UsageError(fmt::format(
          "--trace: {} depth bits, {} coverage samples, accumulation/revealage/weight bits "
          "{}/{}/{}; the Verilated zb_rop has {}, {}, {}/{}/{}",
          t.depth_bits, t.coverage_samples, t.wboit.acc_bits, t.wboit.rev_bits,
          t.wboit.weight_bits, zb::kRtlDepthBits, zb::kRtlCoverageSamples, zb::kRtlWboit.acc_bits,
          zb::kRtlWboit.rev_bits, zb::kRtlWboit.weight_bits));
    return out;
  }
  const zb::Viewport vp = zb::cli::check_viewport(o.width, o.height, zb::kDefaultDepthBits);
  std::vector<std::string> methods = zb::cli::parse_methods(o.method);
  // The reference is exact floating point, not a pass plan: nothing to stream.
  if (o.method == "all")
    methods.erase(std::remove(methods.begin(), methods.end(), std::string(zb::kReferenceMethod)),
                  methods.end());
  for (const std::string& m : methods)
    if (!zb::find_plan(m))
      throw UsageError(fmt::format("--method: '{}' is not a pass plan (no fragment stream)", m));
  std::vector<std::string> scenes{o.scene};
  if (o.scene == "all") {  // every built-in scene
    scenes.clear();
    for (const zb::SceneInfo& s : zb::builtin_scenes()) scenes.push_back(s.name);
  }
  for (const std::string& scene : scenes) {
    const zb::RasterizedScene rs = zb::rasterize_scene(zb::cli::resolve_scene(scene), vp);
    for (const std::string& m : methods)
      out.emplace_back(scenes.size() > 1 ? scene + "/" + m : m,
                       zb::make_trace(rs, *zb::find_plan(m)));
  }
  return out;
}

constexpr double kClockNs = 10;  // the nominal 100 MHz clock

int run(const Options& o) {
  std::vector<std::pair<std::string, zb::Trace>> traces = make_traces(o);
  sc_core::sc_clock clk("clk", kClockNs, sc_core::SC_NS);
  zb::sc::ZbGoldenSc golden("golden");
  zb::sc::ZbRtlSc rtl("rtl");
  zb::sc::ZbCosimSc cosim("cosim", std::move(traces), golden, rtl, clk.period());
  sc_core::sc_fifo<zb::sc::PassCommand> gcmd(16), rcmd(16);
  sc_core::sc_fifo<zb::Fragment> gfrag(4096), rfrag(4096);
  sc_core::sc_fifo<zb::PassStats> gstats(2), rstats(2);
  golden.clk_i(clk);
  golden.cmd_i(gcmd);
  golden.frag_i(gfrag);
  golden.stats_o(gstats);
  rtl.clk_i(clk);
  rtl.cmd_i(rcmd);
  rtl.frag_i(rfrag);
  rtl.stats_o(rstats);
  cosim.golden_cmd_o(gcmd);
  cosim.rtl_cmd_o(rcmd);
  cosim.golden_frag_o(gfrag);
  cosim.rtl_frag_o(rfrag);
  cosim.golden_stats_i(gstats);
  cosim.rtl_stats_i(rstats);
  // sc_stop() (the driver, when done) would report itself as an info.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  sc_core::sc_start();

  bool ok = true;
  if (!o.quiet) {
    // The SystemC model is Verilated as the assertion build (docs/rtl.md "Two builds, two views").
    std::fprintf(stderr, "zblend_systemc: the RTL's assertion build, as SystemC modules\n");
    std::printf("%-24s %9s %6s %10s %12s %12s %12s %12s %12s %10s %12s\n", "method",
                "fragments", "passes", "mismatches", "golden ns", "golden cyc", "rtl ns",
                "rtl cyc", "rtl stream", "wall ms", "wall ns/frag");
  }
  for (const zb::sc::CosimResult& r : cosim.results()) {
    const double gns = r.golden_time.to_seconds() * 1e9, rns = r.rtl_time.to_seconds() * 1e9;
    if (!o.quiet)
      std::printf("%-24s %9llu %6llu %10llu %12.0f %12.0f %12.0f %12.0f %12llu %10.1f %12.1f\n",
                  r.name.c_str(), static_cast<unsigned long long>(r.fragments),
                  static_cast<unsigned long long>(r.passes),
                  static_cast<unsigned long long>(r.mismatches), gns, gns / kClockNs, rns,
                  rns / kClockNs, static_cast<unsigned long long>(r.rtl_stream_cycles), r.wall_ms,
                  r.fragments ? r.wall_ms * 1e6 / double(r.fragments) : 0.0);
    // The golden module waits by zb_rop's issue rule and the driver's tile traffic: its cycles
    // are the RTL's, streaming and tile.
    if (r.mismatches == 0 && (r.golden_stream_cycles != r.rtl_stream_cycles ||
                              r.golden_tile_cycles != r.rtl_tile_cycles)) {
      std::fprintf(stderr,
                   "zblend_systemc: FAILED: %s: golden timing %llu stream + %llu tile cycles, "
                   "rtl %llu + %llu\n",
                   r.name.c_str(), static_cast<unsigned long long>(r.golden_stream_cycles),
                   static_cast<unsigned long long>(r.golden_tile_cycles),
                   static_cast<unsigned long long>(r.rtl_stream_cycles),
                   static_cast<unsigned long long>(r.rtl_tile_cycles));
      ok = false;
    }
    if (r.mismatches != 0) {
      std::fprintf(stderr, "zblend_systemc: FAILED: %s: %llu mismatches; first: %s\n",
                   r.name.c_str(), static_cast<unsigned long long>(r.mismatches),
                   r.first_mismatch.c_str());
      ok = false;
    }
  }
  if (!o.quiet) std::printf("simulated %.0f ns in all\n", sc_core::sc_time_stamp().to_seconds() * 1e9);
  return ok ? 0 : 1;
}

}  // namespace

// SystemC prints its banner before sc_main unless told otherwise: main() is ours, then.
int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}

int sc_main(int argc, char** argv) {
  CLI::App app{"zblend_systemc: the golden model and the Verilated RTL as SystemC modules, "
               "co-simulated on one clock and compared after every pass (docs/systemc.md)"};
  app.name("zblend_systemc");
  Options o;
  app.add_option("--scene,-s", o.scene, "Built-in scene, a scene file (.obj, .gltf, .glb), or 'all' (every built-in one)")
      ->capture_default_str();
  app.add_option("--method,-m", o.method, "Method, a comma-separated list, or 'all'")
      ->capture_default_str();
  app.add_option("--width,-W", o.width, "Frame width in pixels")->capture_default_str();
  app.add_option("--height,-H", o.height, "Frame height in pixels")->capture_default_str();
  CLI::Option* trace =
      app.add_option("--trace", o.trace, "Run a trace file (zblend trace) instead of a scene");
  trace->excludes("--scene")->excludes("--method")->excludes("--width")->excludes("--height");
  app.add_flag("--quiet,-q", o.quiet, "Print nothing but failures");
  return zb::cli::run_main(app, argc, argv, [&o] { return run(o); });
}
