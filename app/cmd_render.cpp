// zblend render: a scene through one or more methods, to PNG images, a table and JSON stats.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "geometry.h"
#include "image.h"
#include "metrics.h"
#include "passes.h"
#include "reference.h"
#include "render.h"
#include "rop.h"

namespace zb::app {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string scene = "cad";
  std::string methods = "three-pass";
  int width = 640;
  int height = 480;
  int depth_bits = kDefaultDepthBits;
  std::string out;
  std::string out_dir;
  std::string stats;
  bool quiet = false;
};

// One method's outcome: its image, its cost and its error against the reference.
struct MethodRun {
  std::string method;
  Framebuffer image;
  std::optional<PassStats> total;  // none for the reference
  size_t passes = 0;
  ImageError error;
  double host_ms = 0;
};

uint64_t bytes_read(const PassStats& s, int depth_bits) {
  return s.color_reads * 4 + s.depth_reads * static_cast<uint64_t>((depth_bits + 7) / 8);
}
uint64_t bytes_written(const PassStats& s, int depth_bits) {
  return s.color_writes * 4 + s.depth_writes * static_cast<uint64_t>((depth_bits + 7) / 8);
}

nlohmann::json stats_json(const PassStats& s) {
  return {{"fragments_in", s.fragments_in},   {"fragments_passed", s.fragments_passed},
          {"fragments_killed", s.fragments_killed()}, {"color_reads", s.color_reads},
          {"color_writes", s.color_writes},   {"depth_reads", s.depth_reads},
          {"depth_writes", s.depth_writes}};
}

nlohmann::json error_json(const ImageError& e) {
  return {{"rmse", e.rmse}, {"psnr_db", std::isinf(e.psnr) ? nlohmann::json(nullptr) : nlohmann::json(e.psnr)},
          {"max_abs", e.max_abs}, {"share_over_2", e.share_over_2},
          {"share_over_16", e.share_over_16}};
}

std::string summary_csv(const std::vector<MethodRun>& runs, int depth_bits) {
  std::string csv =
      "method,passes,fragments,reads,writes,bytes_read,bytes_written,rmse,psnr_db,max_abs,"
      "share_over_2,share_over_16,host_ms\n";
  for (const MethodRun& r : runs) {
    const std::string psnr = std::isinf(r.error.psnr) ? "inf" : fmt::format("{:.2f}", r.error.psnr);
    std::string cost = ",,,,,";
    if (r.total) {
      const PassStats& s = *r.total;
      cost = fmt::format("{},{},{},{},{}", s.fragments_in, s.color_reads + s.depth_reads,
                         s.color_writes + s.depth_writes, bytes_read(s, depth_bits),
                         bytes_written(s, depth_bits));
    }
    csv += fmt::format("{},{},{},{:.4f},{},{},{:.6f},{:.6f},{:.1f}\n", r.method,
                       r.total ? std::to_string(r.passes) : "", cost, r.error.rmse, psnr,
                       r.error.max_abs, r.error.share_over_2, r.error.share_over_16, r.host_ms);
  }
  return csv;
}

void print_table(const std::vector<MethodRun>& runs) {
  fmt::print("{:<12} {:>6} {:>10} {:>10} {:>10} {:>8} {:>8} {:>5} {:>8}\n", "method", "passes",
             "fragments", "reads", "writes", "rmse", "psnr_dB", "max", ">2/255");
  for (const MethodRun& r : runs) {
    const std::string psnr = std::isinf(r.error.psnr) ? "inf" : fmt::format("{:.2f}", r.error.psnr);
    if (r.total)
      fmt::print("{:<12} {:>6} {:>10} {:>10} {:>10} {:>8.3f} {:>8} {:>5} {:>7.2f}%\n", r.method,
                 r.passes, r.total->fragments_in, r.total->color_reads + r.total->depth_reads,
                 r.total->color_writes + r.total->depth_writes, r.error.rmse, psnr,
                 r.error.max_abs, 100.0 * r.error.share_over_2);
    else
      fmt::print("{:<12} {:>6} {:>10} {:>10} {:>10} {:>8.3f} {:>8} {:>5} {:>7.2f}%\n", r.method,
                 "-", "-", "-", "-", r.error.rmse, psnr, r.error.max_abs,
                 100.0 * r.error.share_over_2);
  }
}

