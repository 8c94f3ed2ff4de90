// Stability sweeps: where methods fail as one parameter moves (docs/sweeps.md). Each sweep
// returns its rows; `zblend sweep` writes them as CSV, charts them and summarises them.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rop/framebuffer.h"
#include "geometry/geometry.h"
#include "metrics/line_metrics.h"
#include "metrics/metrics.h"
#include "pipeline/render.h"
#include "scene/scene.h"

namespace zb::lab {

// Called after each step of a sweep with a one-line note on it, for progress on stderr.
using SweepProgress = std::function<void(const std::string&)>;

// --- shared by the sweeps (sweeps.cpp) ---

// The image of `method` (a pass plan on the golden model, or "reference") on `rs`.
Framebuffer render_method(const RasterizedScene& rs, const std::string& method);

// `methods`, or every method when it is empty.
std::vector<std::string> methods_or_all(const std::vector<std::string>& methods);

// `scene` without its transparent objects.
Scene opaque_only(Scene scene);

// One method's error against the sweep's ground truth at one value `x` of the swept parameter.
struct MethodRow {
  double x = 0;
  std::string scene;
  std::string method;
  ImageError error;
};

// --- orbit (sweep_orbit.cpp) ---

// The scene's camera turned by `deg` about its up axis through its look-at point: same
// distance and height, same up, field of view. Near and far are widened, the same at every
// angle, to hold the sphere around the look-at point that holds the whole scene, so that no
// angle clips it.
Camera orbit_camera(const Scene& scene, float deg);

// Share of pixels that pop between frames 0 and 1 of a method: some channel changes by more
// than the reference's change in that channel at that pixel plus `threshold` (8-bit units):
// |m1 - m0| > |r1 - r0| + threshold. All four frames have one size.
double popping_share(const Framebuffer& m0, const Framebuffer& m1, const Framebuffer& r0,
                     const Framebuffer& r1, int threshold);

struct OrbitOptions {
  int steps = 360;                    // frames over 360 degrees
  Viewport viewport{320, 240};
  int threshold = 16;                 // popping threshold, 8-bit units
  std::vector<std::string> methods;   // empty: every method
};

struct OrbitRow {
  int step = 0;
  double angle_deg = 0;
  std::string method;
  double popping = 0;   // popping_share of the frame before (step 0: the last) to this one
  ImageError error;     // this frame against the reference
};

std::vector<OrbitRow> orbit_sweep(const Scene& scene, const OrbitOptions& o,
                                  const SweepProgress& progress = {});

// --- depth separation against depth bits (sweep_depth.cpp) ---

struct DepthOptions {
  std::vector<double> separations;    // empty: default_separations()
  std::vector<int> depth_bits{8, 12, 16, 20, 24, 32};
  Viewport viewport{320, 240};
};

struct DepthRow {
  double separation = 0;
  std::string method;       // "opaque", or "reference" (the exact sort; depth_bits 0)
  int depth_bits = 0;
  size_t near_pixels = 0;   // pixels the near (blue) quad covers: it is in front at every one
  size_t far_shown = 0;     // of those, pixels where the image shows the far (red) one
  double error = 0;         // far_shown / near_pixels
  // The same against the reference instead of the geometry: the share of the pixels where
  // the reference shows the near quad that show the far one.
  double error_vs_reference = 0;
};

// The separations of DepthOptions when it gives none: 10^(k/8), k = -48..0 (1e-6 to 1).
std::vector<double> default_separations();

// two_layers_scene(separation) for every separation: `opaque` at every depth width, and the
// reference.
std::vector<DepthRow> depth_sweep(const DepthOptions& o, const SweepProgress& progress = {});

// The largest separation with a nonzero error of `method` at `depth_bits` (0 for the
// reference), or 0 when there is none.
double onset_separation(const std::vector<DepthRow>& rows, const std::string& method,
                        int depth_bits);

// --- layer count and alpha on layers_scene (sweep_layers.cpp) ---

struct LayersOptions {
  int max_layers = 16;                // N = 1..max_layers
  float alpha = 0.5f;
  Viewport viewport{320, 240};
  std::vector<std::string> methods;   // empty: every method
};

// layers_scene(N, alpha): every method against the reference; x = N.
std::vector<MethodRow> layers_sweep(const LayersOptions& o, const SweepProgress& progress = {});

struct AlphaOptions {
  int layers = 4;
  std::vector<float> alphas;          // empty: 0.05 to 0.95 in steps of 0.05
  Viewport viewport{320, 240};
  std::vector<std::string> methods;   // empty: every method
};

// layers_scene(layers, a): every method against the reference; x = a.
std::vector<MethodRow> alpha_sweep(const AlphaOptions& o, const SweepProgress& progress = {});

// Submission order against K (mlab-K's order independence up to K layers, its merge beyond):
// layers_scene(N, alpha) with its layers submitted near to far, far to near and shuffled
// (seeded), for N = 1..max_layers; x = N, each row's method "M (order)".
struct OrderOptions {
  int max_layers = 16;
  float alpha = 0.5f;
  uint64_t seed = 1;                  // the shuffle's
  Viewport viewport{160, 120};
  std::vector<std::string> methods{"mlab-2", "mlab-4", "depth-peel-2", "depth-peel-4", "wboit",
                                   "unsorted"};
};
std::vector<MethodRow> order_sweep(const OrderOptions& o, const SweepProgress& progress = {});

// --- coverage samples (sweep_samples.cpp) ---

struct SamplesOptions {
  std::vector<int> samples{1, 2, 4, 8, 16};
  int supersample = 8;                // the ground truth: the reference at this factor, filtered
  Viewport viewport{320, 240};
  std::vector<std::string> methods{"coverage-aa", "opaque"};
  // coverage-aa draws every material opaque: a transparent object would add the same error
  // at every sample count and hide the curve, so by default it is left out.
  bool opaque_only = true;
};

// Opaque triangles apart from each other over a white background: edges but no shared
// edges, so coverage-aa's error there is anti-aliasing alone (no seams to leak through).
Scene separate_triangles_scene();

// `scene`, then separate_triangles_scene(), with Viewport::coverage_samples at each count:
// every method against the supersampled reference; x = samples.
std::vector<MethodRow> samples_sweep(const Scene& scene, const SamplesOptions& o,
                                     const SweepProgress& progress = {});

// --- the hidden-line depth offset (sweep_offset.cpp) ---

// One depth offset the sweep tries: which knob it moves (units, slope, clamp: the polygon
// offset around kEdgeSlopeOffset; faces: the units of the offset from the edge's own faces)
// and that knob's value (units, the slope factor, the clamp in units with infinity for none).
struct OffsetSetting {
  std::string knob;
  double value = 0;
  DepthOffset offset;
};

// The settings of the sweep and of zblend plan's offset search, knob by knob, each knob's
// values ascending.
std::vector<OffsetSetting> offset_settings();

// True when `o` is the hidden-line plans' offset (kEdgeOffset).
bool is_default_offset(const DepthOffset& o);

// An opaque plate (a box of half size 0.8 x 0.8 x 0.06, as parts' plates) whose large face is
// tilted `deg` degrees away from the eye about a horizontal axis, with an opaque ball behind
// it: the plate's front edges must stay visible on its face at every tilt, its back edges and
// the ball's silhouette must stay hidden where the plate covers them.
Scene tilted_plate_scene(float deg);

struct OffsetOptions {
  std::vector<double> tilts;          // empty: default_tilts()
  std::vector<std::string> scenes{"cad", "parts"};  // built-ins measured at every setting too
  Viewport viewport{320, 240};
};

// 0 to 80 degrees in steps of 10, then 85, 87, 88, 89, 89.5 and 89.9.
std::vector<double> default_tilts();

struct OffsetRow {
  std::string knob;
  double value = 0;
  bool is_default = false;
  std::string scene;   // "tilt" for tilted_plate_scene, else the built-in's name
  double tilt = 0;     // degrees; NaN for the built-ins
  LineError error;     // hidden-line with this offset against the exact line reference
};

// hidden-line with every setting on tilted_plate_scene at every tilt and on the built-ins,
// against the exact line reference (hidden-line-dim classifies every edge pixel the same way).
std::vector<OffsetRow> offset_sweep(const OffsetOptions& o, const SweepProgress& progress = {});

// The mean over the tilts of hidden drawn plus visible missing, for one knob's value.
double offset_tilt_error(const std::vector<OffsetRow>& rows, const std::string& knob, double value);

// A knob's knee: its smallest value whose offset_tilt_error is within 0.1 % of the edge pixels
// of the least over its values.
double offset_knee(const std::vector<OffsetRow>& rows, const std::string& knob);

// --- weighted blended OIT's widths (sweep_wboit.cpp) ---

struct WboitOptions {
  std::vector<int> weight_bits{0, 2, 4, 6, 8, 10, 12, 14, 16};
  std::vector<int> acc_bits{12, 16, 20, 24, 32};
  // The patents' methods and depth peeling at their one cost each, beside wboit's formats.
  std::vector<std::string> baselines{"unsorted", "three-pass", "back-front", "depth-peel-8"};
  Viewport viewport{160, 120};
};

// The scenes of the sweep: layers of alpha 0.5 and 0.9 (order matters most at high alpha),
// cad's nested shells, glass-torus and particles.
std::vector<Scene> wboit_scenes();

struct WboitRow {
  std::string scene;
  std::string method;    // "wboit" or a baseline
  WboitFormat format;    // wboit's widths (revealage 8 bits); a baseline's are unused
  uint64_t bytes = 0;    // memory traffic, read and written (pass_traffic)
  ImageError error;      // against the reference
};

// wboit at every acc_bits x weight_bits (revealage 8 bits) and each baseline, on one scene
// rasterized at o.viewport.
std::vector<WboitRow> wboit_scene_rows(const Scene& scene, const WboitOptions& o);

// wboit_scene_rows on every scene of wboit_scenes().
std::vector<WboitRow> wboit_sweep(const WboitOptions& o, const SweepProgress& progress = {});

// Mean over the scenes of wboit's mean CIEDE2000 at one format.
double wboit_mean_error(const std::vector<WboitRow>& rows, int acc_bits, int weight_bits);

// The weight range with the least wboit_mean_error at `acc_bits` (the smallest on a tie).
int wboit_best_weight(const std::vector<WboitRow>& rows, int acc_bits);

// --- output (sweep_csv.cpp, sweep_summary.cpp) ---

std::string orbit_csv(const std::vector<OrbitRow>& rows);
std::string depth_csv(const std::vector<DepthRow>& rows);
std::string method_csv(const char* x_name, const std::vector<MethodRow>& rows);
std::string offset_csv(const std::vector<OffsetRow>& rows);
std::string wboit_csv(const std::vector<WboitRow>& rows);

// What a run of `zblend sweep all` found, for DIR/sweeps.md.
struct SweepResults {
  std::string orbit_scene;
  OrbitOptions orbit;
  std::vector<OrbitRow> orbit_rows;
  DepthOptions depth;
  std::vector<DepthRow> depth_rows;
  LayersOptions layers;
  std::vector<MethodRow> layers_rows;
  AlphaOptions alpha;
  std::vector<MethodRow> alpha_rows;
  OrderOptions order;
  std::vector<MethodRow> order_rows;
  std::string samples_scene;
  SamplesOptions samples;
  std::vector<MethodRow> samples_rows;
  OffsetOptions offset;
  std::vector<OffsetRow> offset_rows;
  WboitOptions wboit;
  std::vector<WboitRow> wboit_rows;
  double seconds = 0;                 // wall time of the whole run
};

// The mean popping share of each method over the orbit, in method order.
std::vector<std::pair<std::string, double>> mean_popping(const std::vector<OrbitRow>& rows);

// DIR/sweeps.md: each chart (NAME.png) with what it shows, in numbers from `r`.
std::string sweeps_markdown(const SweepResults& r);

}  // namespace zb::lab
