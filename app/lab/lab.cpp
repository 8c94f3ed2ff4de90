#include "lab.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <fmt/core.h>
#include <fmt/format.h>

#include "geometry/frame_geometry.h"
#include "history/history_report.h"
#include "metrics/error_map.h"
#include "pipeline/passes.h"
#include "reference/line_reference.h"
#include "reference/reference.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "rtl_rop.h"
#include "sizing_cost.h"

namespace zb::lab {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kHostTimeRuns = 3;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

PassStats sum_passes(const RenderResult& r) {
  PassStats total;
  for (const PassStats& p : r.passes) total += p;
  return total;
}

uint64_t differing_pixels(const Framebuffer& a, const Framebuffer& b) {
  if (a.color.size() != b.color.size()) return std::max(a.color.size(), b.color.size());
  uint64_t n = 0;
  for (size_t i = 0; i < a.color.size(); ++i) n += !(a.color[i] == b.color[i]);
  return n;
}

std::string psnr_text(double psnr) { return std::isinf(psnr) ? "inf" : fmt::format("{:.3f}", psnr); }

std::string error_cells(const ImageError& e) {
  return fmt::format("{:.4f},{},{},{:.6f},{:.6f},{:.4f},{:.4f}", e.rmse, psnr_text(e.psnr),
                     e.max_abs, e.share_over_2, e.share_over_16, e.delta_e_mean, e.delta_e_max);
}

}  // namespace

const char* to_string(FairReference r) {
  switch (r) {
    case FairReference::kExact: return "exact";
    case FairReference::kSupersampled: return "supersampled";
    case FairReference::kLines: return "lines";
  }
  return "?";
}

FairReference fair_reference(const std::string& method) {
  const PassPlan* plan = find_plan(method);
  if (!plan) return FairReference::kExact;
  if (plan_draws_edges(*plan)) return FairReference::kLines;
  const bool aa = std::any_of(plan->passes.begin(), plan->passes.end(),
                              [](const PassState& p) { return is_coverage_pass(p.rop); });
  return aa ? FairReference::kSupersampled : FairReference::kExact;
}

