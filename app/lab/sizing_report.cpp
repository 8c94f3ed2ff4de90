#include "sizing_report.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace zb {
namespace {

using nlohmann::json;

std::string samples_text(const SizingTrial& t) {
  return uses_coverage(t.method) ? fmt::format("{}", t.coverage_samples) : "-";
}

const TilesTouched* scene_tiles(const SceneAnalysis& a, int tile) {
  for (const TilesTouched& t : a.tiles)
    if (t.size == tile) return &t;
  return nullptr;
}

std::string analysis_text(const SceneAnalysis& a) {
  std::string s = "analysis\n";
  s += fmt::format("  depth complexity    max {}, mean {:.2f} fragments per covered pixel "
                   "({} of {} pixels covered)\n", a.max_depth_complexity,
                   a.mean_depth_complexity, a.covered_pixels, uint64_t(a.width) * a.height);
  // The histogram's first bins, the rest summed.
  constexpr size_t kBins = 8;
  std::string h;
  uint64_t rest = 0;
  for (size_t n = 1; n < a.depth_histogram.size(); ++n) {
    if (n > kBins) rest += a.depth_histogram[n];
    else if (a.depth_histogram[n]) h += fmt::format("  {}: {}", n, a.depth_histogram[n]);
  }
  if (rest) h += fmt::format("  >{}: {}", kBins, rest);
  s += fmt::format("  pixels by fragments{}\n", h);
  s += fmt::format("  transparent layers  max {}", a.max_layers);
  for (int k = 0; k < a.max_layers && k < 8; ++k)
    s += fmt::format("{} >{}: {:.2f}%", k == 0 ? ";" : ",", k, 100.0 * a.share_over(k));
  s += " of covered pixels\n";
  if (a.separated_pixels == 0) {
    s += "  depth separation    no pixel holds two unconnected surfaces\n";
  } else {
    auto bits = [](int b) {
      return b == kUnresolvable ? std::string("no width up to 32 bits resolves it")
                                : fmt::format("{} bits resolve it", b);
    };
    s += fmt::format("  depth separation    smallest {:.3e} at ({}, {}): {}\n", a.min_separation,
                     a.min_separation_x, a.min_separation_y, bits(a.depth_bits_needed));
    s += fmt::format("                      1% of {} pixels below {:.3e}: {}\n",
                     a.separated_pixels, a.p1_separation, bits(a.depth_bits_needed_p1));
  }
  s += "  tiles touched      ";
  for (const TilesTouched& t : a.tiles)
    s += fmt::format(" {}x{}: {} of {};", t.size, t.size, t.touched, t.total);
  s.back() = '\n';
  s += fmt::format("  anti-aliasing       {} pixels where a partly covered triangle meets another "
                   "colour at 16 samples\n", a.aa_edge_pixels);
  return s;
}

std::string trials_text(const SizingOptions& o, const SizingResult& r) {
  std::string s = fmt::format(
      "trials (E = {} bounds the channel error beyond the rounding floor: depth-peel-{}'s error, "
      "at most 1 unit per layer; up to {} here)\n", o.max_error, r.floor_layers, r.floor_max);
  s += fmt::format("  {:<7} {:<16} {:>5} {:>7} {:>6} {:>4} {:>7} {:>6} {:>10} {:>6} {:>11} "
                   "{:>12}  {}\n", "step", "method", "depth", "samples", "error", "max", "rmse",
                   "passes", "fragments", "tile", "cycles", "bytes", "within E");
  for (const SizingTrial& t : r.trials)
    s += fmt::format("  {:<7} {:<16} {:>5} {:>7} {:>6} {:>4} {:>7.3f} {:>6} {:>10} {:>6} {:>11} "
                     "{:>12}  {}\n", t.step, t.method, t.depth_bits, samples_text(t),
                     t.beyond_rounding, t.error.max_abs, t.error.rmse, t.cost.passes,
                     t.cost.totals.fragments_in, fmt::format("{}x{}", t.tile, t.tile), t.cycles(),
                     t.traffic_bytes(), t.meets ? "yes" : "no");
  return s;
}

std::string choice_text(const std::string& scene, const SizingOptions& o, const SizingResult& r) {
  const SizingTrial& c = r.choice;
  if (!r.found)
    return fmt::format("no candidate meets E = {}: the best achievable is error {} beyond "
                       "rounding (max {}, rmse {:.3f}), {} at {}-bit depth{}\n", o.max_error,
                       c.beyond_rounding, c.error.max_abs, c.error.rmse, c.method, c.depth_bits,
                       uses_coverage(c.method) ? fmt::format(", {} samples", c.coverage_samples)
                                               : "");
  const TileCost& tc = c.cost.at(c.tile);
  std::string s = fmt::format(
      "choice: {} with {}-bit depth, {}, {}x{} tiles\n", c.method, c.depth_bits,
      uses_coverage(c.method) ? fmt::format("{} coverage samples", c.coverage_samples)
                              : std::string("coverage samples not used"),
      c.tile, c.tile);
  s += fmt::format("verified: rendered again, error {} beyond rounding <= {} (max {}, rmse {:.3f}, "
                   "psnr {:.2f} dB)\n", c.beyond_rounding, o.max_error, c.error.max_abs,
                   c.error.rmse, c.error.psnr);
  s += fmt::format("cost: {} passes, {} fragments, {} cycles = {} streaming + {} tile I/O + {} "
                   "frame-op pixels; {} bytes\n", c.cost.passes, c.cost.totals.fragments_in,
                   c.cycles(), tc.stream_cycles, tc.tile_io_cycles, c.cost.frame_op_pixels,
                   c.traffic_bytes());
  const TilesTouched* st = scene_tiles(r.analysis, c.tile);
  s += fmt::format("rtl: -DZBLEND_RTL_DEPTH_BITS={} -DZBLEND_RTL_COV_SAMPLES={} "
                   "-DZBLEND_RTL_TILE={}; the scene touches {} of the frame's {} tiles, the "
                   "passes load {}; {} RTL cycles expected (make plan-rtl SCENE={} MAX_ERROR={})\n",
                   c.depth_bits, c.coverage_samples, c.tile, st ? st->touched : 0,
                   st ? st->total : 0, tc.tiles_loaded, tc.rtl_cycles(), scene, o.max_error);
  return s;
}

json trial_json(const SizingTrial& t) {
  json tiles = json::array();
  for (const TileCost& c : t.cost.tiles)
    tiles.push_back({{"tile", c.tile},
                     {"tiles_loaded", c.tiles_loaded},
                     {"stream_cycles", c.stream_cycles},
                     {"tile_io_cycles", c.tile_io_cycles},
                     {"cycles", t.cost.cycles(c.tile)},
                     {"bytes", t.cost.traffic_bytes(c.tile, t.depth_bits, t.coverage_samples)}});
  const PassStats& s = t.cost.totals;
  return {{"step", t.step},
          {"method", t.method},
          {"depth_bits", t.depth_bits},
          {"coverage_samples", t.coverage_samples},
          {"uses_coverage", uses_coverage(t.method)},
          {"error_beyond_rounding", t.beyond_rounding},
          {"max_error", t.error.max_abs},
          {"rmse", t.error.rmse},
          {"within_bound", t.meets},
          {"passes", t.cost.passes},
          {"fragments", s.fragments_in},
          {"color_reads", s.color_reads},
          {"color_writes", s.color_writes},
          {"depth_reads", s.depth_reads},
          {"depth_writes", s.depth_writes},
          {"frame_op_pixels", t.cost.frame_op_pixels},
          {"tile", t.tile},
          {"cycles", t.cycles()},
          {"bytes", t.traffic_bytes()},
          {"by_tile", tiles}};
}

json analysis_json(const SceneAnalysis& a) {
  json tiles = json::array();
  for (const TilesTouched& t : a.tiles)
    tiles.push_back({{"tile", t.size}, {"touched", t.touched}, {"total", t.total}});
  return {{"width", a.width},
          {"height", a.height},
          {"fragments", a.fragments},
          {"covered_pixels", a.covered_pixels},
          {"max_depth_complexity", a.max_depth_complexity},
          {"mean_depth_complexity", a.mean_depth_complexity},
          {"depth_histogram", a.depth_histogram},
          {"max_transparent_layers", a.max_layers},
          {"layer_histogram", a.layer_histogram},
          {"separated_pixels", a.separated_pixels},
          {"min_separation", a.min_separation},
          {"min_separation_pixel", {a.min_separation_x, a.min_separation_y}},
          {"p1_separation", a.p1_separation},
          {"depth_bits_needed", a.depth_bits_needed},
          {"depth_bits_needed_p1", a.depth_bits_needed_p1},
          {"tiles", tiles},
          {"aa_edge_pixels", a.aa_edge_pixels}};
}

}  // namespace

