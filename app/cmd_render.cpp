// zblend render: a scene through one or more methods on the golden model, the RTL or both,
// to PNG images, a table, summary.csv and JSON stats.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "cosim.h"
#include "pipeline/frame_render.h"
#include "io/image.h"
#include "metrics/memory_use.h"
#include "pipeline/passes.h"
#include "reference/reference.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "rtl_rop.h"
#include "summary.h"

namespace zb::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct RenderOptions {
  FrameOptions frame;
  std::string methods = "three-pass";
  std::string out;
  std::string out_dir;
  std::string stats;
  std::string backend = "golden";
  double backpressure = 0;
  uint64_t seed = 1;
  std::string waves;
  int threads = default_threads();  // golden: render_frame's workers
  bool no_error = false;            // skip the reference and the error columns
  bool quiet = false;
};

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

void check_options(const RenderOptions& o, size_t method_count) {
  if (o.out.empty() == o.out_dir.empty())
    throw UsageError("give exactly one of --out FILE.png (one method) or --out-dir DIR");
  if (!o.out.empty() && method_count != 1)
    throw UsageError("--out: takes one method; use --out-dir DIR for several");
  if (o.backend != "golden" && o.backend != "rtl" && o.backend != "both")
    throw UsageError(fmt::format("--backend: unknown backend '{}' (choose from golden, rtl, both)",
                                 o.backend));
  if (o.backend != "golden" && o.frame.depth_bits != kRtlDepthBits)
    throw UsageError(fmt::format("--depth-bits: the RTL model is built with {} bits, not {}",
                                 kRtlDepthBits, o.frame.depth_bits));
  check_threads(o.threads);
  if (!(o.backpressure >= 0 && o.backpressure < 1))
    throw UsageError(fmt::format("--backpressure: {} is out of range (0 to below 1)", o.backpressure));
  if (!o.waves.empty()) {
    if (o.backend == "golden") throw UsageError("--waves: needs --backend rtl or both");
    if (method_count != 1) throw UsageError("--waves: takes one method");
    check_writable("--waves", o.waves, ".fst");
  }
  if (!o.out.empty()) check_writable("--out", o.out, ".png");
  if (!o.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    check_writable("--out-dir", (fs::path(o.out_dir) / "summary.csv").string(), ".csv");
  }
  if (!o.stats.empty()) check_writable("--stats", o.stats, ".json");
}

// Runs one pass plan on the chosen backend. A mismatch between RTL and golden model is
// recorded in the run and its report printed; the caller fails the command at the end.
void run_plan(const RenderOptions& o, const RasterizedScene& rs, const PassPlan& plan,
              MethodRun& run) {
  RtlOptions rtl;
  rtl.backpressure = o.backpressure;
  rtl.seed = o.seed;
  rtl.trace_path = o.waves;
  std::unique_ptr<Backend> backend;
  if (o.backend == "golden") {
    backend = std::make_unique<GoldenRop>();
  } else if (o.backend == "rtl") {
    backend = std::make_unique<RtlRop>(rtl);
  } else {
    CosimOptions cosim;
    cosim.rtl = rtl;
    const fs::path dir = o.out_dir.empty() ? fs::path(o.out).parent_path() : fs::path(o.out_dir);
    cosim.mismatch_fst = (dir / ("mismatch-" + plan.name + ".fst")).string();
    backend = std::make_unique<Cosim>(cosim);
  }
  run.rtl = o.backend != "golden";
  run.compared = o.backend == "both";
  run.passes = plan.passes.size();
  run.total = PassStats{};
  try {
    for (const PassStats& p : render(rs, plan, *backend).passes) *run.total += p;
  } catch (const MismatchError& e) {
    fmt::print(stderr, "{}\n", e.what());
    run.mismatches = std::max<uint64_t>(1, static_cast<const Cosim&>(*backend).mismatches());
  }
  run.image = backend->framebuffer();
  if (const auto* r = dynamic_cast<const RtlRop*>(backend.get())) run.tile_io_cycles = r->tile_io_cycles();
  if (const auto* c = dynamic_cast<const Cosim*>(backend.get())) run.tile_io_cycles = c->rtl().tile_io_cycles();
}

// One pass plan on the golden model, the whole frame from the scene by the banded renderer
// (frame_render.h): geometry, raster and datapath, which host_ms times.
void run_golden(const RenderOptions& o, const Scene& scene, const Viewport& vp,
                const PassPlan& plan, MethodRun& run) {
  FrameRenderOptions options;
  options.threads = o.threads;
  RenderResult result = render_frame(scene, vp, plan, options);
  run.passes = plan.passes.size();
  run.total = PassStats{};
  for (const PassStats& p : result.passes) *run.total += p;
  run.image = std::move(result.framebuffer);
}