SceneRun run_scene(const LabScene& ls, const LabOptions& o) {
  const auto start = Clock::now();
  const Viewport& vp = o.viewport;
  SceneRun run;
  const Scene scene = ls.load();
  const RasterizedScene rs = rasterize_scene(scene, vp);
  run.triangles = rs.triangles.size();
  run.fragments = rs.fragments.size();
  double reference_ms = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kHostTimeRuns; ++i) {
    const auto t = Clock::now();
    run.reference = render_reference(rs);
    reference_ms = std::min(reference_ms, ms_since(t));
  }
  run.reference_ss = render_reference_supersampled(scene, vp, o.supersample);
  std::optional<LineVisibility> lines;  // the line reference, when a method draws edges
  std::vector<std::vector<float>> errors;  // per method, its CIEDE2000 map (none for lines)

  for (const std::string& m : o.methods) {
    LabRow row;
    row.scene = ls.name;
    row.family = ls.family;
    row.method = m;
    Framebuffer image;
    if (const PassPlan* plan = find_plan(m)) {
      // Host time: the best of three runs, as other work on the machine only ever adds to it.
      RenderResult r;
      row.host_ms = std::numeric_limits<double>::infinity();
      for (int i = 0; i < kHostTimeRuns; ++i) {
        GoldenRop golden;
        const auto t = Clock::now();
        r = render(rs, *plan, golden);
        row.host_ms = std::min(row.host_ms, ms_since(t));
      }
      row.has_cost = true;
      row.passes = plan->passes.size();
      row.golden = sum_passes(r);
      const Traffic traffic = plan_traffic(r.passes, *plan, vp);
      row.bytes_read = traffic.read;
      row.bytes_written = traffic.written;
      image = std::move(r.framebuffer);
      // The cost model watches the RTL's run (or, without it, a golden one): one render
      // gives both, and the cost model's cycles stay its own (IssueSchedule, TileStates).
      GoldenRop golden_inner;
      std::unique_ptr<RtlRop> rtl;
      Backend* outer = &golden_inner;
      if (o.rtl) {
        rtl = std::make_unique<RtlRop>();
        outer = rtl.get();
      }
      std::vector<std::unique_ptr<CostCounter>> counters;
      for (const int beat : kLabBeats) {
        counters.push_back(std::make_unique<CostCounter>(*outer, beat));
        outer = counters.back().get();
      }
      const RenderResult rr = render(rs, *plan, *outer);
      for (size_t k = 0; k < kLabBeats.size(); ++k) {
        const TileCost& c = counters[k]->cost().at(kRtlTileW);
        row.model_tile_cycles[k] = c.tile_io_cycles;
        row.model_stream_2buf[k] = c.two_buffer_stream;
        row.model_cycles_2buf[k] = c.two_buffer_cycles;
      }
      const MethodCost& mc = counters[0]->cost();
      row.model_pipe_2buf = mc.at(kRtlTileW).two_buffer_pipe;
      row.model_stream_cycles = mc.at(kRtlTileW).stream_cycles;
      const TileCost& at_rtl = counters[lab_beat_index(kRtlBeat)]->cost().at(kRtlTileW);
      row.model_tile_cycles_resident = at_rtl.resident.io_cycles;
      row.model_cycles_2buf_resident = at_rtl.resident.two_buffer_cycles;
      row.model_cycles_variant = at_rtl.resident.variant_cycles;
      row.model_cycles_2buf_variant = at_rtl.resident.two_buffer_variant_cycles;
      row.port_bytes_pass = at_rtl.port_bytes(TileSchedule::kPass, vp.depth_bits, vp.coverage_samples, vp.wboit);
      row.port_bytes_tile = at_rtl.port_bytes(TileSchedule::kTile, vp.depth_bits, vp.coverage_samples, vp.wboit);
      row.frame_op_pixels = mc.frame_op_pixels;
      row.host_op_pixels_tile = at_rtl.resident.host_op_pixels;
      row.pixels = uint64_t(vp.width) * uint64_t(vp.height);
      if (rtl) {
        row.rtl_stream_cycles = sum_passes(rr).cycles;
        row.rtl_tile_cycles = rtl->tile_io_cycles();
        row.rtl_cycles = row.rtl_stream_cycles + row.rtl_tile_cycles;
        row.rtl_mismatch_pixels = differing_pixels(rr.framebuffer, image);
        // The same frame under the tile schedule: its bits, and its cycles against the model's.
        RtlOptions ro;
        ro.schedule = TileSchedule::kTile;
        RtlRop resident(ro);
        const RenderResult rt = render(rs, *plan, resident);
        row.rtl_resident_tile_cycles = resident.tile_io_cycles();
        row.rtl_resident_mismatch_pixels = differing_pixels(rt.framebuffer, image);
        if (sum_passes(rt).cycles != row.rtl_stream_cycles ||
            *row.rtl_resident_tile_cycles != row.model_tile_cycles_resident)
          throw std::runtime_error(fmt::format(
              "lab: {} {} under the tile schedule: the RTL took {} streaming and {} tile cycles, "
              "the cost model says {} and {}", ls.name, m, sum_passes(rt).cycles,
              *row.rtl_resident_tile_cycles, row.rtl_stream_cycles, row.model_tile_cycles_resident));
      }
    } else if (m == kReferenceMethod) {
      image = run.reference;
      row.host_ms = reference_ms;
    } else {
      throw std::invalid_argument("unknown method '" + m + "'");
    }
    row.error = compare_images(image, run.reference);
    row.error_ss = compare_images(image, run.reference_ss);
    row.fair = fair_reference(m);
    if (row.fair == FairReference::kLines) {
      if (!lines) lines = line_visibility(rs);
      const bool dim = dims_hidden_edges(*find_plan(m));
      const Framebuffer exact_lines = line_reference_image(
          *lines, vp, rs.background, kEdgeColor, dim ? std::optional<Rgba8>(kHiddenEdgeColor)
                                                     : std::nullopt);
      row.error_lines = compare_images(image, exact_lines);
      row.lines = compare_lines(image, *lines, kEdgeColor);
      row.worst = first_line_error(image, *lines, kEdgeColor);
      errors.emplace_back();
    } else {
      errors.push_back(delta_e_map(
          image, row.fair == FairReference::kExact ? run.reference : run.reference_ss));
    }
    run.images.push_back(std::move(image));
    run.rows.push_back(std::move(row));
  }
  // The error maps, one scale for the scene's methods; the worst pixel of each ringed, and its
  // history kept for the report.
  const double scale = shared_error_scale(errors);  // the reference's map is all 0
  for (size_t i = 0; i < run.rows.size(); ++i) {
    LabRow& row = run.rows[i];
    row.error_scale = scale;
    const std::vector<float>& de = errors[i];
    if (row.fair == FairReference::kLines) {
      run.error_images.push_back(line_error_map_image(run.images[i], *lines, kEdgeColor));
    } else {
      row.worst = worst_pixel(de, vp.width);
      run.error_images.push_back(error_map_image(de, vp.width, vp.height, scale, row.worst));
    }
    std::string history;
    if (const PassPlan* plan = find_plan(row.method); plan && row.worst) {
      const FrameHistory h = record_history(rs, *plan, {*row.worst});
      const auto [x, y] = *row.worst;
      history = row.fair == FairReference::kLines
                    ? fmt::format("{}, {}: its first wrong edge pixel\n\n", ls.name, row.method)
                    : fmt::format("{}, {}: the worst pixel of its error map, CIEDE2000 {:.2f} against "
                                  "the {} reference\n\n", ls.name, row.method,
                                  de[size_t(y) * size_t(vp.width) + size_t(x)], to_string(row.fair));
      history += history_text(h, h.pixels[0], &scene);
    }
    run.histories.push_back(std::move(history));
  }
  run.ms = ms_since(start);
  return run;
}

