// The methods lab: Pareto front, cost in bytes, summaries, the CSV of a tiny run, the report's
// links.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "lab.h"
#include "metrics/error_map.h"
#include "metrics/metrics.h"
#include "rtl_params.h"
#include "report.h"
#include "scene/builtin_scenes.h"

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, sep);) out.push_back(item);
  return out;
}

TEST(ParetoFront, HandMadePoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  //                            0   1  2  3  4  5  6    7   8
  const std::vector<double> x = {1, 2, 3, 4, 4, 5, 1, nan, 10};
  const std::vector<double> y = {10, 5, 7, 1, 1, 1, 12, 0, 0.5};
  // 2 loses to 1 on both; 5 costs more than 3 for the same error; 6 errs more than 0 for the
  // same cost; 7 has no cost; 3 and 4 tie, so neither beats the other.
  EXPECT_EQ(zb::lab::pareto_front(x, y), (std::vector<size_t>{0, 1, 3, 4, 8}));
  EXPECT_TRUE(zb::lab::pareto_front({}, {}).empty());
  EXPECT_EQ(zb::lab::pareto_front({3}, {3}), (std::vector<size_t>{0}));
}

TEST(LabCost, BytesByAccessWidth) {
  zb::PassStats s;
  s.color_reads = 10;
  s.color_writes = 7;
  s.depth_reads = 5;
  s.depth_writes = 3;
  const zb::RopState alpha;  // any mode but accumulate: 4 bytes a colour access
  auto traffic = [&](int depth_bits, const zb::RopState& st, zb::WboitFormat f = {}) {
    return zb::pass_traffic(s, st, zb::Viewport{8, 8, depth_bits, 16, f});
  };
  EXPECT_EQ(traffic(24, alpha).read, 10u * 4 + 5u * 3);
  EXPECT_EQ(traffic(24, alpha).written, 7u * 4 + 3u * 3);
  EXPECT_EQ(traffic(16, alpha).read, 10u * 4 + 5u * 2);
  EXPECT_EQ(traffic(17, alpha).read, 10u * 4 + 5u * 3);  // rounded up to whole bytes
  EXPECT_EQ(traffic(32, alpha).written, 7u * 4 + 3u * 4);
  // Accumulate: the accumulation word, 4 x 16 + 8 = 72 bits, 9 bytes; 4 x 12 + 10, 8 bytes.
  zb::RopState acc;
  acc.blend = zb::BlendMode::kAccumulate;
  EXPECT_EQ(traffic(24, acc).read, 10u * 9 + 5u * 3);
  EXPECT_EQ(traffic(24, acc, {12, 10, 8}).written, 7u * 8 + 3u * 3);
}

TEST(LabFairReference, AntiAliasedMethodsAgainstTheSupersampledOne) {
  using zb::lab::FairReference;
  EXPECT_EQ(zb::lab::fair_reference("coverage-aa"), FairReference::kSupersampled);
  for (const char* m : {"opaque", "three-pass", "depth-peel-8", "reference"})
    EXPECT_EQ(zb::lab::fair_reference(m), FairReference::kExact) << m;
  // The wireframes against the exact line reference.
  for (const char* m : {"hidden-line", "hidden-line-dim"})
    EXPECT_EQ(zb::lab::fair_reference(m), FairReference::kLines) << m;
}

zb::lab::LabRow row(const std::string& scene, const std::string& family, const std::string& method,
                    double delta_e, uint64_t fragments, uint64_t cycles, uint64_t bytes) {
  zb::lab::LabRow r;
  r.scene = scene;
  r.family = family;
  r.method = method;
  r.has_cost = true;
  r.golden.fragments_in = fragments;
  r.bytes_read = bytes;
  r.rtl_cycles = cycles;
  r.error.delta_e_mean = delta_e;
  r.error_ss.delta_e_mean = delta_e + 100;  // never used: every method here is judged exact
  return r;
}

