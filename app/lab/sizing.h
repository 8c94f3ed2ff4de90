// A model sized to the scene (docs/sizing.md): the cheapest method, then the narrowest depth
// width and coverage samples, then the tile size, whose error against `reference` stays within
// a bound, each measured by rendering on the golden model; the choice rendered again to verify.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "metrics/scene_analysis.h"
#include "metrics/metrics.h"
#include "scene/scene.h"
#include "sizing_cost.h"

namespace zb {

struct SizingOptions {
  int width = 640;
  int height = 480;
  int max_error = 0;  // E, 8-bit units: bound on error_beyond_rounding
  std::vector<int> depth_bits{8, 12, 16, 20, 24, 32};  // ascending
  std::vector<int> coverage_samples{1, 2, 4, 8, 16};   // ascending; coverage-aa only
  std::function<void(const std::string&)> progress;    // a line per render, when set
};

// One render of the search.
struct SizingTrial {
  std::string step;  // "method", "depth", "samples" or "verify"
  std::string method;
  int depth_bits = 0;
  int coverage_samples = 0;  // the frame's sample pattern; only coverage-aa's image depends on it
  ImageError error;          // against `reference`
  int beyond_rounding = 0;   // error_beyond_rounding against `reference`: what E bounds
  bool meets = false;        // beyond_rounding <= E
  MethodCost cost;
  int tile = 0;              // cost.best_tile at these widths
  uint64_t cycles() const { return cost.cycles(tile); }
  uint64_t traffic_bytes() const { return cost.traffic_bytes(tile, depth_bits, coverage_samples); }
};

struct SizingResult {
  SceneAnalysis analysis;           // at the frame size, the widest depth, 16 samples
  int floor_layers = 0;             // L of the exact-order composite, depth-peel-L
  int floor_max = 0;                // the largest rounding_allowance
  std::vector<SizingTrial> trials;  // in the order rendered
  bool found = false;
  // Found: the verifying render of the choice. Not found: the trial of least error (the best
  // achievable), ties to the cheaper.
  SizingTrial choice;
};

// True when `method`'s image depends on the coverage samples (coverage passes).
bool uses_coverage(const std::string& method);

// The 8-bit datapath's rounding floor, per pixel: how far its own exact-order composite
// (`exact_order`: depth-peel-L, L the scene's most transparent layers, every layer in order in
// the under blend) lies from `reference` (largest of R, G, B), but at most one unit per
// transparent layer at the pixel (`pixel_layers`, SceneAnalysis): each 8-bit blend step rounds,
// and where peeling itself goes wrong (equal depths) its error is not rounding.
std::vector<uint16_t> rounding_allowance(const Framebuffer& exact_order,
                                         const Framebuffer& reference,
                                         const std::vector<uint16_t>& pixel_layers);

// The figure E bounds: the largest channel difference (R, G, B) between `image` and
// `reference` beyond the pixel's `allowance`; 0 when every pixel is within it.
int error_beyond_rounding(const Framebuffer& image, const Framebuffer& reference,
                          const std::vector<uint16_t>& allowance);

// Runs the search. Throws std::invalid_argument for empty or invalid candidate lists.
SizingResult size_model(const Scene& scene, const SizingOptions& options);

}  // namespace zb