std::string lab_csv(const std::vector<LabRow>& rows) {
  std::string csv =
      "scene,family,method,passes,fragments,fragments_passed,color_reads,color_writes,"
      "depth_reads,depth_writes,bytes_read,bytes_written,host_ms,rtl_cycles,rtl_stream_cycles,rtl_tile_cycles,"
      "rtl_mismatch_pixels,rmse,psnr_db,max_abs,share_over_2,share_over_16,delta_e_mean,"
      "delta_e_max,ss_rmse,ss_psnr_db,ss_max_abs,ss_share_over_2,ss_share_over_16,"
      "ss_delta_e_mean,ss_delta_e_max,fair_reference,fair_delta_e_mean,fair_rmse,"
      "model_stream_cycles,pipe_cycles_2buf";
  for (const int beat : kLabBeats) csv += fmt::format(",tile_cycles_beat{}", beat);
  for (const int beat : kLabBeats) csv += fmt::format(",stream_cycles_2buf_beat{}", beat);
  for (const int beat : kLabBeats) csv += fmt::format(",cycles_2buf_beat{}", beat);
  csv += ",edge_pixels,hidden_drawn,visible_missing,hidden_drawn_share,visible_missing_share";
  csv += ",tile_cycles_tile_schedule,rtl_tile_cycles_tile_schedule,rtl_mismatch_pixels_tile_schedule,"
         "port_bytes_pass,port_bytes_tile,frame_op_pixels,host_op_pixels_tile_schedule,"
         "frame_pixels,cycles_2buf_tile_schedule";
  for (const BankVariant& v : kBankVariants) csv += fmt::format(",cycles_{}_tile_schedule", v.name);
  for (const BankVariant& v : kBankVariants) csv += fmt::format(",cycles_2buf_{}_tile_schedule", v.name);
  csv += "\n";
  for (const LabRow& r : rows) {
    const PassStats& s = r.golden;
    const std::string cost =
        r.has_cost ? fmt::format("{},{},{},{},{},{},{},{},{}", r.passes, s.fragments_in,
                                 s.fragments_passed, s.color_reads, s.color_writes, s.depth_reads,
                                 s.depth_writes, r.bytes_read, r.bytes_written)
                   : ",,,,,,,,";
    const std::string rtl =
        r.rtl_cycles ? fmt::format("{},{},{},{}", *r.rtl_cycles, r.rtl_stream_cycles,
                                   r.rtl_tile_cycles, r.rtl_mismatch_pixels)
                     : ",,,";
    std::string model;
    if (r.has_cost) {
      model = fmt::format("{},{}", r.model_stream_cycles, r.model_pipe_2buf);
      for (const uint64_t t : r.model_tile_cycles) model += fmt::format(",{}", t);
      for (const uint64_t t : r.model_stream_2buf) model += fmt::format(",{}", t);
      for (const uint64_t t : r.model_cycles_2buf) model += fmt::format(",{}", t);
    } else {
      model = std::string(3 * kLabBeats.size() + 1, ',');
    }
    const std::string lines =
        r.lines ? fmt::format("{},{},{},{:.6f},{:.6f}", r.lines->edge_pixels,
                              r.lines->hidden_drawn, r.lines->visible_missing,
                              r.lines->hidden_drawn_share(), r.lines->visible_missing_share())
                : ",,,,";
    std::string sched =
        r.has_cost ? fmt::format("{},{},{},{},{},{},{},{},{}", r.model_tile_cycles_resident,
                                 r.rtl_resident_tile_cycles ? std::to_string(*r.rtl_resident_tile_cycles) : "",
                                 r.rtl_resident_tile_cycles ? std::to_string(r.rtl_resident_mismatch_pixels) : "",
                                 r.port_bytes_pass, r.port_bytes_tile, r.frame_op_pixels,
                                 r.host_op_pixels_tile, r.pixels, r.model_cycles_2buf_resident)
                   : ",,,,,,,,";
    for (const auto* v : {&r.model_cycles_variant, &r.model_cycles_2buf_variant})
      for (const uint64_t c : *v) sched += r.has_cost ? fmt::format(",{}", c) : ",";
    csv += fmt::format("{},{},{},{},{:.3f},{},{},{},{},{:.4f},{:.4f},{},{},{}\n", r.scene, r.family,
                       r.method, cost, r.host_ms, rtl, error_cells(r.error),
                       error_cells(r.error_ss), to_string(r.fair), r.fair_error().delta_e_mean,
                       r.fair_error().rmse, model, lines, sched);
  }
  return csv;
}