TEST(LabSummary, MeansPerFamilyAndOverAll) {
  std::vector<zb::lab::LabRow> rows = {
      row("a1", "A", "cheap", 4.0, 100, 110, 1000),
      row("a1", "A", "dear", 1.0, 300, 330, 500),
      row("a2", "A", "cheap", 6.0, 200, 210, 3000),
      row("a2", "A", "dear", 3.0, 500, 530, 1500),
      row("b1", "B", "cheap", 0.5, 50, 60, 100),
      row("b1", "B", "dear", 0.5, 80, 90, 100),
  };
  zb::lab::LabRow ref;
  ref.scene = "a1";
  ref.family = "A";
  ref.method = "reference";
  rows.push_back(ref);

  const std::vector<zb::lab::MethodSummary> s = zb::lab::summarize(rows);
  ASSERT_EQ(s.size(), 6u);  // A, B, all: cheap and dear each; no reference
  EXPECT_EQ(s[0].family, "A");
  EXPECT_EQ(s[0].method, "cheap");
  EXPECT_EQ(s[0].scenes, 2u);
  EXPECT_DOUBLE_EQ(s[0].delta_e_mean, 5.0);       // (4 + 6) / 2
  EXPECT_DOUBLE_EQ(s[0].fragments, 150.0);        // (100 + 200) / 2
  EXPECT_DOUBLE_EQ(s[0].cost(), 160.0);           // RTL cycles (110 + 210) / 2
  EXPECT_DOUBLE_EQ(s[0].bytes, 2000.0);
  EXPECT_DOUBLE_EQ(s[1].delta_e_mean, 2.0);       // dear in A: (1 + 3) / 2
  // In A each is best at something by cycles; by bytes dear is cheaper and better.
  EXPECT_TRUE(s[0].pareto_cost);
  EXPECT_TRUE(s[1].pareto_cost);
  EXPECT_FALSE(s[0].pareto_bytes);
  EXPECT_TRUE(s[1].pareto_bytes);
  // In B the errors tie, so the dearer one is dominated.
  EXPECT_EQ(s[2].family, "B");
  EXPECT_TRUE(s[2].pareto_cost);
  EXPECT_FALSE(s[3].pareto_cost);
  // Over all, each family once: cheap (5 + 0.5) / 2 = 2.75 at (160 + 60) / 2 = 110 cycles;
  // dear (2 + 0.5) / 2 = 1.25 at (430 + 90) / 2 = 260.
  EXPECT_EQ(s[4].family, zb::lab::kAllFamilies);
  EXPECT_EQ(s[4].scenes, 3u);
  EXPECT_DOUBLE_EQ(s[4].delta_e_mean, 2.75);
  EXPECT_DOUBLE_EQ(s[4].cost(), 110.0);
  EXPECT_DOUBLE_EQ(s[5].delta_e_mean, 1.25);
  EXPECT_DOUBLE_EQ(s[5].cost(), 260.0);
  EXPECT_TRUE(s[4].pareto_cost);
  EXPECT_TRUE(s[5].pareto_cost);

  // Without RTL cycles on every row the cost falls back to fragments.
  rows[0].rtl_cycles.reset();
  EXPECT_DOUBLE_EQ(zb::lab::summarize(rows)[0].cost(), 150.0);
}

