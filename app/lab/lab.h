// The methods lab: every method on every scene of a suite, cost against error (docs/lab.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rop/backend.h"
#include "rtl_params.h"
#include "rop/framebuffer.h"
#include "geometry/geometry.h"
#include "metrics/line_metrics.h"
#include "metrics/metrics.h"
#include "scene/scene.h"

namespace zb::lab {

// A scene of the lab: its name in the CSV and the report, its family (one chart each), a line
// on what it tests, and how to build it (scene files load only when their turn comes).
struct LabScene {
  std::string name;
  std::string family;
  std::string description;
  std::function<Scene()> load;
};

struct LabOptions {
  Viewport viewport{320, 240};
  std::vector<std::string> methods;  // pass plans and "reference", in column order
  bool rtl = true;                   // also run each plan on the Verilated RTL (cycles)
  int supersample = 4;               // factor of the supersampled reference per axis
};

// The reference a method's error is judged against in the charts: anti-aliased methods (a
// plan with a coverage pass) against the supersampled one, the hidden-line methods (a plan
// that draws edges) against the exact line reference (reference/line_reference.h), every
// other against the exact one.
enum class FairReference { kExact, kSupersampled, kLines };
const char* to_string(FairReference r);
FairReference fair_reference(const std::string& method);

// Tile port widths (pixels a beat) the lab's cost model prices every method at, zb_rop's BEAT
// among them: the width's effect on tile cycles (charts/tile-beat.png).
inline constexpr std::array<int, 5> kLabBeats{2, 4, 8, 16, 32};
// The index of `beat` in kLabBeats, or kLabBeats.size() when it is not one of them.
constexpr size_t lab_beat_index(int beat) {
  size_t k = 0;
  while (k < kLabBeats.size() && kLabBeats[k] != beat) ++k;
  return k;
}
static_assert(lab_beat_index(kRtlBeat) < kLabBeats.size(), "zb_rop's BEAT is among the lab's");

// One method on one scene.
struct LabRow {
  std::string scene;
  std::string family;
  std::string method;
  bool has_cost = false;          // false for the reference, which is not a datapath method
  size_t passes = 0;
  PassStats golden;               // the golden model's counters, summed over passes
  uint64_t bytes_read = 0;
  uint64_t bytes_written = 0;
  double host_ms = 0;             // golden model's render, best of 3 (reference: its composite)
  std::optional<uint64_t> rtl_cycles;  // the RTL's cycles: streaming plus tile load and store
  uint64_t rtl_stream_cycles = 0;      // of which streaming fragments (first offer to drain)
  uint64_t rtl_tile_cycles = 0;        // of which loading and storing tiles
  uint64_t rtl_mismatch_pixels = 0;    // pixels where the RTL's frame differs from the golden's
  // The cost model (app/lab/sizing_cost.h) at the RTL's tile: streaming cycles, and tile cycles at
  // each of kLabBeats (at zb_rop's BEAT they are the RTL's).
  uint64_t model_stream_cycles = 0;
  std::array<uint64_t, kLabBeats.size()> model_tile_cycles{};
  // The cost model with a second tile buffer (docs/rtl.md "A second tile buffer", proposed),
  // at each of kLabBeats: streaming cycles (each pass's first offer to its last drain) and all
  // cycles, the tile port's included.
  std::array<uint64_t, kLabBeats.size()> model_stream_2buf{}, model_cycles_2buf{};
  uint64_t model_pipe_2buf = 0;  // its streaming cycles with a port of no cycles (TileCost)
  // The tile schedule (docs/rtl.md "Schedules"; the fields above are the pass schedule's): the
  // cost model's tile cycles at zb_rop's BEAT, and, with the RTL, its run under that schedule:
  // tile cycles and pixels differing from the golden frame.
  uint64_t model_tile_cycles_resident = 0;
  // Its every cycle, streaming included, with two tile buffers (cost model of the proposed
  // design, ResidentTraffic::two_buffer_cycles).
  uint64_t model_cycles_2buf_resident = 0;
  // Per kBankVariants: every cycle with one buffer, with two (ResidentTraffic::variant_cycles,
  // two_buffer_variant_cycles).
  std::array<uint64_t, 4> model_cycles_variant{}, model_cycles_2buf_variant{};
  std::optional<uint64_t> rtl_resident_tile_cycles;
  uint64_t rtl_resident_mismatch_pixels = 0;
  // Tile-port bytes per frame (loads and stores, each plane its width), per schedule, and the
  // pixels the host's frame operations touch (a pixel a clock on a tile port).
  uint64_t port_bytes_pass = 0, port_bytes_tile = 0;
  uint64_t frame_op_pixels = 0;
  uint64_t host_op_pixels_tile = 0;  // of those, left on the host under the tile schedule
  uint64_t pixels = 0;           // the frame's
  ImageError error;               // against the exact reference
  ImageError error_ss;            // against the supersampled reference
  FairReference fair = FairReference::kExact;
  // kLines: the error against the line reference's picture in the method's style, and the
  // edge pixels' error shares (metrics/line_metrics.h).
  ImageError error_lines;
  std::optional<LineError> lines;
  // The error map's scale (the scene's, every method alike) and the pixel it rings: the largest
  // error, or a hidden-line method's first wrong edge pixel; none where nothing is wrong.
  double error_scale = 0;
  std::optional<std::pair<int, int>> worst;
  const ImageError& fair_error() const {
    return fair == FairReference::kExact ? error
                                         : fair == FairReference::kSupersampled ? error_ss
                                                                                : error_lines;
  }
};

// One scene's outcome: a row and an image per method, the two references, and the error
// image of each method against its fair reference.
struct SceneRun {
  std::vector<LabRow> rows;
  std::vector<Framebuffer> images;
  std::vector<Framebuffer> error_images;  // error maps (metrics/error_map.h)
  std::vector<std::string> histories;     // per method, its worst pixel's history; or empty
  Framebuffer reference;
  Framebuffer reference_ss;
  size_t triangles = 0;
  size_t fragments = 0;
  double ms = 0;                  // wall time of the whole scene
};

// Runs every method of `options` on the scene. Throws std::invalid_argument for an unknown
// method, or what the scene's loader throws.
SceneRun run_scene(const LabScene& scene, const LabOptions& options);

// lab.csv: a header line, then a line per row.
std::string lab_csv(const std::vector<LabRow>& rows);
// One line: tile cycles as a share of streaming cycles over `rows` at each of kLabBeats
// (`beat` marked as zb_rop's), and the RTL's own share when the rows have RTL cycles.
std::string tile_share_text(const std::vector<LabRow>& rows, int beat);
// Streaming cycles per fragment over the rows with a cost, as the RTL runs (its figures, or the
// cost model's, equal, without it) and with a second tile buffer (the pipeline's own): overall,
// the worst run, the runs above 1.01; and all cycles per fragment, tile port included, with one
// buffer and with two at `beat` (one of kLabBeats; otherwise left out).
std::string stream_share_text(const std::vector<LabRow>& rows, int beat);
// Per schedule (pass, tile) over the rows with a cost: all cycles per fragment (streaming and
// the tile port; then with the host's frame operations at a pixel a clock), tile-port bytes per
// pixel, and the RTL's mismatching pixels; a line each, then the tile schedule with two tile
// buffers (the cost model's), then (`per_method`) one per method (its scenes' sums).
std::string schedule_text(const std::vector<LabRow>& rows, bool per_method = true);

// The non-dominated points when both coordinates are to be minimised: indices of the points
// that no other point matches or beats in both and beats in one, in order of x, then y.
// Points with a NaN coordinate are never on the front.
std::vector<size_t> pareto_front(const std::vector<double>& x, const std::vector<double>& y);

// A method's means over the scenes of a family; for "all", the mean of its family means, so
// that each family counts once. The error is against the method's fair reference; the cost is
// the RTL's cycles when every row has them, else the golden model's fragments.
struct MethodSummary {
  std::string family;
  std::string method;
  size_t scenes = 0;               // scenes behind the means
  double delta_e_mean = 0;
  double rmse = 0;
  double share_over_16 = 0;
  double fragments = 0;
  double bytes = 0;               // read + written
  double host_ms = 0;
  std::optional<double> rtl_cycles;
  bool pareto_cost = false;       // on the front of delta_e_mean against cost()
  bool pareto_bytes = false;      // on the front of delta_e_mean against bytes
  double cost() const { return rtl_cycles ? *rtl_cycles : fragments; }
};

constexpr const char* kAllFamilies = "all";

// Per family (in order of first appearance), then "all"; methods without cost (the reference)
// and the hidden-line methods (judged against another reference, line_summary) are left out.
// Pareto flags are set within each family.
std::vector<MethodSummary> summarize(const std::vector<LabRow>& rows);

// lab_summary.csv, the input of scripts/lab_charts.py.
std::string summary_csv(const std::vector<MethodSummary>& summaries);

// A hidden-line method on one scene, or its mean over the scene families ("all"): the error
// shares against the exact line reference and the cost.
struct LineSummary {
  std::string scene;              // kAllFamilies for the mean
  std::string method;
  size_t scenes = 0;
  double edge_pixels = 0;
  double hidden_drawn = 0;        // shares of the reference's edge pixels
  double visible_missing = 0;
  std::optional<double> rtl_cycles;
  double fragments = 0;
  double cost() const { return rtl_cycles ? *rtl_cycles : fragments; }
};

// The rows with line errors, scene by scene in order, then per method the mean over the
// families of its scenes' means (each family once, as summarize's "all").
std::vector<LineSummary> line_summary(const std::vector<LabRow>& rows);

// lab_lines.csv, the input of the hidden-line chart (scripts/lab_charts.py).
std::string line_summary_csv(const std::vector<LineSummary>& summaries);

}  // namespace zb::lab