std::string tile_share_text(const std::vector<LabRow>& rows, int beat) {
  uint64_t stream = 0, rtl_stream = 0, rtl_tile = 0;
  std::array<uint64_t, kLabBeats.size()> tile{};
  for (const LabRow& r : rows) {
    if (!r.has_cost) continue;
    stream += r.model_stream_cycles;
    for (size_t k = 0; k < tile.size(); ++k) tile[k] += r.model_tile_cycles[k];
    if (r.rtl_cycles) {
      rtl_stream += r.rtl_stream_cycles;
      rtl_tile += r.rtl_tile_cycles;
    }
  }
  std::string out = "tile cycles per streaming cycle (cost model), by pixels a beat:";
  for (size_t k = 0; k < tile.size(); ++k)
    out += fmt::format(" {}{}: {:.1f}%", kLabBeats[k], kLabBeats[k] == beat ? " (zb_rop)" : "",
                       stream ? 100.0 * double(tile[k]) / double(stream) : 0.0);
  if (rtl_stream)
    out += fmt::format("; RTL: {} tile / {} streaming cycles = {:.1f}%", rtl_tile, rtl_stream,
                       100.0 * double(rtl_tile) / double(rtl_stream));
  return out;
}

std::string stream_share_text(const std::vector<LabRow>& rows, int beat) {
  const size_t k = lab_beat_index(beat);
  const bool at_beat = k < kLabBeats.size();
  struct Tally {
    uint64_t cycles = 0, fragments = 0, above = 0, runs = 0;
    double worst = 0;
    std::string worst_run;
    void add(const LabRow& r, uint64_t c) {
      const uint64_t f = r.golden.fragments_in;
      if (f == 0) return;
      cycles += c;
      fragments += f;
      ++runs;
      const double per = double(c) / double(f);
      above += per > 1.01;
      if (per > worst) worst = per, worst_run = r.scene + " " + r.method;
    }
    double overall() const { return fragments ? double(cycles) / double(fragments) : 0.0; }
    std::string text() const {
      return fmt::format("{:.4f} overall, worst {:.3f} ({}), {} of {} runs above 1.01",
                         overall(), worst, worst_run.empty() ? "none" : worst_run, above, runs);
    }
  } one, two, all_one, all_two;
  for (const LabRow& r : rows) {
    if (!r.has_cost) continue;
    const uint64_t stream = r.rtl_cycles ? r.rtl_stream_cycles : r.model_stream_cycles;
    one.add(r, stream);
    two.add(r, r.model_pipe_2buf);
    if (!at_beat) continue;
    all_one.add(r, r.rtl_cycles ? *r.rtl_cycles : stream + r.model_tile_cycles[k]);
    all_two.add(r, r.model_cycles_2buf[k]);
  }
  std::string out = fmt::format(
      "streaming cycles per fragment: {}; with a second tile buffer (cost model of the "
      "proposed design; its fill and drain once a pass): {}", one.text(), two.text());
  if (at_beat)
    out += fmt::format(". All cycles per fragment, the tile port's included, at {} pixels a "
                       "beat: {:.4f} with one buffer, {:.4f} with two (worst run {:.3f}, {})",
                       beat, all_one.overall(), all_two.overall(), all_two.worst,
                       all_two.worst_run.empty() ? "none" : all_two.worst_run);
  return out;
}

