// zblend_oracle: renders a scene with pass plans on the golden model and through OpenGL on
// Mesa's llvmpipe, and compares the frames pixel by pixel (docs/oracle.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <stdexcept>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "cli.h"
#include "exact_depth.h"
#include "frame_diff.h"
#include "pipeline/frame_render.h"
#include "gl_render.h"
#include "io/image.h"
#include "output_paths.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene_options.h"

namespace {

namespace fs = std::filesystem;
using zb::cli::UsageError;

constexpr const char* kDefaultMethods = "opaque,unsorted,three-pass,back-front";

struct Options {
  zb::cli::FrameOptions frame;
  std::string methods = kDefaultMethods;
  std::string out_dir;
  double min_identical = 99.9;
  std::string window_y = "down";
  bool quiet = false;
  bool time = false;
  int repeat = 5;
};

struct Row {
  std::string method;
  zb::oracle::FrameDiff diff;
  zb::Rgba8 golden, gl;  // at the first differing pixel
  // Differing pixels by what the plan replayed with exact depths gives there (exact_depth.h).
  uint64_t exact_golden = 0, exact_gl = 0, exact_neither = 0;
  double golden_ms = 0, gl_ms = 0;  // --time: median frame times
};

// Median wall time of `repeat` calls of `frame`, after one call to warm caches and JITs.
double median_ms(int repeat, const std::function<void()>& frame) {
  using Clock = std::chrono::steady_clock;
  frame();
  std::vector<double> ms;
  for (int i = 0; i < repeat; ++i) {
    const auto t0 = Clock::now();
    frame();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

// The golden model's whole frame, from the scene, as `zblend render` draws it: vertex stage,
// setup, raster and passes, in bands on every core (frame_render.h).
zb::Framebuffer golden_frame(const zb::Scene& scene, const zb::Viewport& vp,
                             const zb::PassPlan& plan) {
  return zb::render_frame(scene, vp, plan).framebuffer;
}

// llvmpipe's whole frame, from the same scene: the vertex stage (on the host, as the oracle
// feeds GL clip coordinates), drawing every pass, and reading colour and depth back.
zb::Framebuffer gl_frame(zb::oracle::GlRenderer& gl, const zb::Scene& scene,
                         const zb::Viewport& vp, const zb::PassPlan& plan,
                         zb::oracle::WindowY window_y) {
  return gl.draw(zb::transform_triangles(scene, vp), plan, scene.background, window_y);
}

// Sorts the differing pixels by which frame the exact-depth replay agrees with.
void classify(const zb::RasterizedScene& rs, const zb::PassPlan& plan, const zb::Framebuffer& g,
              const zb::Framebuffer& l, Row& row) {
  std::vector<size_t> differing;
  for (size_t i = 0; i < g.color.size(); ++i)
    if (g.color[i] != l.color[i]) differing.push_back(i);
  const std::vector<zb::Rgba8> exact = zb::oracle::replay_exact_depth(rs, plan, differing);
  for (size_t k = 0; k < differing.size(); ++k) {
    if (exact[k] == g.color[differing[k]]) ++row.exact_golden;
    else if (exact[k] == l.color[differing[k]]) ++row.exact_gl;
    else ++row.exact_neither;
  }
}

// Every plan GL can draw when `list` is "all"; otherwise each named one, checked.
std::vector<const zb::PassPlan*> oracle_plans(const std::string& list) {
  std::vector<const zb::PassPlan*> plans;
  if (list == "all") {
    for (const zb::PassPlan& p : zb::pass_plans())
      if (zb::oracle::unsupported_reason(p).empty()) plans.push_back(&p);
    return plans;
  }
  for (const std::string& m : zb::cli::parse_methods(list)) {
    const zb::PassPlan* p = zb::find_plan(m);
    if (!p) throw UsageError(fmt::format("--method: '{}' has no pass plan to draw", m));
    if (const std::string why = zb::oracle::unsupported_reason(*p); !why.empty())
      throw UsageError(fmt::format("--method: '{}' cannot be drawn by OpenGL: {}", m, why));
    plans.push_back(p);
  }
  return plans;
}

std::string rgba(zb::Rgba8 c) { return fmt::format("{},{},{},{}", c.r, c.g, c.b, c.a); }

std::string csv(const Options& o, const std::vector<Row>& rows) {
  std::string s =
      "scene,method,width,height,pixels,identical,identical_pct,max_diff,depth_identical_pct,"
      "max_depth_diff,first_x,first_y,exact_sides_golden,exact_sides_llvmpipe,exact_sides_neither,"
      "golden_ms,llvmpipe_ms\n";
  for (const Row& r : rows)
    s += fmt::format("{},{},{},{},{},{},{:.4f},{},{:.4f},{},{},{},{},{},{},{},{}\n", o.frame.scene,
                     r.method, o.frame.width, o.frame.height, r.diff.pixels, r.diff.identical,
                     100 * r.diff.identical_share(), r.diff.max_diff,
                     100 * r.diff.depth_identical_share(), r.diff.max_depth_diff, r.diff.first_x,
                     r.diff.first_y, r.exact_golden, r.exact_gl, r.exact_neither,
                     o.time ? fmt::format("{:.3f}", r.golden_ms) : "",
                     o.time ? fmt::format("{:.3f}", r.gl_ms) : "");
  return s;
}

int run(const Options& o) {
  const zb::Scene scene = zb::cli::resolve_scene(o.frame.scene, o.frame.camera);
  const zb::Viewport vp = zb::cli::check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  if (vp.depth_bits != 24)
    throw UsageError(fmt::format("--depth-bits: the oracle's depth buffer is DEPTH_COMPONENT24, "
                                 "not {} bits", vp.depth_bits));
  if (!(o.min_identical >= 0 && o.min_identical <= 100))
    throw UsageError(fmt::format("--min-identical: {} is out of range (0 to 100)", o.min_identical));
  if (o.repeat < 1 || o.repeat > 1000)
    throw UsageError(fmt::format("--repeat: {} is out of range (1 to 1000)", o.repeat));
  if (o.window_y != "down" && o.window_y != "up")
    throw UsageError(fmt::format("--window-y: unknown direction '{}' (choose from down, up)",
                                 o.window_y));
  const auto window_y =
      o.window_y == "down" ? zb::oracle::WindowY::kDown : zb::oracle::WindowY::kUp;
  const std::vector<const zb::PassPlan*> plans = oracle_plans(o.methods);
  if (!o.out_dir.empty()) {
    const std::string table = (fs::path(o.out_dir) / "oracle.csv").string();
    zb::cli::create_output_dirs({{"--out-dir", o.out_dir, nullptr}, {"--out-dir", table, ".csv"}});
  }

  zb::oracle::GlContext gl(vp.width, vp.height);
  const zb::RasterizedScene rs = zb::rasterize_scene(scene, vp);
  const std::vector<zb::ClipTriangle> clip = zb::transform_triangles(scene, vp);
  if (!o.quiet)
    fmt::print("{}: {}x{}, {} triangles; OpenGL: {}, {}\n", o.frame.scene, vp.width, vp.height,
               clip.size(), gl.renderer(), gl.version());

  zb::oracle::GlRenderer renderer(gl);
  std::vector<Row> rows;
  std::vector<std::pair<std::string, zb::Framebuffer>> images;
  for (const zb::PassPlan* plan : plans) {
    zb::GoldenRop golden;
    const zb::Framebuffer g = zb::render(rs, *plan, golden).framebuffer;
    const zb::Framebuffer l = renderer.draw(clip, *plan, scene.background, window_y);
    Row row{plan->name, zb::oracle::diff_frames(g, l), {}, {}};
    if (o.time) {
      // Each timed frame is checked against the compared one: speed never at the cost of bits.
      const auto same = [&](const zb::Framebuffer& a, const zb::Framebuffer& b, const char* who) {
        if (a.color != b.color || a.depth != b.depth)
          throw std::runtime_error(fmt::format("{}: the timed {} frame differs from the "
                                               "compared one", plan->name, who));
      };
      row.golden_ms = median_ms(o.repeat, [&] { same(golden_frame(scene, vp, *plan), g, "golden"); });
      row.gl_ms = median_ms(o.repeat, [&] {
        same(gl_frame(renderer, scene, vp, *plan, window_y), l, "llvmpipe");
      });
    }
    classify(rs, *plan, g, l, row);
    if (row.diff.first_x >= 0) {
      row.golden = g.color_at(row.diff.first_x, row.diff.first_y);
      row.gl = l.color_at(row.diff.first_x, row.diff.first_y);
    }
    rows.push_back(row);
    if (!o.out_dir.empty()) {
      images.emplace_back(plan->name + "-golden.png", g);
      images.emplace_back(plan->name + "-llvmpipe.png", l);
      images.emplace_back(plan->name + "-diff.png", zb::oracle::diff_image(g, l));
    }
  }

  for (const auto& [name, fb] : images)
    zb::cli::write_or_fail(zb::write_png((fs::path(o.out_dir) / name).string(), fb));
  if (!o.out_dir.empty())
    zb::cli::write_or_fail(
        zb::write_file_atomic((fs::path(o.out_dir) / "oracle.csv").string(), csv(o, rows)));

  if (!o.quiet) {
    fmt::print("{:<12} {:>24} {:>9} {:>16} {:>15}  {}\n", "method", "bit-identical pixels",
               "max diff", "depth identical", "max depth diff",
               "exact depths side with golden/llvmpipe/neither");
    for (const Row& r : rows)
      fmt::print("{:<12} {:>14} {:>8.4f}% {:>9} {:>15.4f}% {:>15}  {}/{}/{}\n", r.method,
                 fmt::format("{}/{}", r.diff.identical, r.diff.pixels),
                 100 * r.diff.identical_share(), r.diff.max_diff,
                 100 * r.diff.depth_identical_share(), r.diff.max_depth_diff, r.exact_golden,
                 r.exact_gl, r.exact_neither);
    if (o.time) {
      fmt::print("\n{:<12} {:>12} {:>12} {:>18}   (median of {} frames each, after a warm-up)\n",
                 "method", "golden ms", "llvmpipe ms", "llvmpipe / golden", o.repeat);
      for (const Row& r : rows)
        fmt::print("{:<12} {:>12.2f} {:>12.2f} {:>18.2f}\n", r.method, r.golden_ms, r.gl_ms,
                   r.gl_ms / r.golden_ms);
    }
  }
  int failed = 0;
  for (const Row& r : rows) {
    if (100 * r.diff.identical_share() >= o.min_identical) continue;
    std::fprintf(stderr,
                 "zblend_oracle: FAILED: %s on %s: %.4f%% bit-identical pixels, below %.4g%%; "
                 "first difference at (%d, %d): golden %s, llvmpipe %s\n",
                 r.method.c_str(), o.frame.scene.c_str(), 100 * r.diff.identical_share(),
                 o.min_identical, r.diff.first_x, r.diff.first_y, rgba(r.golden).c_str(),
                 rgba(r.gl).c_str());
    ++failed;
  }
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"zblend_oracle: the golden model against OpenGL on Mesa's llvmpipe, pixel by "
               "pixel, for the pass plans OpenGL can draw"};
  app.name("zblend_oracle");
  Options o;
  zb::cli::add_frame_options(&app, o.frame);
  app.add_option("--method,-m", o.methods,
                 "Methods, comma-separated, or 'all' (every plan OpenGL can draw)")
      ->capture_default_str();
  app.add_option("--out-dir", o.out_dir,
                 "Write METHOD-golden.png, METHOD-llvmpipe.png, METHOD-diff.png and oracle.csv");
  app.add_option("--min-identical", o.min_identical,
                 "Fail (exit 1) when a method's share of bit-identical pixels, in percent, is "
                 "below this")
      ->capture_default_str();
  app.add_option("--window-y", o.window_y,
                 "down: GL's window y runs down the picture as zblend's (the picture drawn upside "
                 "down); up: GL's usual y up, where pixels on horizontal edges go to the other "
                 "triangle")
      ->capture_default_str();
  app.add_flag("--time", o.time,
               "Also time each method's whole frame (vertex stage to read-back) on both, checking "
               "every timed frame against the compared one");
  app.add_option("--repeat", o.repeat, "--time: frames timed per method and renderer (median)")
      ->capture_default_str();
  app.add_flag("--quiet,-q", o.quiet, "Print nothing but failures and errors");
  return zb::cli::run_main(app, argc, argv, [&o] {
    try {
      return run(o);
    } catch (const zb::oracle::GlUnavailable& e) {  // no llvmpipe here: exit 3, not a failure
      throw zb::cli::CannotRun(e.what());
    }
  });
}
