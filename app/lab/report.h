// The lab's report: charts, images and error images side by side (docs/lab.md). Every link is
// relative to the lab's output folder, so the report still works when the folder moves.
#pragma once

#include <string>
#include <vector>

#include "lab.h"

namespace zb::lab {

struct ReportScene {
  std::string name;
  std::string family;
  std::string description;
  size_t triangles = 0;
  size_t fragments = 0;
};

struct ReportInput {
  int width = 0;
  int height = 0;
  int supersample = 0;
  bool rtl = false;
  std::vector<ReportScene> scenes;        // in report order
  std::vector<LabRow> rows;               // every scene's rows
  std::vector<MethodSummary> summaries;   // summarize(rows)
  std::vector<LineSummary> line_summaries;  // line_summary(rows)
  std::vector<std::string> charts;        // relative paths of the charts that exist
  std::string sweeps_markdown;            // sweeps/sweeps.md, or empty
  std::vector<std::string> sweep_images;  // relative paths under sweeps/
};

// A name made safe as one path component: letters, digits, '-', '_' and '.' kept, the rest '_'.
std::string path_name(const std::string& name);

// Where the lab writes a scene's images, relative to its output folder.
std::string image_path(const std::string& scene, const std::string& method);
std::string error_image_path(const std::string& scene, const std::string& method);
std::string reference_ss_path(const std::string& scene);
// The history of the pixel a method's error map rings (zblend pixel's text).
std::string history_path(const std::string& scene, const std::string& method);

// The charts scripts/lab_charts.py writes, relative to the output folder.
std::string main_chart_path();        // delta E against cost, every scene
std::string main_bytes_chart_path();  // delta E against bytes, every scene
std::string tile_beat_chart_path();   // tile cycles against the tile port's width
std::string port_bytes_chart_path();  // error against tile-port bytes per pixel, per schedule
std::string hidden_line_chart_path(); // the hidden-line methods against the line reference
std::string family_chart_path(const std::string& family);

// Markdown links and images whose target is a relative path get `dir` put in front, so that
// text written for dir/ reads right from its parent.
std::string rebase_markdown_links(const std::string& markdown, const std::string& dir);

std::string report_markdown(const ReportInput& in);
std::string report_html(const ReportInput& in);

}  // namespace zb::lab