std::string schedule_text(const std::vector<LabRow>& rows, bool per_method) {
  struct Sum {
    uint64_t fragments = 0, stream = 0, io[2] = {0, 0}, bytes[2] = {0, 0}, host[2] = {0, 0}, pixels = 0,
             mismatch[2] = {0, 0}, runs = 0, two_buffers = 0;
    std::array<uint64_t, kBankVariants.size()> variant{}, variant2{};
    void add(const LabRow& r) {
      fragments += r.golden.fragments_in;
      stream += r.model_stream_cycles;
      io[0] += r.model_tile_cycles[lab_beat_index(kRtlBeat)];
      io[1] += r.model_tile_cycles_resident;
      bytes[0] += r.port_bytes_pass;
      bytes[1] += r.port_bytes_tile;
      host[0] += r.frame_op_pixels;
      host[1] += r.host_op_pixels_tile;
      pixels += r.pixels;
      mismatch[0] += r.rtl_mismatch_pixels;
      mismatch[1] += r.rtl_resident_mismatch_pixels;
      two_buffers += r.model_cycles_2buf_resident;
      for (size_t v = 0; v < variant.size(); ++v) {
        variant[v] += r.model_cycles_variant[v];
        variant2[v] += r.model_cycles_2buf_variant[v];
      }
      ++runs;
    }
    double per(uint64_t c) const { return fragments ? double(c) / double(fragments) : 0.0; }
  };
  Sum all;
  std::vector<std::pair<std::string, Sum>> methods;
  bool rtl = false;
  for (const LabRow& r : rows) {
    if (!r.has_cost || r.golden.fragments_in == 0) continue;
    rtl = rtl || r.rtl_resident_tile_cycles.has_value();
    all.add(r);
    auto it = std::find_if(methods.begin(), methods.end(), [&](const auto& m) { return m.first == r.method; });
    if (it == methods.end()) it = methods.insert(methods.end(), {r.method, Sum{}});
    it->second.add(r);
  }
  auto line = [](const std::string& what, const Sum& s, int i) {
    return fmt::format("{} {}: all cycles per fragment {:.4f} (streaming {:.4f}, tile port {:.4f}), "
                       "{:.4f} with the host's frame operations at a pixel a clock; tile-port "
                       "bytes per pixel {:.1f}",
                       what, i ? "tile" : "pass", s.per(s.stream + s.io[i]), s.per(s.stream),
                       s.per(s.io[i]), s.per(s.stream + s.io[i] + s.host[i]),
                       s.pixels ? double(s.bytes[i]) / double(s.pixels) : 0.0);
  };
  std::string out;
  for (int i = 0; i < 2; ++i) {
    out += line("schedule", all, i);
    if (rtl) out += fmt::format("; {} mismatching pixels on the RTL", all.mismatch[i]);
    out += "\n";
  }
  out += fmt::format("schedule tile with two tile buffers (cost model of the proposed design): "
                     "all cycles per fragment {:.4f}, {:.4f} with the host's frame operations\n",
                     all.per(all.two_buffers), all.per(all.two_buffers + all.host[1]));
  // Per bank variant: "a / b / c / d".
  auto variants = [&](const std::array<uint64_t, kBankVariants.size()>& c, uint64_t more) {
    std::string s;
    for (size_t v = 0; v < c.size(); ++v) s += fmt::format("{}{:.4f}", v ? " / " : "", all.per(c[v] + more));
    return s;
  };
  out += fmt::format("schedule tile with copies of depth to peel by reads / renamed with the "
                     "depth banks' generations of 1 / 2 (zb_rop) / 3 bits (cost model): all cycles "
                     "per fragment with one tile buffer {}, with two {}; with the host's frame "
                     "operations {} and {}\n",
                     variants(all.variant, 0), variants(all.variant2, 0),
                     variants(all.variant, all.host[1]), variants(all.variant2, all.host[1]));
  if (!per_method) return out;
  for (const auto& [name, m] : methods)
    out += fmt::format("  {:<16} pass: {:.4f} cycles/fragment, {:5.1f} B/pixel, host frame "
                       "operations {:.4f}; tile: {:.4f}, {:5.1f} B/pixel, host {:.4f}; "
                       "two buffers {:.4f}\n",
                       name, m.per(m.stream + m.io[0]),
                       m.pixels ? double(m.bytes[0]) / double(m.pixels) : 0.0, m.per(m.host[0]),
                       m.per(m.stream + m.io[1]),
                       m.pixels ? double(m.bytes[1]) / double(m.pixels) : 0.0, m.per(m.host[1]),
                       m.per(m.two_buffers));
  return out;
}