// The tiny run: two methods on quads at 32x24, golden model and RTL.
// The streaming summary by hand: two runs of 100 fragments, 101 and 104 streaming cycles as the
// RTL runs them (200 and 130 in all), 100 and 102 with a second buffer's pipeline, 150 and 140
// in all with two buffers at 8 pixels a beat; the reference row is left out.
TEST(LabSummary, StreamShareByHand) {
  std::vector<zb::lab::LabRow> rows(3);
  rows[0].scene = "a";
  rows[0].method = "m1";
  rows[1].scene = "b";
  rows[1].method = "m2";
  for (int k = 0; k < 2; ++k) {
    rows[size_t(k)].has_cost = true;
    rows[size_t(k)].golden.fragments_in = 100;
  }
  rows[0].rtl_cycles = 200;
  rows[0].rtl_stream_cycles = 101;
  rows[1].model_stream_cycles = 104;  // no RTL run: the cost model's
  const size_t at8 = size_t(std::find(zb::lab::kLabBeats.begin(), zb::lab::kLabBeats.end(), 8) -
                            zb::lab::kLabBeats.begin());
  rows[1].model_tile_cycles[at8] = 26;
  rows[0].model_pipe_2buf = 100;
  rows[1].model_pipe_2buf = 102;
  rows[0].model_cycles_2buf[at8] = 150;
  rows[1].model_cycles_2buf[at8] = 140;
  rows[2].scene = "c";  // the reference: no cost
  const std::string text = zb::lab::stream_share_text(rows, 8);
  EXPECT_NE(text.find("fragment: 1.0250 overall, worst 1.040 (b m2), 1 of 2 runs above 1.01"),
            std::string::npos) << text;
  EXPECT_NE(text.find("once a pass): 1.0100 overall, worst 1.020 (b m2), 1 of 2 runs above"),
            std::string::npos) << text;
  EXPECT_NE(text.find("8 pixels a beat: 1.6500 with one buffer, 1.4500 with two (worst run "
                      "1.500, a m1)"),
            std::string::npos) << text;
  // A beat the model does not run: no whole-frame figures.
  EXPECT_EQ(zb::lab::stream_share_text(rows, 1).find("All cycles"), std::string::npos);
}

// The tile schedule's lines by hand: two runs of 100 fragments, 110 and 130 cycles with two
// buffers (1.2000 a fragment), with copies renamed 105 and 115 (1.1000) at 3 generation bits,
// 5 more each at 2 (1.1500), at 1 as the 110 and 130 with two buffers and 10 more with one
// (1.2000), copied by reads 10 more again with two (1.3000), 20 more with one (1.4000); 20 host
// pixels (0.1 a fragment more).
TEST(LabSummary, TwoBuffersByHand) {
  std::vector<zb::lab::LabRow> rows(2);
  const uint64_t two[2] = {110, 130}, renamed[2] = {105, 115};
  for (size_t k = 0; k < 2; ++k) {
    rows[k].scene = k ? "b" : "a";
    rows[k].method = "m";
    rows[k].has_cost = true;
    rows[k].golden.fragments_in = 100;
    rows[k].model_stream_cycles = 100;
    rows[k].model_cycles_2buf_resident = two[k];
    rows[k].model_cycles_variant = {two[k] + 20, renamed[k] + 10, renamed[k] + 5, renamed[k]};
    rows[k].model_cycles_2buf_variant = {two[k] + 10, two[k], renamed[k] + 5, renamed[k]};
    rows[k].host_op_pixels_tile = 10;
  }
  const std::string text = zb::lab::schedule_text(rows, false);
  EXPECT_NE(text.find("schedule tile with two tile buffers (cost model of the proposed design): "
                      "all cycles per fragment 1.2000, 1.3000 with the host's frame operations\n"),
            std::string::npos) << text;
  EXPECT_NE(text.find("schedule tile with copies of depth to peel by reads / renamed with the "
                      "depth banks' generations of 1 / 2 (zb_rop) / 3 bits (cost model): all "
                      "cycles per fragment with one tile buffer 1.4000 / 1.2000 / 1.1500 / 1.1000, "
                      "with two 1.3000 / 1.2000 / 1.1500 / 1.1000; with the host's frame "
                      "operations 1.5000 / 1.3000 / 1.2500 / 1.2000 and 1.4000 / 1.3000 / 1.2500 "
                      "/ 1.2000\n"),
            std::string::npos) << text;
}