std::string sizing_text(const std::string& scene, const SizingOptions& o, const SizingResult& r) {
  return fmt::format("scene {} at {}x{}: {} fragments\n", scene, o.width, o.height,
                     r.analysis.fragments) +
         analysis_text(r.analysis) + trials_text(o, r) + choice_text(scene, o, r);
}

std::string sizing_json(const std::string& scene, const SizingOptions& o, const SizingResult& r) {
  json trials = json::array();
  for (const SizingTrial& t : r.trials) trials.push_back(trial_json(t));
  json j = {{"scene", scene},
            {"width", o.width},
            {"height", o.height},
            {"max_error", o.max_error},
            {"bound", "largest channel error beyond the rounding floor, 8-bit units"},
            {"floor_layers", r.floor_layers},
            {"floor_max", r.floor_max},
            {"analysis", analysis_json(r.analysis)},
            {"trials", trials},
            {"found", r.found},
            {"choice", trial_json(r.choice)}};
  if (r.found) {
    const TilesTouched* st = scene_tiles(r.analysis, r.choice.tile);
    j["rtl"] = {{"ZBLEND_RTL_DEPTH_BITS", r.choice.depth_bits},
                {"ZBLEND_RTL_COV_SAMPLES", r.choice.coverage_samples},
                {"ZBLEND_RTL_TILE", r.choice.tile},
                {"render_method", r.choice.method},
                {"scene_tiles_touched", st ? st->touched : 0},
                {"frame_tiles", st ? st->total : 0},
                {"pass_tiles_loaded", r.choice.cost.at(r.choice.tile).tiles_loaded},
                {"rtl_cycles_expected", r.choice.cost.at(r.choice.tile).rtl_cycles()}};
  }
  return j.dump(2) + "\n";
}

}  // namespace zb
