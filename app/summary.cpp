#include "summary.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

namespace zb::app {
namespace {

std::string psnr_text(double psnr) {
  return std::isinf(psnr) ? "inf" : fmt::format("{:.2f}", psnr);
}

}  // namespace

std::string summary_csv(const std::vector<MethodRun>& runs) {
  std::string csv =
      "method,passes,fragments,reads,writes,bytes_read,bytes_written,rmse,psnr_db,max_abs,"
      "share_over_2,share_over_16,delta_e_mean,delta_e_max,host_ms,rtl_cycles,"
      "rtl_stream_cycles,rtl_tile_cycles,mismatches,edge_pixels,hidden_drawn_share,"
      "visible_missing_share,worst_x,worst_y\n";
  for (const MethodRun& r : runs) {
    std::string cost = ",,,,,";  // passes, fragments, reads, writes, bytes: none for reference
    std::string rtl = ",,,";
    if (r.total) {
      const PassStats& s = *r.total;
      cost = fmt::format("{},{},{},{},{},{}", r.passes, s.fragments_in,
                         s.color_reads + s.depth_reads, s.color_writes + s.depth_writes,
                         r.traffic.read, r.traffic.written);
      if (r.rtl)
        rtl = fmt::format("{},{},{},{}", s.cycles + r.tile_io_cycles, s.cycles, r.tile_io_cycles,
                          r.compared ? std::to_string(r.mismatches) : "");
    }
    const std::string error =
        r.error ? fmt::format("{:.4f},{},{},{:.6f},{:.6f},{:.4f},{:.4f}", r.error->rmse,
                              psnr_text(r.error->psnr), r.error->max_abs, r.error->share_over_2,
                              r.error->share_over_16, r.error->delta_e_mean, r.error->delta_e_max)
                : ",,,,,,";
    const std::string lines =
        r.line_error ? fmt::format("{},{:.6f},{:.6f}", r.line_error->edge_pixels,
                                   r.line_error->hidden_drawn_share(),
                                   r.line_error->visible_missing_share())
                     : ",,";
    const std::string worst = r.error && r.error->worst_x >= 0
                                  ? fmt::format("{},{}", r.error->worst_x, r.error->worst_y)
                                  : ",";
    csv += fmt::format("{},{},{},{:.1f},{},{},{}\n", r.method, cost, error, r.host_ms, rtl, lines, worst);
  }
  return csv;
}

void print_table(const std::vector<MethodRun>& runs) {
  const bool rtl = std::any_of(runs.begin(), runs.end(), [](const MethodRun& r) { return r.rtl; });
  fmt::print("{:<16} {:>6} {:>10} {:>10} {:>10} {:>8} {:>8} {:>5} {:>8} {:>7} {:>18}", "method",
             "passes", "fragments", "reads", "writes", "rmse", "psnr_dB", "max", ">2/255",
             "dE2000", "worst dE at pixel");
  fmt::print(rtl ? " {:>10} {:>10}\n" : "\n", "rtl_cycles", "mismatches");
  for (const MethodRun& r : runs) {
    if (r.total)
      fmt::print("{:<16} {:>6} {:>10} {:>10} {:>10}", r.method, r.passes, r.total->fragments_in,
                 r.total->color_reads + r.total->depth_reads,
                 r.total->color_writes + r.total->depth_writes);
    else
      fmt::print("{:<16} {:>6} {:>10} {:>10} {:>10}", r.method, "-", "-", "-", "-");
    if (r.error)
      fmt::print(" {:>8.3f} {:>8} {:>5} {:>7.2f}% {:>7.3f} {:>18}", r.error->rmse,
                 psnr_text(r.error->psnr), r.error->max_abs, 100.0 * r.error->share_over_2,
                 r.error->delta_e_mean,
                 r.error->worst_x < 0 ? std::string("- (exact)")
                                      : fmt::format("{:.1f} ({},{})", r.error->delta_e_max,
                                                    r.error->worst_x, r.error->worst_y));
    else
      fmt::print(" {:>8} {:>8} {:>5} {:>8} {:>7} {:>18}", "-", "-", "-", "-", "-", "-");
    if (rtl && r.total && r.rtl)
      fmt::print(" {:>10} {:>10}\n", r.total->cycles + r.tile_io_cycles,
                 r.compared ? std::to_string(r.mismatches) : "-");
    else
      fmt::print(rtl ? " {:>10} {:>10}\n" : "\n", "-", "-");
  }
  // The shaded error of a wireframe measures nothing: its own against the line reference.
  for (const MethodRun& r : runs)
    if (r.line_error)
      fmt::print("{:<16} edges against the exact line reference: {:.3f}% of its {} edge pixels "
                 "drawn hidden, {:.3f}% visible missing\n",
                 r.method, 100 * r.line_error->hidden_drawn_share(), r.line_error->edge_pixels,
                 100 * r.line_error->visible_missing_share());
}

std::string stats_json(const std::vector<MethodRun>& runs, const std::string& header_json) {
  nlohmann::json j = nlohmann::json::parse(header_json);
  j["methods"] = nlohmann::json::array();
  for (const MethodRun& r : runs) {
    nlohmann::json m = {{"method", r.method}, {"host_ms", r.host_ms}, {"error", nullptr}};
    if (r.error) {
      const ImageError& e = *r.error;
      m["error"] = {
          {"rmse", e.rmse},
          {"psnr_db", std::isinf(e.psnr) ? nlohmann::json(nullptr) : nlohmann::json(e.psnr)},
          {"max_abs", e.max_abs},
          {"share_over_2", e.share_over_2},
          {"share_over_16", e.share_over_16},
          {"delta_e_mean", e.delta_e_mean},
          {"delta_e_max", e.delta_e_max},
          {"worst_pixel", e.worst_x < 0 ? nlohmann::json(nullptr)
                                        : nlohmann::json{{"x", e.worst_x}, {"y", e.worst_y},
                                                         {"delta_e", e.delta_e_max}}}};
    }
    if (r.line_error)
      m["line_error"] = {{"edge_pixels", r.line_error->edge_pixels},
                         {"hidden_drawn", r.line_error->hidden_drawn},
                         {"visible_missing", r.line_error->visible_missing},
                         {"hidden_drawn_share", r.line_error->hidden_drawn_share()},
                         {"visible_missing_share", r.line_error->visible_missing_share()}};
    if (r.total) {
      const PassStats& s = *r.total;
      m["passes"] = r.passes;
      m["total"] = {{"fragments_in", s.fragments_in},
                    {"fragments_passed", s.fragments_passed},
                    {"fragments_killed", s.fragments_killed()},
                    {"color_reads", s.color_reads},
                    {"color_writes", s.color_writes},
                    {"depth_reads", s.depth_reads},
                    {"depth_writes", s.depth_writes}};
      m["bytes_read"] = r.traffic.read;
      m["bytes_written"] = r.traffic.written;
      if (r.rtl) {
        m["rtl"] = {{"cycles", s.cycles + r.tile_io_cycles},
                    {"stream_cycles", s.cycles},
                    {"tile_cycles", r.tile_io_cycles}};
        if (r.compared) m["rtl"]["mismatches"] = r.mismatches;
      }
    }
    j["methods"].push_back(m);
  }
  return j.dump(2) + "\n";
}

}  // namespace zb::app
