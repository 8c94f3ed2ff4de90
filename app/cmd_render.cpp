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

#include "cli.h"
#include "output_paths.h"
#include "scene_options.h"
#include "commands.h"
#include "cosim.h"
#include "error_maps.h"
#include "pipeline/frame_render.h"
#include "io/image.h"
#include "lab.h"
#include "metrics/memory_use.h"
#include "pipeline/passes.h"
#include "reference/line_reference.h"
#include "reference/reference.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "rtl_rop.h"
#include "summary.h"

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

enum class BackendKind { kGolden, kRtl, kBoth };

const char* backend_name(BackendKind b) {
  switch (b) {
    case BackendKind::kGolden: return "golden";
    case BackendKind::kRtl: return "rtl";
    case BackendKind::kBoth: return "both";
  }
  return "?";
}

BackendKind parse_backend(const std::string& name) {
  for (BackendKind b : {BackendKind::kGolden, BackendKind::kRtl, BackendKind::kBoth})
    if (name == backend_name(b)) return b;
  throw UsageError(fmt::format("--backend: unknown backend '{}' (choose from golden, rtl, both)",
                               name));
}

struct RenderOptions {
  FrameOptions frame;
  std::string methods = "three-pass";
  std::string out;
  std::string out_dir;
  std::string stats;
  std::string backend_text = "golden";  // --backend as given, parsed into `backend`
  BackendKind backend = BackendKind::kGolden;
  // The RTL backends' options, which --backpressure, --waves (rtl.trace_path) and
  // --no-lockstep set directly; make_rtl_backend adds the checked --seed, --threads and each
  // method's mismatch waveform.
  CosimOptions cosim;
  int64_t seed = 1;                 // checked (0 or more) before it becomes cosim.rtl.seed
  std::string schedule = "tile";    // --schedule, parsed into cosim.rtl.schedule
  std::string background;
  int threads = default_threads();  // golden: render_frame's workers; RTL: models side by side
  bool threads_given = false;
  std::vector<std::string> given;   // the RTL-only options given
  bool no_error = false;            // skip the reference and the error columns
  bool error_map = false;           // --error-map: maps beside --out (under --out-dir: default)
  bool no_error_map = false;
  std::string error_scale_text = "auto";
  ErrorScale error_scale;           // parsed from error_scale_text
  bool quiet = false;
  // Whether the run writes error maps.
  bool error_maps() const { return !no_error && (error_map || (!out_dir.empty() && !no_error_map)); }
};

// The options that only the RTL backends use.
constexpr const char* kRtlOnly[] = {"--backpressure", "--seed", "--waves", "--schedule"};

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

std::vector<OutputPath> outputs(const RenderOptions& o) {
  return {{"--out", o.out, ".png"},
          {"--out-dir", o.out_dir, nullptr},
          {"--stats", o.stats, ".json"},
          {"--waves", o.cosim.rtl.trace_path, ".fst"},
          {"--error-map", o.error_map && !o.out.empty() ? error_map_path(o.out, "", "") : "", ".png"}};
}

// An option given for a backend the run does not use would do nothing: refused.
void check_backend_options(const RenderOptions& o) {
  if (!o.cosim.lockstep && o.backend != BackendKind::kBoth)
    throw UsageError("--no-lockstep: needs --backend both (it turns off the per-write comparison)");
  if (o.backend != BackendKind::kGolden) return;
  for (const std::string& name : o.given)
    throw UsageError(fmt::format("{}: needs --backend rtl or both", name));
}

// Everything that can be checked before the scene is read; changes nothing on disk.
void check_options(const RenderOptions& o, size_t method_count) {
  if (o.out.empty() == o.out_dir.empty())
    throw UsageError("give exactly one of --out FILE.png (one method) or --out-dir DIR");
  if (!o.out.empty() && method_count != 1)
    throw UsageError("--out: takes one method; use --out-dir DIR for several");
  if (o.backend != BackendKind::kGolden && o.frame.depth_bits != kRtlDepthBits)
    throw UsageError(fmt::format("--depth-bits: the RTL model is built with {} bits, not {}",
                                 kRtlDepthBits, o.frame.depth_bits));
  check_backend_options(o);
  check_threads(o.threads);
  const bool waves = !o.cosim.rtl.trace_path.empty();
  if (waves && o.threads_given && o.threads > 1)
    throw UsageError(fmt::format("--waves: one waveform needs one RTL model; --threads {} asks "
                                 "for {} (drop --threads or give --threads 1)", o.threads, o.threads));
  const double backpressure = o.cosim.rtl.backpressure;
  if (!(backpressure >= 0 && backpressure < 1))
    throw UsageError(
        fmt::format("--backpressure: {} is out of range (0 to below 1)", backpressure));
  if (o.seed < 0) throw UsageError(fmt::format("--seed: {} is out of range (0 or more)", o.seed));
  if (waves && method_count != 1) throw UsageError("--waves: takes one method");
  if (o.error_map && o.no_error_map) throw UsageError("--error-map, --no-error-map: give one of them");
  if (o.error_map && o.no_error)
    throw UsageError("--error-map, --no-error: a map is the error against the reference; drop one of them");
  if (o.no_error_map && o.out_dir.empty())
    throw UsageError("--no-error-map: needs --out-dir (only there are maps written unasked)");
  if (o.error_scale_text != "auto" && !o.error_maps())
    throw UsageError("--error-scale: no error maps are written (give --error-map, or --out-dir "
                     "without --no-error-map)");
  check_outputs(outputs(o));
}