std::vector<size_t> pareto_front(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = std::min(x.size(), y.size());
  std::vector<size_t> front;
  for (size_t i = 0; i < n; ++i) {
    if (std::isnan(x[i]) || std::isnan(y[i])) continue;
    bool dominated = false;
    for (size_t j = 0; j < n && !dominated; ++j)
      dominated = x[j] <= x[i] && y[j] <= y[i] && (x[j] < x[i] || y[j] < y[i]);
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](size_t a, size_t b) {
    return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b];
  });
  return front;
}

namespace {

// One row as a summary of one scene.
MethodSummary one_scene(const std::string& family, const LabRow& r) {
  MethodSummary s;
  s.family = family;
  s.method = r.method;
  s.scenes = 1;
  s.delta_e_mean = r.fair_error().delta_e_mean;
  s.rmse = r.fair_error().rmse;
  s.share_over_16 = r.fair_error().share_over_16;
  s.fragments = double(r.golden.fragments_in);
  s.bytes = double(r.bytes_read + r.bytes_written);
  s.host_ms = r.host_ms;
  if (r.rtl_cycles) s.rtl_cycles = double(*r.rtl_cycles);
  return s;
}

// The unweighted mean of `parts` (one method) in each of `fields`, labelled `label` (the
// summary's `label_field`: its family or scene); scenes add up. RTL cycles only when every part
// has them.
template <class Summary, size_t N>
Summary mean_of(std::string Summary::*label_field, const std::string& label,
                const std::vector<Summary>& parts, double Summary::*const (&fields)[N]) {
  Summary s;
  s.*label_field = label;
  s.method = parts.front().method;
  double cycles = 0;
  bool all_rtl = true;
  for (const Summary& p : parts) {
    s.scenes += p.scenes;
    for (double Summary::*f : fields) s.*f += p.*f;
    all_rtl = all_rtl && p.rtl_cycles.has_value();
    if (p.rtl_cycles) cycles += *p.rtl_cycles;
  }
  const double n = double(parts.size());
  for (double Summary::*f : fields) s.*f /= n;
  if (all_rtl) s.rtl_cycles = cycles / n;
  return s;
}

// What a method's summary averages.
constexpr double MethodSummary::*kMethodMeans[] = {
    &MethodSummary::delta_e_mean, &MethodSummary::rmse,  &MethodSummary::share_over_16,
    &MethodSummary::fragments,    &MethodSummary::bytes, &MethodSummary::host_ms};

// Means over one family's rows of one method.
MethodSummary summarize_group(const std::string& family, const std::vector<const LabRow*>& rows) {
  std::vector<MethodSummary> scenes;
  for (const LabRow* r : rows) scenes.push_back(one_scene(family, *r));
  return mean_of(&MethodSummary::family, family, scenes, kMethodMeans);
}

// "all": each family counts once, however many scenes it has (the suite samples some
// families, such as layers, far more densely than others).
MethodSummary mean_of_families(const std::vector<const MethodSummary*>& fams) {
  std::vector<MethodSummary> parts;
  for (const MethodSummary* f : fams) parts.push_back(*f);
  return mean_of(&MethodSummary::family, kAllFamilies, parts, kMethodMeans);
}

void mark_pareto(std::vector<MethodSummary>::iterator first,
                 std::vector<MethodSummary>::iterator last) {
  std::vector<double> cost, bytes, err;
  for (auto it = first; it != last; ++it) {
    cost.push_back(it->cost());
    bytes.push_back(it->bytes);
    err.push_back(it->delta_e_mean);
  }
  for (size_t i : pareto_front(cost, err)) first[i].pareto_cost = true;
  for (size_t i : pareto_front(bytes, err)) first[i].pareto_bytes = true;
}

}  // namespace

