// DIR/sweeps.md: each chart with what it shows, in the run's own numbers.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "sweeps.h"

namespace zb::lab {

namespace {

std::string pct(double share) { return fmt::format("{:.2f}%", 100 * share); }

bool wireframe(const std::string& m) { return m == "hidden-line" || m == "hidden-line-dim"; }

// The rows of `method` (and `scene`, when not empty), in x order as the sweep made them.
std::vector<const MethodRow*> rows_of(const std::vector<MethodRow>& rows, const std::string& method,
                                      const std::string& scene = "") {
  std::vector<const MethodRow*> out;
  for (const MethodRow& r : rows)
    if (r.method == method && (scene.empty() || r.scene == scene)) out.push_back(&r);
  return out;
}

// The largest max_abs of `method` over the rows with lo <= x <= hi, or -1 when there is none.
int worst_max(const std::vector<MethodRow>& rows, const std::string& method, double lo, double hi) {
  int worst = -1;
  for (const MethodRow* r : rows_of(rows, method))
    if (r->x >= lo && r->x <= hi) worst = std::max(worst, r->error.max_abs);
  return worst;
}

std::vector<std::string> methods_in(const std::vector<MethodRow>& rows) {
  std::vector<std::string> out;
  for (const MethodRow& r : rows)
    if (std::find(out.begin(), out.end(), r.method) == out.end()) out.push_back(r.method);
  return out;
}

std::string orbit_section(const SweepResults& r) {
  if (r.orbit_rows.empty()) return "";
  auto means = mean_popping(r.orbit_rows);
  std::stable_sort(means.begin(), means.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string ranked, zero;
  for (const auto& [m, v] : means) {
    if (v == 0) zero += (zero.empty() ? "" : ", ") + fmt::format("`{}`", m);
    else ranked += (ranked.empty() ? "" : ", ") + fmt::format("`{}` {}", m, pct(v));
  }
  const OrbitRow* peak = &r.orbit_rows.front();
  for (const OrbitRow& row : r.orbit_rows)
    if (row.popping > peak->popping) peak = &row;
  const Viewport& vp = r.orbit.viewport;
  std::string md = "## Orbit\n\n![orbit](orbit.png)\n\n";
  md += fmt::format(
      "The camera goes once around `{}` in {} steps of {:g} degree{} at {}x{}, at the scene's own "
      "distance and height; a pixel pops when a channel changes from one frame to the next by "
      "more than the reference's change there plus {}/255. Mean popping share per frame: {}; "
      "none at all for {}. The largest single step is `{}` at {:g} degrees ({}). A method whose "
      "edges have more contrast than the reference's scores wherever they move, without "
      "flickering: wireframes, and transparent surfaces drawn opaque.\n\n",
      r.orbit_scene, r.orbit.steps, 360.0 / r.orbit.steps, r.orbit.steps == 360 ? "" : "s",
      vp.width, vp.height, r.orbit.threshold,
      ranked.empty() ? "none" : ranked, zero.empty() ? "no method" : zero, peak->method,
      peak->angle_deg, pct(peak->popping));
  return md;
}

std::string depth_section(const SweepResults& r) {
  if (r.depth_rows.empty()) return "";
  std::string onsets;
  for (const int bits : r.depth.depth_bits) {
    const double s = onset_separation(r.depth_rows, "opaque", bits);
    onsets += fmt::format("{}{} bits {}", onsets.empty() ? "" : ", ", bits,
                          s > 0 ? fmt::format("{:.3g}", s) : std::string("none"));
  }
  const double ref_onset = onset_separation(r.depth_rows, kReferenceMethod, 0);
  const int widest = r.depth.depth_bits.empty() ? 0 : r.depth.depth_bits.back();
  size_t differ = 0, points = 0;
  for (const DepthRow& row : r.depth_rows)
    if (row.method == "opaque" && row.depth_bits == widest)
      ++points, differ += row.error_vs_reference > 0;
  const auto seps = r.depth.separations.empty() ? default_separations() : r.depth.separations;
  const DepthRow* ref_first = nullptr;  // the reference at the smallest separation
  for (const DepthRow& row : r.depth_rows)
    if (row.method == kReferenceMethod && (!ref_first || row.separation < ref_first->separation))
      ref_first = &row;
  const std::string exact =
      ref_onset > 0
          ? fmt::format("The exact sort itself fails from {:.3g} down ({} of the near quad at "
                        "{:.3g}): vertices snap to 1/256 pixel but keep their depths, which "
                        "tilts the two planes apart by more than their distance.",
                        ref_onset, pct(ref_first->error), ref_first->separation)
          : std::string("The exact sort never fails in this range.");
  std::string md = "## Depth\n\n![depth](depth.png)\n\n";
  md += fmt::format(
      "Two parallel opaque quads, the near one submitted second, drawn with `opaque` at "
      "separations from {:.3g} to {:.3g} world units; the error is the share of the near quad's "
      "pixels that show the far one. The far quad first shows through (the largest separation "
      "with any such pixel) at: {}. {} At {} bits `opaque` differs from the reference at {} of "
      "{} separations.\n\n",
      seps.front(), seps.back(), onsets, exact, widest, differ, points);
  return md;
}

std::string layers_section(const SweepResults& r) {
  if (r.layers_rows.empty()) return "";
  const std::vector<MethodRow>& rows = r.layers_rows;
  const int n = r.layers.max_layers;
  std::string md = "## Layers\n\n![layers](layers.png)\n\n";
  md += fmt::format(
      "`layers_scene(N, {:.2f})`: N transparent quads submitted near to far over a two-tone "
      "backdrop, N = 1 to {}, at {}x{}.",
      r.layers.alpha, n, r.layers.viewport.width, r.layers.viewport.height);
  const int ref = worst_max(rows, kReferenceMethod, 1, n);
  if (ref >= 0) md += fmt::format(" `reference`'s largest channel error: {}.", ref);
  std::string peel;
  for (const int k : kDepthPeelLayers) {
    const std::string m = fmt::format("depth-peel-{}", k);
    const int within = worst_max(rows, m, 1, k), beyond = worst_max(rows, m, k + 1, k + 1);
    if (within < 0) continue;
    peel += fmt::format("{}`{}` {} up to {} layers{}", peel.empty() ? "" : "; ", m, within, k,
                        beyond < 0 ? "" : fmt::format(" and {} at {}", beyond, k + 1));
    // Behind K layers only (1 - a)^K of the light is left: the missing ones may not show.
    const double left = 255.0 * std::pow(1.0 - std::lround(r.layers.alpha * 255.0f) / 255.0, k);
    if (beyond >= 0 && beyond <= within)
      peel += fmt::format(" (behind {} layers of alpha {:.2f} only {:.1f}/255 of the light is "
                          "left, too little for the missing layers to show)", k, r.layers.alpha,
                          left);
  }
  if (!peel.empty()) md += fmt::format(" Largest channel error (8-bit units): {}.", peel);
  const int u1 = worst_max(rows, "unsorted", 1, 1), u2 = worst_max(rows, "unsorted", 2, n);
  if (u1 >= 0)
    md += fmt::format(" `unsorted` is off by at most {} for one layer{}.", u1,
                      u2 < 0 ? "" : fmt::format(" and by up to {} from two on (it blends the "
                                                "far layers over the near ones)", u2));
  const auto three = rows_of(rows, "three-pass");
  if (!three.empty())
    md += fmt::format(" `three-pass` has RMSE {:.2f} on one layer, which it blends twice.",
                      three.front()->error.rmse);
  return md + "\n\n";
}

// Per method, how far its error moves with the submission order: up to K layers and beyond.
std::string order_section(const SweepResults& r) {
  if (r.order_rows.empty()) return "";
  // RMSE by method, then layer count, over the three orders.
  std::map<std::string, std::map<int, std::pair<double, double>>> range;
  for (const MethodRow& row : r.order_rows) {
    const std::string m = row.method.substr(0, row.method.find(" ("));
    auto [it, fresh] = range[m].try_emplace(int(row.x), row.error.rmse, row.error.rmse);
    if (!fresh) {
      it->second.first = std::min(it->second.first, row.error.rmse);
      it->second.second = std::max(it->second.second, row.error.rmse);
    }
  }
  std::string per;
  for (const std::string& m : r.order.methods) {
    if (!range.count(m)) continue;
    int identical = 0;  // the layer counts up to which every order gives the same RMSE
    double spread = 0;
    for (const auto& [n, mm] : range[m]) {
      if (identical == n - 1 && mm.first == mm.second) identical = n;
      spread = std::max(spread, mm.second - mm.first);
    }
    per += fmt::format("{}`{}` the same in every order up to {} layer{}, RMSE spread at most {:.2f}",
                       per.empty() ? "" : "; ", m, identical, identical == 1 ? "" : "s", spread);
  }
  std::string md = "## Order\n\n![order](order.png)\n\n";
  md += fmt::format(
      "`layers_scene(N, {:.2f})` with its layers submitted near to far, far to near and shuffled "
      "(seed {}), N = 1 to {}, at {}x{}: {}. The RMSE of a method is equal in every order up to "
      "the layer count given, bit for bit in its frames where that count is K for mlab-K "
      "(tests/methods/test_mlab.cpp).\n\n",
      r.order.alpha, r.order.seed, r.order.max_layers, r.order.viewport.width,
      r.order.viewport.height, per);
  return md;
}

std::string alpha_section(const SweepResults& r) {
  if (r.alpha_rows.empty()) return "";
  std::string peaks;
  for (const std::string& m : methods_in(r.alpha_rows)) {
    if (m == kReferenceMethod || wireframe(m)) continue;
    const MethodRow* best = nullptr;
    for (const MethodRow* row : rows_of(r.alpha_rows, m))
      if (!best || row->error.rmse > best->error.rmse) best = row;
    peaks += fmt::format("{}`{}` {:.1f} at {:.2f}", peaks.empty() ? "" : ", ", m,
                         best->error.rmse, best->x);
  }
  std::string md = "## Alpha\n\n![alpha](alpha.png)\n\n";
  md += fmt::format(
      "`layers_scene({}, a)` for a = {:.2f} to {:.2f}. The largest RMSE of each method and the "
      "alpha where it occurs: {}. The chart leaves out the wireframe methods: they draw lines, "
      "and their error against a shaded image measures only that.\n\n",
      r.alpha.layers, r.alpha_rows.front().x, r.alpha_rows.back().x, peaks);
  return md;
}

std::string samples_section(const SweepResults& r) {
  if (r.samples_rows.empty()) return "";
  // coverage-aa's RMSE at each count, and which way it went from the first to the last.
  auto curve = [&](const std::string& scene) {
    std::string c;
    const auto rows = rows_of(r.samples_rows, "coverage-aa", scene);
    for (const MethodRow* row : rows)
      c += fmt::format("{}{:.2f}", c.empty() ? "" : ", ", row->error.rmse);
    if (rows.size() < 2) return c;
    const double first = rows.front()->error.rmse, last = rows.back()->error.rmse;
    return c + (last > first ? ": it rises" : last < first ? ": it falls" : ": level");
  };
  auto opaque = [&](const std::string& scene) {
    const auto o = rows_of(r.samples_rows, "opaque", scene);
    return o.empty() ? std::string()
                     : fmt::format(", against {:.2f} for `opaque`", o.front()->error.rmse);
  };
  std::string counts;
  for (const int n : r.samples.samples)
    counts += fmt::format("{}{}", counts.empty() ? "" : ", ", n);
  const std::string tri = separate_triangles_scene().name;
  std::string md = "## Coverage samples\n\n![samples](samples.png)\n\n";
  md += fmt::format(
      "`coverage-aa` with {} samples per pixel against the reference supersampled {}x{} and "
      "box-filtered, at {}x{}. Its RMSE on `{}` (the scene's opaque objects) goes {}{}; on `{}` "
      "(edges, none of them shared) {}{}. On the second scene the error is anti-aliasing alone; "
      "on the first, one coverage count per pixel also lets the background leak through the "
      "edges that two triangles of one surface share (README, `parts`).\n\n",
      counts, r.samples.supersample, r.samples.supersample, r.samples.viewport.width,
      r.samples.viewport.height, r.samples_scene, curve(r.samples_scene), opaque(r.samples_scene),
      tri, curve(tri), opaque(tri));
  return md;
}

// A knob's value: "none" for no clamp, 2^k for the large powers of two, as the chart labels it.
std::string value_text(const std::string& knob, double v) {
  if (std::isinf(v)) return "none";
  if (knob == "slope") return fmt::format("{}", v);
  const int k = std::ilogb(v);
  if (v >= 1024 && std::ldexp(1.0, k) == v) return fmt::format("2^{} units", k);
  return fmt::format("{} units", v);
}

// The error shares of one setting on one built-in scene, as "h% hidden drawn, m% missing".
std::string scene_figures(const std::vector<OffsetRow>& rows, const std::string& knob, double value,
                          const std::string& scene) {
  for (const OffsetRow& r : rows)
    if (r.knob == knob && r.value == value && r.scene == scene)
      return fmt::format("{} hidden drawn, {} visible missing", pct(r.error.hidden_drawn_share()),
                         pct(r.error.visible_missing_share()));
  return "not run";
}

std::string offset_section(const SweepResults& r) {
  if (r.offset_rows.empty()) return "";
  const std::vector<OffsetRow>& rows = r.offset_rows;
  std::vector<std::string> knobs;
  for (const OffsetSetting& s : offset_settings())
    if (std::find(knobs.begin(), knobs.end(), s.knob) == knobs.end()) knobs.push_back(s.knob);
  std::string per_knob;
  for (const std::string& k : knobs) {
    std::vector<double> values;
    for (const OffsetSetting& s : offset_settings())
      if (s.knob == k) values.push_back(s.value);
    const double knee = offset_knee(rows, k);
    per_knob += fmt::format("{}`{}`: {} at {}, {} at its knee {}, {} at {}", per_knob.empty() ? "" : "; ",
                            k, pct(offset_tilt_error(rows, k, values.front())),
                            value_text(k, values.front()), pct(offset_tilt_error(rows, k, knee)),
                            value_text(k, knee), pct(offset_tilt_error(rows, k, values.back())),
                            value_text(k, values.back()));
  }
  std::string scenes;
  for (const std::string& sc : r.offset.scenes) {
    scenes += fmt::format(" On `{}`: the first polygon offset (2 units + 1.0 x slope) {}; the "
                          "plans' default {}.",
                          sc, scene_figures(rows, "slope", 1.0, sc),
                          scene_figures(rows, "faces", double(kEdgeOffset.units), sc));
  }
  std::string def;
  for (const OffsetRow& row : rows)
    if (row.is_default) {
      def = fmt::format("`{}` at {}", row.knob, value_text(row.knob, row.value));
      break;
    }
  const size_t tilts = r.offset.tilts.empty() ? default_tilts().size() : r.offset.tilts.size();
  std::string md = "## Hidden-line offset\n\n![offset](offset.png)\n\n";
  md += fmt::format(
      "`hidden-line` with each depth offset, on a plate tilted 0 to 89.9 degrees away from the "
      "eye with a ball behind it ({} tilts) and on the built-in scenes, at {}x{}, against the "
      "exact line reference: hidden edge pixels drawn (the leak) and visible ones missing (the "
      "gaps), as shares of the reference's edge pixels. Mean over the tilts of the two together, "
      "per knob, at its smallest value, at its knee (its smallest value within 0.1% of its "
      "least) and at its largest: {}. The plans' default: {}.{}\n\n",
      tilts, r.offset.viewport.width, r.offset.viewport.height, per_knob,
      def.empty() ? std::string("not among the settings") : def, scenes);
  return md;
}

// Per scene: wboit at the default widths against the baselines, at their traffic.
std::string wboit_section(const SweepResults& r) {
  if (r.wboit_rows.empty()) return "";
  const WboitFormat d;
  const std::vector<WboitRow>& rows = r.wboit_rows;
  std::string table = "| scene | wboit (default) |";
  for (const std::string& b : r.wboit.baselines) table += " " + b + " |";
  table += "\n|---|---|";
  for (size_t i = 0; i < r.wboit.baselines.size(); ++i) table += "---|";
  table += "\n";
  auto cell = [](const WboitRow& w) {
    return fmt::format(" {:.2f} ({:.0f} kB) |", w.error.delta_e_mean, w.bytes / 1e3);
  };
  std::vector<std::string> scenes;
  for (const WboitRow& w : rows)
    if (std::find(scenes.begin(), scenes.end(), w.scene) == scenes.end())
      scenes.push_back(w.scene);
  for (const std::string& sc : scenes) {
    table += "| `" + sc + "` |";
    for (const WboitRow& w : rows)
      if (w.scene == sc && w.method == "wboit" && w.format == d) table += cell(w);
    for (const std::string& b : r.wboit.baselines)
      for (const WboitRow& w : rows)
        if (w.scene == sc && w.method == b) table += cell(w);
    table += "\n";
  }
  std::string md = "## Weighted blended OIT\n\n![wboit](wboit.png)\n\n";
  md += fmt::format(
      "`wboit` at every accumulation width A and weight range W (revealage 8 bits), at {}x{}, "
      "mean CIEDE2000 over the scenes: with A = {} bits the least at W = {} ({:.2f}; no depth "
      "weight, W = 0: {:.2f}); A = 12 saturates ({:.2f} at W = {}, {:.2f} at W = 16); A = 32 "
      "at W = {}: {:.2f}. Per scene, mean CIEDE2000 and memory traffic:\n\n{}\n",
      r.wboit.viewport.width, r.wboit.viewport.height, d.acc_bits,
      wboit_best_weight(rows, d.acc_bits),
      wboit_mean_error(rows, d.acc_bits, wboit_best_weight(rows, d.acc_bits)),
      wboit_mean_error(rows, d.acc_bits, 0), wboit_mean_error(rows, 12, d.weight_bits),
      d.weight_bits, wboit_mean_error(rows, 12, 16), d.weight_bits,
      wboit_mean_error(rows, 32, d.weight_bits), table);
  return md;
}

}  // namespace

std::vector<std::pair<std::string, double>> mean_popping(const std::vector<OrbitRow>& rows) {
  std::vector<std::pair<std::string, double>> means;
  std::vector<int> counts;
  for (const OrbitRow& r : rows) {
    size_t i = 0;
    while (i < means.size() && means[i].first != r.method) ++i;
    if (i == means.size()) means.emplace_back(r.method, 0.0), counts.push_back(0);
    means[i].second += r.popping;
    ++counts[i];
  }
  for (size_t i = 0; i < means.size(); ++i) means[i].second /= counts[i];
  return means;
}

std::string sweeps_markdown(const SweepResults& r) {
  std::string md = "# Sweeps\n\n";
  md += fmt::format(
      "Where methods fail as one parameter moves, made by `zblend sweep all` in {:.0f} s "
      "(docs/sweeps.md defines each sweep). Errors are in 8-bit units against the exact "
      "reference; the CSV beside each chart holds every number.\n\n",
      r.seconds);
  md += orbit_section(r) + depth_section(r) + layers_section(r) + order_section(r) +
        alpha_section(r) +
        samples_section(r) + offset_section(r) + wboit_section(r);
  return md;
}

}  // namespace zb::lab