// An RTL backend and typed views of it: the RTL model alone, or within a Cosim (both).
struct RtlBackend {
  std::unique_ptr<Backend> backend;
  const RtlRop* rtl = nullptr;
  const Cosim* cosim = nullptr;
};

RtlBackend make_rtl_backend(const RenderOptions& o, const PassPlan& plan) {
  CosimOptions cosim = o.cosim;
  cosim.rtl.seed = static_cast<uint64_t>(o.seed);
  cosim.rtl.threads = o.threads;  // the golden model's bands take the same --threads
  RtlBackend b;
  if (o.backend == BackendKind::kRtl) {
    auto r = std::make_unique<RtlRop>(cosim.rtl);
    b.rtl = r.get();
    b.backend = std::move(r);
    return b;
  }
  const fs::path dir = o.out_dir.empty() ? fs::path(o.out).parent_path() : fs::path(o.out_dir);
  cosim.mismatch_fst = (dir / ("mismatch-" + plan.name + ".fst")).string();
  auto c = std::make_unique<Cosim>(cosim);
  b.cosim = c.get();
  b.rtl = &c->rtl();
  b.backend = std::move(c);
  return b;
}

// One pass plan on the RTL, alone or compared with the golden model: the plan executor
// (render(), executor.h) on an RTL backend, with the run's counters, traffic and image. A
// mismatch between them is recorded in the run and its report printed; the caller fails the
// command at the end.
void run_rtl(const RenderOptions& o, const RasterizedScene& rs, const PassPlan& plan,
             MethodRun& run) {
  const RtlBackend b = make_rtl_backend(o, plan);
  run.rtl = true;
  run.compared = b.cosim != nullptr;
  run.passes = plan.passes.size();
  run.total = PassStats{};
  try {
    const std::vector<PassStats> passes = render(rs, plan, *b.backend).passes;
    for (const PassStats& p : passes) *run.total += p;
    run.traffic = plan_traffic(passes, plan, rs.viewport);
  } catch (const MismatchError& e) {
    fmt::print(stderr, "{}\n", e.what());
    run.mismatches = std::max<uint64_t>(1, b.cosim ? b.cosim->mismatches() : 0);
  }
  run.image = b.backend->framebuffer();
  run.tile_io_cycles = b.rtl->tile_io_cycles();
}

// One pass plan on the golden model, the whole frame from the scene by the banded renderer
// (frame_render.h): geometry, raster and datapath, which host_ms times.
// Returns the set-up triangles it drew from.
size_t run_golden(const RenderOptions& o, const Scene& scene, const Viewport& vp,
                  const PassPlan& plan, MethodRun& run) {
  FrameRenderOptions options;
  options.threads = o.threads;
  RenderResult result = render_frame(scene, vp, plan, options);
  run.passes = plan.passes.size();
  run.total = PassStats{};
  for (const PassStats& p : result.passes) *run.total += p;
  run.traffic = plan_traffic(result.passes, plan, vp);
  run.image = std::move(result.framebuffer);
  return result.triangles;
}

// The scene after the options: its file read, its camera aimed, --background applied.
Scene load_scene(const RenderOptions& o) {
  Scene scene = resolve_scene_with_background(o.frame, o.background);
#ifdef __GLIBC__
  // The scene loaders free large temporaries that glibc keeps resident; returned before the
  // frame's buffers are allocated, they stay out of the run's peak memory.
  malloc_trim(0);
#endif
  return scene;
}