void run_render(const RenderOptions& o) {
  const Scene scene = resolve_scene(o.scene);
  const std::vector<std::string> methods = parse_methods(o.methods);
  const Viewport vp = check_viewport(o.width, o.height, o.depth_bits);
  if (o.out.empty() == o.out_dir.empty())
    throw UsageError("give exactly one of --out FILE.png (one method) or --out-dir DIR");
  if (!o.out.empty() && methods.size() != 1)
    throw UsageError("--out: takes one method; use --out-dir DIR for several");
  if (!o.out.empty()) check_writable("--out", o.out, ".png");
  if (!o.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    check_writable("--out-dir", (fs::path(o.out_dir) / "summary.csv").string(), ".csv");
  }
  if (!o.stats.empty()) check_writable("--stats", o.stats, ".json");

  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const RasterizedScene rs = rasterize_scene(scene, vp);
  const auto t1 = Clock::now();
  const Framebuffer reference = render_reference(rs);
  const double raster_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  const double reference_ms = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
  if (!o.quiet)
    fmt::print(stderr, "{}: {} triangles, {} fragments at {}x{} ({:.1f} ms geometry and raster)\n",
               o.scene, rs.triangles.size(), rs.fragments.size(), o.width, o.height, raster_ms);

  std::vector<MethodRun> runs;
  for (const std::string& m : methods) {
    MethodRun run;
    run.method = m;
    const auto start = Clock::now();
    if (const PassPlan* plan = find_plan(m)) {
      GoldenRop rop;
      RenderResult result = render(rs, *plan, rop);
      run.image = std::move(result.framebuffer);
      run.passes = result.passes.size();
      run.total = PassStats{};
      for (const PassStats& p : result.passes) *run.total += p;
    } else {
      run.image = reference;
    }
    run.host_ms = run.total ? std::chrono::duration<double, std::milli>(Clock::now() - start).count()
                            : reference_ms;
    run.error = compare_images(run.image, reference);
    if (!o.quiet) fmt::print(stderr, "  {:<12} {:8.1f} ms\n", m, run.host_ms);
    runs.push_back(std::move(run));
  }

  for (const MethodRun& r : runs)
    write_or_fail(write_png(o.out.empty() ? (fs::path(o.out_dir) / (r.method + ".png")).string()
                                          : o.out,
                            r.image));
  if (!o.out_dir.empty())
    write_or_fail(write_file_atomic((fs::path(o.out_dir) / "summary.csv").string(),
                                    summary_csv(runs, o.depth_bits)));
  if (!o.stats.empty()) {
    nlohmann::json j = {{"scene", o.scene}, {"width", o.width}, {"height", o.height},
                        {"depth_bits", o.depth_bits}, {"triangles", rs.triangles.size()},
                        {"fragments", rs.fragments.size()}, {"methods", nlohmann::json::array()}};
    for (const MethodRun& r : runs) {
      nlohmann::json m = {{"method", r.method}, {"error", error_json(r.error)},
                          {"host_ms", r.host_ms}};
      if (r.total) {
        m["passes"] = r.passes;
        m["total"] = stats_json(*r.total);
        m["bytes_read"] = bytes_read(*r.total, o.depth_bits);
        m["bytes_written"] = bytes_written(*r.total, o.depth_bits);
      }
      j["methods"].push_back(m);
    }
    write_or_fail(write_file_atomic(o.stats, j.dump(2) + "\n"));
  }
  if (!o.quiet) print_table(runs);
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Render a scene with one or more methods through the golden model");
  cmd->add_option("--scene,-s", o->scene, "Built-in scene (see 'zblend scenes')")
      ->capture_default_str();
  cmd->add_option("--method,-m", o->methods,
                  "Method, a comma-separated list, or 'all' (see 'zblend methods')")
      ->capture_default_str();
  cmd->add_option("--width,-W", o->width, "Frame width in pixels")->capture_default_str();
  cmd->add_option("--height,-H", o->height, "Frame height in pixels")->capture_default_str();
  cmd->add_option("--depth-bits", o->depth_bits, "Depth buffer width in bits")
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "Output PNG (one method)");
  cmd->add_option("--out-dir", o->out_dir,
                  "Output directory: METHOD.png for each method and summary.csv");
  cmd->add_option("--stats", o->stats, "Statistics as JSON: passes, traffic, error");
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors");
  cmd->callback([o] { run_render(*o); });
}

}  // namespace zb::app