std::vector<MethodSummary> summarize(const std::vector<LabRow>& rows) {
  std::vector<std::string> families, methods;
  auto note = [](std::vector<std::string>& v, const std::string& s) {
    if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
  };
  for (const LabRow& r : rows) {
    if (!r.has_cost || r.fair == FairReference::kLines) continue;
    note(families, r.family);
    note(methods, r.method);
  }

  std::vector<MethodSummary> out;
  for (const std::string& family : families) {
    const size_t begin = out.size();
    for (const std::string& method : methods) {
      std::vector<const LabRow*> group;
      for (const LabRow& r : rows)
        if (r.has_cost && r.fair != FairReference::kLines && r.method == method &&
            r.family == family)
          group.push_back(&r);
      if (!group.empty()) out.push_back(summarize_group(family, group));
    }
    mark_pareto(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
  }
  const size_t begin = out.size();
  for (const std::string& method : methods) {
    std::vector<const MethodSummary*> per_family;
    for (const MethodSummary& s : out)
      if (s.method == method) per_family.push_back(&s);
    out.push_back(mean_of_families(per_family));
  }
  mark_pareto(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
  return out;
}

std::string summary_csv(const std::vector<MethodSummary>& summaries) {
  std::string csv =
      "family,method,scenes,delta_e_mean,rmse,share_over_16,fragments,bytes,host_ms,rtl_cycles,"
      "cost,cost_unit,pareto_cost,pareto_bytes\n";
  for (const MethodSummary& s : summaries)
    csv += fmt::format("{},{},{},{:.4f},{:.4f},{:.6f},{:.1f},{:.1f},{:.3f},{},{:.1f},{},{},{}\n",
                       s.family, s.method, s.scenes, s.delta_e_mean, s.rmse, s.share_over_16,
                       s.fragments, s.bytes, s.host_ms,
                       s.rtl_cycles ? fmt::format("{:.1f}", *s.rtl_cycles) : "", s.cost(),
                       s.rtl_cycles ? "rtl_cycles" : "fragments", int(s.pareto_cost),
                       int(s.pareto_bytes));
  return csv;
}

namespace {

// What a hidden-line summary averages (over one method's rows, or its family means).
constexpr double LineSummary::*kLineMeans[] = {
    &LineSummary::edge_pixels, &LineSummary::hidden_drawn, &LineSummary::visible_missing,
    &LineSummary::fragments};

}  // namespace

std::vector<LineSummary> line_summary(const std::vector<LabRow>& rows) {
  std::vector<LineSummary> out;
  std::vector<std::string> methods, families;
  std::vector<std::string> family_of;  // per scene row of `out`
  auto note = [](std::vector<std::string>& v, const std::string& s) {
    if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
  };
  for (const LabRow& r : rows) {
    if (!r.lines) continue;
    LineSummary s;
    s.scene = r.scene;
    s.method = r.method;
    s.scenes = 1;
    s.edge_pixels = double(r.lines->edge_pixels);
    s.hidden_drawn = r.lines->hidden_drawn_share();
    s.visible_missing = r.lines->visible_missing_share();
    if (r.rtl_cycles) s.rtl_cycles = double(*r.rtl_cycles);
    s.fragments = double(r.golden.fragments_in);
    out.push_back(s);
    family_of.push_back(r.family);
    note(methods, r.method);
    note(families, r.family);
  }
  // Each family counts once, as in summarize: its scenes' mean, then the mean of those.
  const size_t per_scene = out.size();
  for (const std::string& m : methods) {
    std::vector<LineSummary> family_means;
    for (const std::string& f : families) {
      std::vector<LineSummary> scenes;
      for (size_t i = 0; i < per_scene; ++i)
        if (out[i].method == m && family_of[i] == f) scenes.push_back(out[i]);
      if (!scenes.empty())
        family_means.push_back(mean_of(&LineSummary::scene, f, scenes, kLineMeans));
    }
    out.push_back(mean_of(&LineSummary::scene, kAllFamilies, family_means, kLineMeans));
  }
  return out;
}

std::string line_summary_csv(const std::vector<LineSummary>& summaries) {
  std::string csv =
      "scene,method,scenes,edge_pixels,hidden_drawn,visible_missing,fragments,rtl_cycles,cost,"
      "cost_unit\n";
  for (const LineSummary& s : summaries)
    csv += fmt::format("{},{},{},{:.1f},{:.6f},{:.6f},{:.1f},{},{:.1f},{}\n", s.scene, s.method,
                       s.scenes, s.edge_pixels, s.hidden_drawn, s.visible_missing, s.fragments,
                       s.rtl_cycles ? fmt::format("{:.1f}", *s.rtl_cycles) : "", s.cost(),
                       s.rtl_cycles ? "rtl_cycles" : "fragments");
  return csv;
}

}  // namespace zb::lab