TEST(LabRun, TinyCaseCsv) {
  zb::lab::LabScene scene{"quads", "built-in", "three quads",
                          [] { return *zb::builtin_scene("quads"); }};
  zb::lab::LabOptions o;
  o.viewport = zb::Viewport{32, 24};
  o.methods = {"unsorted", "reference"};
  o.rtl = true;
  const zb::lab::SceneRun run = zb::lab::run_scene(scene, o);
  ASSERT_EQ(run.rows.size(), 2u);
  ASSERT_EQ(run.images.size(), 2u);
  ASSERT_EQ(run.error_images.size(), 2u);
  EXPECT_EQ(run.images[0].width, 32);
  EXPECT_EQ(run.reference_ss.height, 24);

  const std::vector<std::string> lines = split(zb::lab::lab_csv(run.rows), '\n');
  ASSERT_EQ(lines.size(), 3u);  // header and a row per method
  const std::vector<std::string> head = split(lines[0], ',');
  for (const char* col : {"scene", "family", "method", "passes", "fragments", "bytes_read",
                          "bytes_written", "host_ms", "rtl_cycles", "rmse", "psnr_db", "max_abs",
                          "share_over_2", "share_over_16", "delta_e_mean", "delta_e_max",
                          "ss_rmse", "ss_delta_e_mean", "fair_reference", "fair_delta_e_mean"})
    EXPECT_NE(std::find(head.begin(), head.end(), col), head.end()) << col;
  auto cell = [&](int line, const std::string& col) {
    const std::vector<std::string> cells = split(lines[size_t(line)] + ",", ',');
    const size_t i = size_t(std::find(head.begin(), head.end(), col) - head.begin());
    return i < cells.size() ? cells[i] : std::string("?");
  };
  EXPECT_EQ(cell(1, "method"), "unsorted");
  EXPECT_EQ(cell(1, "passes"), "2");
  EXPECT_NE(cell(1, "rtl_cycles"), "");
  // The total is its two parts, both there.
  EXPECT_NE(cell(1, "rtl_tile_cycles"), "0");
  EXPECT_EQ(std::stoull(cell(1, "rtl_cycles")),
            std::stoull(cell(1, "rtl_stream_cycles")) + std::stoull(cell(1, "rtl_tile_cycles")));
  EXPECT_EQ(cell(1, "rtl_mismatch_pixels"), "0");
  EXPECT_GT(std::stod(cell(1, "rmse")), 0.0);  // unsorted gets the left half wrong
  // One tile a pass: a second buffer has no tile to overlap, so its cycles are the RTL's.
  if (zb::kRtlTileW >= 32 && zb::kRtlTileH >= 24) {
    const std::string beat = std::to_string(zb::kRtlBeat);
    if (cell(1, "cycles_2buf_beat" + beat) != "?") {
      EXPECT_EQ(cell(1, "cycles_2buf_beat" + beat), cell(1, "rtl_cycles"));
      EXPECT_EQ(cell(1, "stream_cycles_2buf_beat" + beat), cell(1, "rtl_stream_cycles"));
    }
  }

  EXPECT_EQ(cell(2, "method"), "reference");
  EXPECT_EQ(cell(2, "passes"), "");
  EXPECT_EQ(std::stod(cell(2, "rmse")), 0.0);
  EXPECT_EQ(cell(2, "psnr_db"), "inf");
  EXPECT_EQ(cell(2, "max_abs"), "0");
  EXPECT_EQ(std::stod(cell(2, "delta_e_mean")), 0.0);
  EXPECT_EQ(std::stod(cell(2, "share_over_2")), 0.0);
}