// The first line: the scene's triangles and those set up after clipping (more where clipping
// splits one, fewer where it drops one), which the camera and frame size change; and the RTL's
// build where it runs.
void print_header(const RenderOptions& o, const Scene& scene, size_t drawn,
                  const std::optional<RasterizedScene>& rs, double raster_ms) {
  const std::string head = fmt::format("{}: {} triangles in the scene, {} after clipping",
                                       o.frame.scene, scene.triangle_count(), drawn);
  const std::string backend =
      o.backend == BackendKind::kGolden
          ? std::string(backend_name(o.backend))
          : fmt::format("{} (RTL: {})", backend_name(o.backend), RtlRop::build());
  if (rs)
    fmt::print(stderr, "{}, {} fragments at {}x{} ({:.1f} ms geometry and raster), backend {}\n",
               head, rs->fragments.size(), o.frame.width, o.frame.height, raster_ms, backend);
  else
    fmt::print(stderr, "{}, at {}x{}, backend {}\n", head, o.frame.width, o.frame.height,
               backend);
}

// The fragments that reached the frame: all of them where they were stored, else the most any
// method drew.
uint64_t frame_fragments(const std::optional<RasterizedScene>& rs,
                         const std::vector<MethodRun>& runs) {
  if (rs) return rs->fragments.size();
  uint64_t most = 0;
  for (const MethodRun& r : runs)
    if (r.total) most = std::max(most, r.total->fragments_in);
  return most;
}

void write_stats(const RenderOptions& o, const Scene& scene, const Viewport& vp,
                 const std::optional<RasterizedScene>& rs, size_t drawn,
                 const std::vector<MethodRun>& runs) {
  // The stored fragments exist only where the reference (or the RTL) needed them.
  const nlohmann::json fragments = rs ? nlohmann::json(rs->fragments.size()) : nlohmann::json();
  const nlohmann::json fragment_bytes =
      rs ? nlohmann::json(rs->fragments.size() * kReferenceFragmentBytes) : nlohmann::json();
  const nlohmann::json header = {
      {"scene", o.frame.scene},
      {"width", o.frame.width},
      {"height", o.frame.height},
      {"depth_bits", o.frame.depth_bits},
      {"backend", backend_name(o.backend)},
      {"triangles", scene.triangle_count()},
      {"triangles_drawn", drawn},
      {"fragments", fragments},
      // Peak so far: every method has run and its images are written.
      {"memory",
       {{"frame_bytes", frame_bytes(vp.width, vp.height)},
        {"scene_bytes", scene_bytes(scene)},
        {"fragments", fragments},
        {"fragment_bytes", fragment_bytes},
        {"peak_rss_bytes", peak_rss_bytes()}}}};
  write_or_fail(write_file_atomic(o.stats, stats_json(runs, header.dump())));
}

