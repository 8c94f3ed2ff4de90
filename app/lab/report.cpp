#include "report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include <fmt/core.h>

#include "metrics/metrics.h"
#include "pipeline/passes.h"
#include "rtl_params.h"

namespace zb::lab {
namespace {

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> families_of(const ReportInput& in) {
  std::vector<std::string> out;
  for (const ReportScene& s : in.scenes)
    if (!has(out, s.family)) out.push_back(s.family);
  return out;
}

std::string psnr_text(double psnr) { return std::isinf(psnr) ? "inf" : fmt::format("{:.1f}", psnr); }

std::string count_text(double v) {
  if (v >= 1e6) return fmt::format("{:.2f} M", v / 1e6);
  if (v >= 1e3) return fmt::format("{:.1f} k", v / 1e3);
  return fmt::format("{:.0f}", v);
}

std::string md_cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// One table, written once for both formats: a header and rows of cells already escaped.
struct Table {
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> rows;
};

std::string markdown_table(const Table& t) {
  std::string out = "|";
  for (const std::string& h : t.head) out += " " + h + " |";
  out += "\n|";
  for (size_t i = 0; i < t.head.size(); ++i) out += i == 0 ? "---|" : "---:|";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (const std::string& c : row) out += " " + c + " |";
    out += "\n";
  }
  return out + "\n";
}

std::string html_table(const Table& t) {
  std::string out = "<table>\n<tr>";
  for (const std::string& h : t.head) out += "<th>" + h + "</th>";
  out += "</tr>\n";
  for (const auto& row : t.rows) {
    out += "<tr>";
    for (const std::string& c : row) out += "<td>" + c + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

enum class Format { kMarkdown, kHtml };

std::string image(Format f, const std::string& path, const std::string& alt, int width) {
  if (f == Format::kMarkdown) return fmt::format("![{}]({})", alt, path);
  return fmt::format("<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\" width=\"{2}\"></a>",
                     html_escape(path), html_escape(alt), width);
}

std::string text(Format f, const std::string& s) {
  return f == Format::kMarkdown ? md_cell(s) : html_escape(s);
}

std::string link(Format f, const std::string& label, const std::string& target) {
  return f == Format::kMarkdown ? fmt::format("[{}]({})", label, target)
                                : fmt::format("<a href=\"{}\">{}</a>", html_escape(target),
                                              html_escape(label));
}

// "worst pixel (x, y)" linked to its history, or "" when the map rings none.
std::string worst_link(Format f, const LabRow& r) {
  if (!r.worst) return "";
  return link(f, fmt::format("worst pixel ({}, {})", r.worst->first, r.worst->second),
              history_path(r.scene, r.method));
}

// Means per method of one family (or "all").
Table summary_table(const ReportInput& in, const std::string& family, Format f) {
  const bool rtl = in.rtl;
  Table t{{"method", "scenes", "mean &Delta;E2000", "RMSE", "&gt;16/255", "fragments",
           rtl ? "RTL cycles" : "", "bytes", "host ms", "Pareto (cost, bytes)"},
          {}};
  if (f == Format::kMarkdown) {
    t.head[2] = "mean ΔE2000";
    t.head[4] = ">16/255";
  }
  if (!rtl) t.head.erase(t.head.begin() + 6);
  for (const MethodSummary& s : in.summaries) {
    if (s.family != family) continue;
    std::vector<std::string> row = {
        text(f, s.method), std::to_string(s.scenes), fmt::format("{:.2f}", s.delta_e_mean),
        fmt::format("{:.2f}", s.rmse), fmt::format("{:.1f}%", 100.0 * s.share_over_16),
        count_text(s.fragments)};
    if (rtl) row.push_back(s.rtl_cycles ? count_text(*s.rtl_cycles) : "-");
    row.push_back(count_text(s.bytes));
    row.push_back(fmt::format("{:.1f}", s.host_ms));
    row.push_back(std::string(s.pareto_cost ? "cost" : "") +
                  (s.pareto_cost && s.pareto_bytes ? ", " : "") + (s.pareto_bytes ? "bytes" : ""));
    t.rows.push_back(std::move(row));
  }
  return t;
}

// The hidden-line methods per scene and their means: error shares against the exact line
// reference, and cost.
Table line_table(const ReportInput& in, Format f) {
  Table t{{"scene", "method", "edge pixels", "hidden drawn", "visible missing",
           in.rtl ? "RTL cycles" : "fragments"},
          {}};
  for (const LineSummary& s : in.line_summaries)
    t.rows.push_back({text(f, s.scene == kAllFamilies
                                  ? "mean of " + std::to_string(s.scenes) +
                                        " scenes (each family once)"
                                  : s.scene),
                      text(f, s.method), fmt::format("{:.0f}", s.edge_pixels),
                      fmt::format("{:.2f}%", 100.0 * s.hidden_drawn),
                      fmt::format("{:.2f}%", 100.0 * s.visible_missing), count_text(s.cost())});
  return t;
}

// One scene: a row per method with its image, its error image and its numbers.
Table scene_table(const ReportInput& in, const ReportScene& sc, Format f) {
  const bool md = f == Format::kMarkdown;
  Table t{{"method", "image", md ? "error (ΔE2000)" : "error (&Delta;E2000)",
           md ? "mean ΔE" : "mean &Delta;E", md ? "max ΔE" : "max &Delta;E", "RMSE", "PSNR dB",
           md ? ">16/255" : "&gt;16/255", "vs", "worst", "passes", "fragments"},
          {}};
  if (in.rtl) t.head.push_back("RTL cycles");
  const int w = std::min(in.width, 320);
  for (const LabRow& r : in.rows) {
    if (r.scene != sc.name) continue;
    const ImageError& e = r.fair_error();
    std::vector<std::string> row = {
        text(f, r.method),
        image(f, image_path(r.scene, r.method), r.method, w),
        image(f, error_image_path(r.scene, r.method), r.method + " error", w),
        fmt::format("{:.2f}", e.delta_e_mean),
        fmt::format("{:.1f}", e.delta_e_max),
        fmt::format("{:.2f}", e.rmse),
        psnr_text(e.psnr),
        fmt::format("{:.1f}%", 100.0 * e.share_over_16),
        to_string(r.fair),
        worst_link(f, r),
        r.has_cost ? std::to_string(r.passes) : "-",
        r.has_cost ? count_text(double(r.golden.fragments_in)) : "-"};
    if (in.rtl) row.push_back(r.rtl_cycles ? count_text(double(*r.rtl_cycles)) : "-");
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string table(Format f, const Table& t) {
  return f == Format::kMarkdown ? markdown_table(t) : html_table(t);
}

std::string heading(Format f, int level, const std::string& s, const std::string& id = "") {
  if (f == Format::kMarkdown) return std::string(size_t(level), '#') + " " + s + "\n\n";
  const std::string anchor = id.empty() ? "" : " id=\"" + html_escape(id) + "\"";
  return fmt::format("<h{0}{1}>{2}</h{0}>\n", level, anchor, html_escape(s));
}

std::string para(Format f, const std::string& s) {
  return f == Format::kMarkdown ? s + "\n\n" : "<p>" + s + "</p>\n";
}

std::string code(Format f, const std::string& s) {
  return f == Format::kMarkdown ? "`" + s + "`" : "<code>" + html_escape(s) + "</code>";
}

// A family's grid: its scene with the most fragments, the exact reference first, then each
// method's image over its error map, the worst pixel ringed there and its history a click away.
std::string family_grid(const ReportInput& in, const std::string& family, Format f) {
  const ReportScene* pick = nullptr;
  for (const ReportScene& s : in.scenes)
    if (s.family == family && (!pick || s.fragments > pick->fragments)) pick = &s;
  if (!pick) return "";
  const int w = std::min(in.width, 240);
  const bool md = f == Format::kMarkdown;
  std::string out = para(f, fmt::format("{} (the family's scene with the most fragments): each "
                                        "method's image above its error map.",
                                        md ? code(f, pick->name) : link(f, pick->name, "#" + path_name(pick->name))));
  if (md) {
    Table t{{"method", "image", "error map", "mean ΔE", "worst"}, {}};
    for (const LabRow& r : in.rows)
      if (r.scene == pick->name)
        t.rows.push_back({text(f, r.method), image(f, image_path(r.scene, r.method), r.method, w),
                          r.method == kReferenceMethod ? "" : image(f, error_image_path(r.scene, r.method), r.method + " error", w),
                          fmt::format("{:.2f}", r.fair_error().delta_e_mean), worst_link(f, r)});
    return out + table(f, t);
  }
  out += "<div class=\"grid\">\n";
  // The reference first: what every map compares with (the supersampled one for the AA methods).
  for (const LabRow& r : in.rows)
    if (r.scene == pick->name && r.method == kReferenceMethod)
      out += "<figure>" + image(f, image_path(r.scene, r.method), "reference", w) + "<br>" +
             image(f, reference_ss_path(r.scene), "supersampled reference", w) +
             "<figcaption><b>reference</b><br>exact; below it supersampled</figcaption></figure>\n";
  for (const LabRow& r : in.rows) {
    if (r.scene != pick->name || r.method == kReferenceMethod) continue;
    out += "<figure>" + image(f, image_path(r.scene, r.method), r.method, w) + "<br>" +
           image(f, error_image_path(r.scene, r.method), r.method + " error", w) +
           fmt::format("<figcaption><b>{}</b><br>mean &Delta;E {:.2f} against {}<br>{}</figcaption></figure>\n",
                       html_escape(r.method), r.fair_error().delta_e_mean, to_string(r.fair),
                       r.worst ? worst_link(f, r) : "nothing wrong to ring");
  }
  return out + "</div>\n";
}

// Headings pushed `levels` deeper, so that a document can sit inside a section of another;
// fenced code blocks are left alone (their '#' lines are comments).
std::string demote_headings(const std::string& markdown, int levels) {
  std::string out;
  bool fenced = false;
  std::stringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (!fenced && !line.empty() && line[0] == '#') line = std::string(size_t(levels), '#') + line;
    out += line + "\n";
  }
  return out;
}

std::string body(const ReportInput& in, Format f) {
  const bool md = f == Format::kMarkdown;
  const std::string de = md ? "ΔE2000" : "&Delta;E2000";
  std::string out = heading(f, 1, "zblend methods lab");
  size_t methods = 0;
  for (const LabRow& r : in.rows) methods += r.scene == in.rows.front().scene;
  out += para(f, fmt::format(
      "{} methods on {} scenes at {}x{}. Error: CIEDE2000 ({}) per pixel, averaged over the "
      "frame, against each method's fair reference: the exact per-pixel sort at pixel centres "
      "({}), or for anti-aliased methods the same at {}x{} samples per pixel, box-filtered "
      "({}). Cost: {}; bytes count colour reads and writes at 4 bytes each and depth reads and "
      "writes at the depth width in whole bytes (3 at 24 bits). Every number: {} and {}; definitions: docs/lab.md.",
      methods, in.scenes.size(), in.width, in.height, de, code(f, "exact"), in.supersample,
      in.supersample, code(f, "supersampled"),
      in.rtl ? "the RTL's clock cycles (Verilated zb_rop): streaming fragments plus loading and "
               "storing tiles"
             : "fragments through the datapath (run without the RTL)",
      link(f, "lab.csv", "lab.csv"), link(f, "lab_summary.csv", "lab_summary.csv")));

  out += heading(f, 2, "Error against cost, every family", "main");
  for (const std::string& c : {main_chart_path(), main_bytes_chart_path()})
    if (has(in.charts, c)) out += para(f, image(f, c, "error against cost", 900));
  out += para(f, fmt::format(
      "Means over the scene families, each family counted once (its own mean over its "
      "scenes), so that densely sampled families do not outweigh the rest. Pareto: no other "
      "method is both cheaper and closer to the "
      "reference (by {} or by bytes). The reference itself has no cost and is not listed.",
      in.rtl ? "RTL cycles" : "fragments"));
  out += table(f, summary_table(in, kAllFamilies, f));

  if (!in.line_summaries.empty()) {
    out += heading(f, 2, "Hidden-line methods against the exact line reference", "hidden-line");
    if (has(in.charts, hidden_line_chart_path()))
      out += para(f, image(f, hidden_line_chart_path(), "hidden-line error shares", 900));
    out += para(f, "Every tessellation edge's pixels, by the line rule the methods draw with, "
                   "decided visible or hidden against the exact depth of the faces not adjacent "
                   "to the edge (docs/lab.md, \"Hidden-line error\"). Hidden drawn: hidden edge "
                   "pixels drawn in the visible style; visible missing: visible ones not drawn "
                   "in it (for hidden-line-dim, drawn dimmed); both as shares of the reference's "
                   "edge pixels. These methods are left out of the charts above: a wireframe's "
                   "error against a shaded image measures nothing.");
    out += table(f, line_table(in, f));
  }

  if (has(in.charts, tile_beat_chart_path())) {
    out += heading(f, 2, "Tile traffic against the tile port's width", "tile-beat");
    out += para(f, image(f, tile_beat_chart_path(), "tile cycles against beat width", 800));
    out += para(f, tile_share_text(in.rows, kRtlBeat) +
                       ". Tile cycles: per touched tile a setup cycle, the beats of the planes "
                       "the pass loads (a cleared plane is fast-cleared, not loaded) and of those "
                       "it stores (docs/rtl.md \"Tile port\").");
    out += para(f, stream_share_text(in.rows, kRtlBeat) +
                       ". A second tile buffer would let each tile's stream follow the last "
                       "without its fill and drain, the port loading and storing the other "
                       "buffer meanwhile (docs/rtl.md \"A second tile buffer\").");
  }

  if (has(in.charts, port_bytes_chart_path())) {
    out += heading(f, 2, "Error against the tile port's bandwidth", "port-bytes");
    out += para(f, image(f, port_bytes_chart_path(), "error against tile-port bytes per pixel", 800));
    out += para(f, "Bytes the tile port moves per pixel of the frame (loads and stores, each plane "
                   "its width), under the pass schedule (open) and the tile schedule (filled; "
                   "docs/rtl.md \"Schedules\"): the external bandwidth a method costs, where the "
                   "chart of memory traffic above counts the datapath's accesses to the resident "
                   "tile.");
    std::istringstream lines(schedule_text(in.rows, false));
    for (std::string line; std::getline(lines, line);) out += para(f, line + ".");
  }

  out += heading(f, 2, "Scene families");
  for (const std::string& family : families_of(in)) {
    out += heading(f, 3, family, "family-" + family);
    std::string names;
    for (const ReportScene& s : in.scenes)
      if (s.family == family) names += (names.empty() ? "" : ", ") + link(f, s.name, "#" + path_name(s.name));
    if (md) {
      names.clear();
      for (const ReportScene& s : in.scenes)
        if (s.family == family) names += (names.empty() ? "" : ", ") + code(f, s.name);
    }
    out += para(f, "Scenes: " + names + ".");
    const std::string chart = family_chart_path(family);
    if (has(in.charts, chart)) out += para(f, image(f, chart, family, 640));
    out += table(f, summary_table(in, family, f));
    out += family_grid(in, family, f);
  }

  out += heading(f, 2, "Scenes");
  out += para(f, fmt::format(
      "Error maps show each pixel's {} against the method's fair reference (the column {}) on "
      "a perceptually uniform ramp from black (exact) through violet, red and orange to pale "
      "yellow at the scene's scale, printed under each map and the same for every method of "
      "the scene: the largest 99th percentile of their errors, rounded up to 1, 2 or 5 x 10^k. "
      "A cyan ring marks each method's worst pixel, whose history (every fragment that reached "
      "it, pass by pass: docs/history.md) the column {} links. Hidden-line methods: hidden "
      "edges drawn in red, visible ones missing in blue.", de, code(f, "vs"), code(f, "worst")));
  for (const ReportScene& sc : in.scenes) {
    out += heading(f, 3, sc.name, path_name(sc.name));
    out += para(f, text(f, fmt::format("{} (family {}; {} triangles, {} fragments).",
                                       sc.description, sc.family, sc.triangles, sc.fragments)));
    out += para(f, "Supersampled reference: " +
                       image(f, reference_ss_path(sc.name), "supersampled reference",
                             std::min(in.width, 320)));
    out += table(f, scene_table(in, sc, f));
  }

  out += heading(f, 2, "Sweeps", "sweeps");
  if (in.sweeps_markdown.empty() && in.sweep_images.empty()) {
    out += para(f, "No sweeps in sweeps/ (run " + code(f, "zblend sweep all --out-dir DIR/sweeps") +
                       " before the lab, as " + code(f, "make lab") + " does).");
  } else if (md) {
    out += "[sweeps/sweeps.md](sweeps/sweeps.md), as written by `zblend sweep all`:\n\n";
    out += demote_headings(rebase_markdown_links(in.sweeps_markdown, "sweeps"), 2) + "\n";
  } else {
    if (!in.sweeps_markdown.empty()) out += para(f, link(f, "sweeps/sweeps.md", "sweeps/sweeps.md"));
    for (const std::string& img : in.sweep_images)
      out += "<figure>" + image(f, img, img, 800) + "<figcaption>" + html_escape(img) +
             "</figcaption></figure>\n";
  }
  return out;
}

}  // namespace

std::string path_name(const std::string& name) {
  std::string out;
  for (char c : name)
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  return out.empty() || out == "." || out == ".." ? "_" + out : out;
}

std::string image_path(const std::string& scene, const std::string& method) {
  return "images/" + path_name(scene) + "/" + path_name(method) + ".png";
}

std::string error_image_path(const std::string& scene, const std::string& method) {
  return "images/" + path_name(scene) + "/" + path_name(method) + "-error.png";
}

std::string history_path(const std::string& scene, const std::string& method) {
  return "images/" + path_name(scene) + "/" + path_name(method) + "-worst.txt";
}

std::string reference_ss_path(const std::string& scene) {
  return "images/" + path_name(scene) + "/reference-supersampled.png";
}

std::string main_chart_path() { return "charts/main.png"; }
std::string main_bytes_chart_path() { return "charts/main-bytes.png"; }
std::string tile_beat_chart_path() { return "charts/tile-beat.png"; }
std::string port_bytes_chart_path() { return "charts/main-port-bytes.png"; }
std::string hidden_line_chart_path() { return "charts/hidden-line.png"; }
std::string family_chart_path(const std::string& family) {
  return "charts/family-" + path_name(family) + ".png";
}

namespace {

// True when a link target starting at `t` is absolute: a URL scheme, a path from the root, an
// anchor.
bool absolute_target(const std::string& s, size_t t) {
  if (t >= s.size()) return false;
  if (s[t] == '/' || s[t] == '#') return true;
  if (!std::isalpha(static_cast<unsigned char>(s[t]))) return false;
  size_t i = t + 1;
  while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '+' ||
                          s[i] == '.' || s[i] == '-'))
    ++i;
  return i < s.size() && s[i] == ':';
}

}  // namespace

std::string rebase_markdown_links(const std::string& markdown, const std::string& dir) {
  // Every "](" opens a link or image target.
  std::string out;
  size_t from = 0;
  for (size_t at; (at = markdown.find("](", from)) != std::string::npos; from = at + 2) {
    out.append(markdown, from, at + 2 - from);
    if (!absolute_target(markdown, at + 2)) out += dir + "/";
  }
  out.append(markdown, from, std::string::npos);
  return out;
}

std::string report_markdown(const ReportInput& in) { return body(in, Format::kMarkdown); }

std::string report_html(const ReportInput& in) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<title>zblend methods lab</title>\n<style>\n"
         "body { font-family: sans-serif; margin: 2em; max-width: 1500px; }\n"
         "table { border-collapse: collapse; margin: 1em 0; }\n"
         "th, td { border: 1px solid #ccc; padding: 3px 6px; text-align: right; }\n"
         "td:first-child, th:first-child { text-align: left; }\n"
         "img { image-rendering: pixelated; }\n"
         "figure { display: inline-block; margin: 0.5em; }\n"
         ".grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(250px, 1fr)); "
         "gap: 0.5em; }\n"
         ".grid figure { margin: 0; }\n"
         "</style>\n</head>\n<body>\n" +
         body(in, Format::kHtml) + "</body>\n</html>\n";
}

}  // namespace zb::lab