// The hidden-line methods on parts, golden model only: their rows carry the line reference's
// shares, stay out of the shaded summaries, and have their own.
TEST(LabRun, HiddenLineAgainstTheLineReference) {
  zb::lab::LabScene scene{"parts", "built-in", "parts", [] { return *zb::builtin_scene("parts"); }};
  zb::lab::LabOptions o;
  o.viewport = zb::Viewport{160, 120};
  o.methods = {"opaque", "hidden-line", "hidden-line-dim"};
  o.rtl = false;
  const zb::lab::SceneRun run = zb::lab::run_scene(scene, o);
  ASSERT_EQ(run.rows.size(), 3u);
  EXPECT_FALSE(run.rows[0].lines.has_value());
  for (const size_t i : {size_t{1}, size_t{2}}) {
    const zb::lab::LabRow& r = run.rows[i];
    ASSERT_TRUE(r.lines.has_value()) << r.method;
    EXPECT_EQ(r.fair, zb::lab::FairReference::kLines);
    EXPECT_GT(r.lines->edge_pixels, 500u);
    EXPECT_GT(r.lines->visible_pixels, r.lines->edge_pixels / 4);
    EXPECT_LT(r.lines->visible_pixels, r.lines->edge_pixels);
    // Small against the wireframe's own reference, where the shaded one gives tens of units.
    EXPECT_LT(r.lines->hidden_drawn_share() + r.lines->visible_missing_share(), 0.05);
    EXPECT_LT(r.fair_error().delta_e_mean, r.error.delta_e_mean);
  }
  // hidden-line-dim draws every edge pixel one way or the other, visible ones last: the
  // same pixels are in the visible style.
  EXPECT_EQ(run.rows[1].lines->hidden_drawn, run.rows[2].lines->hidden_drawn);
  EXPECT_EQ(run.rows[1].lines->visible_missing, run.rows[2].lines->visible_missing);

  const std::vector<zb::lab::MethodSummary> s = zb::lab::summarize(run.rows);
  for (const auto& m : s) EXPECT_EQ(m.method, "opaque");
  const std::vector<zb::lab::LineSummary> ls = zb::lab::line_summary(run.rows);
  ASSERT_EQ(ls.size(), 4u);  // two scene rows, two means
  EXPECT_EQ(ls[2].scene, zb::lab::kAllFamilies);
  EXPECT_EQ(ls[2].method, "hidden-line");
  EXPECT_DOUBLE_EQ(ls[2].hidden_drawn, run.rows[1].lines->hidden_drawn_share());
  const std::vector<std::string> csv = split(zb::lab::line_summary_csv(ls), '\n');
  EXPECT_EQ(csv.size(), 5u);
  const std::vector<std::string> lab = split(zb::lab::lab_csv(run.rows), '\n');
  EXPECT_NE(lab[0].find("hidden_drawn_share,visible_missing_share"), std::string::npos);
  EXPECT_NE(lab[2].find(",lines,"), std::string::npos);
}

// The error maps: one scale for the scene's methods, the worst pixel ringed where the error is
// largest, its history (which replays: record_history checks it) kept for the report.
TEST(LabRun, ErrorMapsWorstPixelsAndTheirHistories) {
  zb::lab::LabScene scene{"cad", "shells", "cad", [] { return *zb::builtin_scene("cad"); }};
  zb::lab::LabOptions o;
  o.viewport = zb::Viewport{64, 48};
  o.methods = {"unsorted", "depth-peel-4", "hidden-line", "reference"};
  o.rtl = false;
  const zb::lab::SceneRun run = zb::lab::run_scene(scene, o);
  ASSERT_EQ(run.histories.size(), 4u);
  const double scale = run.rows[0].error_scale;
  EXPECT_GE(scale, zb::kMinErrorScale);
  for (const zb::lab::LabRow& r : run.rows) EXPECT_EQ(r.error_scale, scale) << r.method;
  // unsorted is wrong somewhere: its worst pixel is where its map is largest.
  const zb::lab::LabRow& u = run.rows[0];
  ASSERT_TRUE(u.worst.has_value());
  const std::vector<float> de = zb::delta_e_map(run.images[0], run.reference);
  const auto [x, y] = *u.worst;
  EXPECT_EQ(de[size_t(y) * 64 + size_t(x)], *std::max_element(de.begin(), de.end()));
  EXPECT_NEAR(de[size_t(y) * 64 + size_t(x)], u.error.delta_e_max, 1e-3);
  const std::string at = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  EXPECT_NE(run.histories[0].find(at), std::string::npos) << run.histories[0];
  EXPECT_NE(run.histories[0].find("cad, unsorted: the worst pixel"), std::string::npos);
  // The map: the frame above a legend, the worst pixel's colour the ramp's at its error.
  const zb::Framebuffer& map = run.error_images[0];
  EXPECT_EQ(map.width, zb::kLegendWidth);
  EXPECT_EQ(map.color_at(x, y), zb::error_ramp(de[size_t(y) * 64 + size_t(x)] / scale));
  // The reference has no history; a hidden-line method's map has the two colours' legend.
  EXPECT_TRUE(run.histories[3].empty());
  EXPECT_FALSE(run.rows[3].worst.has_value());
  size_t swatch = 0;
  for (const zb::Rgba8 c : run.error_images[2].color) swatch += c == zb::kHiddenDrawnColor;
  EXPECT_GT(swatch, 50u);
}