void run_render(const RenderOptions& o) {
  const Scene scene = resolve_scene(o.frame.scene, o.frame.camera);
#ifdef __GLIBC__
  // The scene loaders free large temporaries that glibc keeps resident; returned before the
  // frame's buffers are allocated, they stay out of the run's peak memory.
  malloc_trim(0);
#endif
  const std::vector<std::string> methods = parse_methods(o.methods);
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const bool reference_method =
      std::find(methods.begin(), methods.end(), kReferenceMethod) != methods.end();
  if (o.no_error && reference_method)
    throw UsageError("--no-error: the reference method is what errors are measured against; "
                     "drop one of them");
  check_options(o, methods.size());

  // The exact reference feeds the error columns (the table, summary.csv, --stats) and the
  // reference method; it needs the whole scene's fragments stored. The golden model renders
  // without them, so a golden run that writes only images skips both.
  const bool golden = o.backend == "golden";
  const bool need_reference =
      !o.no_error && (!o.quiet || !o.out_dir.empty() || !o.stats.empty() || reference_method);
  std::optional<RasterizedScene> rs;
  Framebuffer reference;
  double raster_ms = 0, reference_ms = 0;
  if (!golden || need_reference) {
    const auto t0 = Clock::now();
    // The reference draws no edges: the golden model's run sets them up itself.
    rs = golden ? rasterize_triangles(setup_triangles(scene, vp), vp, scene.background)
                : rasterize_scene(scene, vp);
    raster_ms = ms_since(t0);
  }
  if (need_reference) {
    const auto t1 = Clock::now();
    reference = render_reference(*rs);
    reference_ms = ms_since(t1);
  }
  if (!o.quiet && rs)
    fmt::print(stderr, "{}: {} triangles, {} fragments at {}x{} ({:.1f} ms geometry and raster), "
               "backend {}\n", o.frame.scene, rs->triangles.size(), rs->fragments.size(),
               o.frame.width, o.frame.height, raster_ms, o.backend);
  else if (!o.quiet)
    fmt::print(stderr, "{}: {} triangles at {}x{}, backend {}\n", o.frame.scene,
               scene.triangle_count(), o.frame.width, o.frame.height, o.backend);

  std::vector<MethodRun> runs;
  uint64_t mismatches = 0;
  for (const std::string& m : methods) {
    MethodRun run;
    run.method = m;
    const auto start = Clock::now();
    if (const PassPlan* plan = find_plan(m)) {
      if (golden)
        run_golden(o, scene, vp, *plan, run);
      else
        run_plan(o, *rs, *plan, run);
      run.host_ms = ms_since(start);
    } else {
      run.image = reference;
      run.host_ms = reference_ms;
    }
    if (need_reference) run.error = compare_images(run.image, reference);
    mismatches += run.mismatches;
    if (!o.quiet) fmt::print(stderr, "  {:<12} {:8.1f} ms\n", m, run.host_ms);
    runs.push_back(std::move(run));
  }

  for (const MethodRun& r : runs)
    write_or_fail(write_png(
        o.out.empty() ? (fs::path(o.out_dir) / (r.method + ".png")).string() : o.out, r.image));
  if (!o.out_dir.empty())
    write_or_fail(write_file_atomic((fs::path(o.out_dir) / "summary.csv").string(),
                                    summary_csv(runs, o.frame.depth_bits)));
  if (!o.stats.empty()) {
    // The stored fragments exist only where the reference (or the RTL) needed them.
    const nlohmann::json fragments = rs ? nlohmann::json(rs->fragments.size()) : nlohmann::json();
    const nlohmann::json fragment_bytes =
        rs ? nlohmann::json(rs->fragments.size() * kReferenceFragmentBytes) : nlohmann::json();
    const nlohmann::json header = {
        {"scene", o.frame.scene},
        {"width", o.frame.width},
        {"height", o.frame.height},
        {"depth_bits", o.frame.depth_bits},
        {"backend", o.backend},
        {"triangles", scene.triangle_count()},
        {"fragments", fragments},
        // Peak so far: every method has run and its images are written.
        {"memory",
         {{"frame_bytes", frame_bytes(vp.width, vp.height)},
          {"scene_bytes", scene_bytes(scene)},
          {"fragments", fragments},
          {"fragment_bytes", fragment_bytes},
          {"peak_rss_bytes", peak_rss_bytes()}}}};
    write_or_fail(write_file_atomic(o.stats, stats_json(runs, o.frame.depth_bits, header.dump())));
  }
  if (!o.quiet) print_table(runs);
  if (mismatches) throw VerificationError("RTL and golden model differ (report above)");
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Render a scene with one or more methods on the golden model, the RTL or both");
  add_frame_options(cmd, o->frame);
  cmd->add_option("--method,-m", o->methods,
                  "Method, a comma-separated list, or 'all' (see 'zblend methods')")
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "Output PNG (one method)");
  cmd->add_option("--out-dir", o->out_dir,
                  "Output directory: METHOD.png for each method and summary.csv");
  cmd->add_option("--stats", o->stats, "Statistics as JSON: passes, traffic, error, cycles");
  cmd->add_option("--backend,-b", o->backend,
                  "golden (C++ model), rtl (Verilated RTL) or both (compared bit for bit after "
                  "every pass)")
      ->capture_default_str();
  cmd->add_option("--backpressure", o->backpressure,
                  "RTL: probability per cycle of a stall on the fragment input")
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "RTL: seed of the back-pressure pattern")
      ->capture_default_str();
  cmd->add_option("--waves", o->waves, "RTL: FST waveform of the whole run");
  add_threads_option(cmd, o->threads, "Golden model: threads rendering the frame's bands");
  cmd->add_flag("--no-error", o->no_error,
                "Skip the exact reference and the error columns (its fragments are stored for "
                "the whole frame): the golden model's own time and memory");
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors");
  cmd->callback([o] { run_render(*o); });
}

}  // namespace zb::app