void run_render(const RenderOptions& o) {
  const std::vector<std::string> methods = parse_methods(o.methods);
  const Viewport vp = check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const bool reference_method =
      std::find(methods.begin(), methods.end(), kReferenceMethod) != methods.end();
  if (o.no_error && reference_method)
    throw UsageError("--no-error: the reference method is what errors are measured against; "
                     "drop one of them");
  check_options(o, methods.size());
  const Scene scene = load_scene(o);
  create_output_dirs(outputs(o));

  // The exact reference feeds the error columns (the table, summary.csv, --stats) and the
  // reference method; it needs the whole scene's fragments stored. The golden model renders
  // without them, so a golden run that writes only images skips both.
  const bool golden = o.backend == BackendKind::kGolden;
  const bool need_reference = !o.no_error && (!o.quiet || !o.out_dir.empty() || !o.stats.empty() ||
                                              reference_method || o.error_maps());
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
  // Set-up triangles: the stored ones, or (golden model alone) those of its first run, which
  // the header then follows.
  size_t drawn = rs ? rs->triangles.size() : 0;
  bool header = o.quiet;
  auto print_header_once = [&] {
    if (header) return;
    header = true;
    print_header(o, scene, drawn, rs, raster_ms);
    print_warnings("zblend render", scene);
  };
  if (rs) print_header_once();

  std::vector<MethodRun> runs;
  std::optional<LineVisibility> lines;  // the line reference, when a method draws edges
  uint64_t mismatches = 0;
  for (const std::string& m : methods) {
    MethodRun run;
    run.method = m;
    const auto start = Clock::now();
    if (const PassPlan* plan = find_plan(m)) {
      if (golden)
        drawn = run_golden(o, scene, vp, *plan, run);
      else
        run_rtl(o, *rs, *plan, run);
      run.host_ms = ms_since(start);
    } else {
      run.image = reference;
      run.host_ms = reference_ms;
    }
    // The error maps take a shaded method's CIEDE2000 from here when its fair reference is this.
    const bool keep_de = o.error_maps() && lab::fair_reference(m) == lab::FairReference::kExact;
    if (need_reference) run.error = compare_images(run.image, reference, keep_de ? &run.delta_e : nullptr);
    // Edges are judged against the exact line reference, not the shaded one (docs/lab.md).
    if (const PassPlan* plan = find_plan(m); need_reference && plan && plan_draws_edges(*plan)) {
      if (!lines) {
        FrameGeometry g = *rs;
        if (g.lines.empty()) g.lines = setup_lines(scene, vp, g.triangles);
        lines = line_visibility(g.triangles, g.lines, vp);
      }
      run.line_error = compare_lines(run.image, *lines, kEdgeColor);
    }
    mismatches += run.mismatches;
    print_header_once();
    if (!o.quiet) fmt::print(stderr, "  {:<12} {:8.1f} ms\n", m, run.host_ms);
    runs.push_back(std::move(run));
  }
  if (!o.quiet && frame_fragments(rs, runs) == 0)
    fmt::print(stderr, "zblend render: warning: nothing drawn: 0 fragments reach the frame; "
                       "try --camera\n");

  for (const MethodRun& r : runs)
    write_or_fail(write_png(
        o.out.empty() ? (fs::path(o.out_dir) / (r.method + ".png")).string() : o.out, r.image));
  if (!o.out_dir.empty())
    write_or_fail(write_file_atomic((fs::path(o.out_dir) / "summary.csv").string(),
                                    summary_csv(runs)));
  if (o.error_maps()) {
    const std::string scale = write_error_maps(runs, reference, lines, scene, vp, o.out, o.out_dir,
                                               o.error_scale, o.threads);
    if (!o.quiet)
      fmt::print(stderr, "  error maps: {}, {}\n", error_map_path(o.out, o.out_dir, "METHOD"), scale);
  }
  if (!o.stats.empty()) write_stats(o, scene, vp, rs, drawn, runs);
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
  cmd->add_option("--backend,-b", o->backend_text,
                  "golden (C++ model), rtl (Verilated RTL) or both (compared bit for bit: every "
                  "write at its cycle, every plane after every pass)")
      ->capture_default_str();
  cmd->add_option("--backpressure", o->cosim.rtl.backpressure,
                  "RTL: probability per cycle of a stall on the fragment input")
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "RTL: seed of the back-pressure pattern")
      ->capture_default_str();
  cmd->add_option("--waves", o->cosim.rtl.trace_path, "RTL: FST waveform of the whole run");
  cmd->add_option("--schedule", o->schedule,
                  "RTL: tile (each tile loaded once, the passes up to a host frame operation run "
                  "on it, stored once) or pass (every pass loads and stores each tile it touches)")
      ->capture_default_str();
  cmd->add_flag("!--no-lockstep", o->cosim.lockstep,
                "--backend both: compare the frames after each pass only, not every write at its "
                "cycle");
  add_background_option(cmd, o->background);
  add_threads_option(cmd, o->threads,
                     "Threads: the golden model's frame bands, the RTL's models running a "
                     "pass's tiles side by side (one with --waves)");
  cmd->add_flag("--no-error", o->no_error,
                "Skip the exact reference and the error columns (its fragments are stored for "
                "the whole frame): the golden model's own time and memory");
  cmd->add_flag("--error-map", o->error_map,
                "Write each method's error map (per-pixel dE2000 against its fair reference, one "
                "scale for the run; hidden-line methods: hidden edges drawn, visible ones missing) "
                "beside --out as FILE-error.png; under --out-dir they are written anyway, as "
                "METHOD-error.png");
  cmd->add_flag("--no-error-map", o->no_error_map, "--out-dir: no error maps");
  cmd->add_option("--error-scale", o->error_scale_text,
                  "The maps' scale: auto (one for the run, the largest 99th percentile rounded "
                  "up: maps that compare), per-method (each its own: a good method's errors "
                  "show), or a number of dE2000")
      ->capture_default_str();
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors (no warnings either)");
  cmd->callback([o, cmd] {
    o->backend = parse_backend(o->backend_text);
    if (!parse_schedule(o->schedule, o->cosim.rtl.schedule))
      throw UsageError(
          fmt::format("--schedule: unknown schedule '{}' (choose from tile, pass)", o->schedule));
    for (const char* name : kRtlOnly)
      if (cmd->count(name)) o->given.emplace_back(name);
    o->threads_given = cmd->count("--threads") != 0;
    o->error_scale = parse_error_scale(o->error_scale_text);
    run_render(*o);
  });
}

}  // namespace zb::app