TEST(LabReport, RelativeLinks) {
  EXPECT_EQ(zb::lab::rebase_markdown_links("![a](x.png) [b](sub/y.csv)", "sweeps"),
            "![a](sweeps/x.png) [b](sweeps/sub/y.csv)");
  EXPECT_EQ(zb::lab::rebase_markdown_links("[w](https://e.org/p) [r](/abs) [h](#top)", "sweeps"),
            "[w](https://e.org/p) [r](/abs) [h](#top)");
  EXPECT_EQ(zb::lab::path_name("a b/c"), "a_b_c");
  EXPECT_EQ(zb::lab::path_name(".."), "_..");
  EXPECT_EQ(zb::lab::image_path("cad", "three-pass"), "images/cad/three-pass.png");
  EXPECT_EQ(zb::lab::error_image_path("cad", "three-pass"), "images/cad/three-pass-error.png");
  EXPECT_EQ(zb::lab::history_path("cad", "three-pass"), "images/cad/three-pass-worst.txt");
}

TEST(LabReport, ShowsEveryMethodsImageAndErrorImage) {
  zb::lab::ReportInput in;
  in.width = 32;
  in.height = 24;
  in.supersample = 4;
  in.scenes = {{"s1", "fam", "a scene | with a pipe", 2, 10}};
  in.rows = {row("s1", "fam", "m1", 1.0, 10, 12, 40), row("s1", "fam", "m2", 2.0, 20, 22, 80)};
  in.summaries = zb::lab::summarize(in.rows);
  in.charts = {zb::lab::main_chart_path(), zb::lab::family_chart_path("fam")};
  in.sweeps_markdown = "# Sweeps\n\n![orbit](orbit.png)\n";
  in.rows[1].worst = std::pair<int, int>{3, 4};
  for (const std::string& doc : {zb::lab::report_markdown(in), zb::lab::report_html(in)}) {
    // m2's worst pixel links its history, in the scene's table and the family's grid.
    size_t links = 0;
    for (size_t at = 0; (at = doc.find("images/s1/m2-worst.txt", at)) != std::string::npos; ++at) ++links;
    EXPECT_GE(links, 2u);
    EXPECT_NE(doc.find("worst pixel (3, 4)"), std::string::npos);
    EXPECT_EQ(doc.find("images/s1/m1-worst.txt"), std::string::npos);  // m1 rings nothing
    for (const char* path : {"images/s1/m1.png", "images/s1/m1-error.png", "images/s1/m2.png",
                             "images/s1/m2-error.png", "charts/main.png", "charts/family-fam.png",
                             "images/s1/reference-supersampled.png"})
      EXPECT_NE(doc.find(path), std::string::npos) << path;
    EXPECT_EQ(doc.find("charts/main-bytes.png"), std::string::npos);  // not in in.charts
    EXPECT_EQ(doc.find("/work"), std::string::npos);                  // nothing absolute
  }
  EXPECT_NE(zb::lab::report_markdown(in).find("![orbit](sweeps/orbit.png)"), std::string::npos);
  EXPECT_NE(zb::lab::report_markdown(in).find("\n### Sweeps\n"), std::string::npos);  // nested
  EXPECT_NE(zb::lab::report_markdown(in).find("a scene \\| with a pipe"), std::string::npos);
}

}  // namespace
