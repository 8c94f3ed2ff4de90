// Scene analysis: depth complexity, transparent layers, depth separation, tiles touched and
// anti-aliased edges of a rasterized scene (docs/sizing.md "What is analysed").
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/render.h"

namespace zb {

// The tile sizes analysed (square tiles, the RTL's TILE_W = TILE_H).
constexpr int kAnalysisTileSizes[] = {16, 32, 64};

struct TilesTouched {
  int size = 0;          // tile width and height, pixels
  uint64_t touched = 0;  // tiles holding at least one fragment
  uint64_t total = 0;    // tiles of the frame, ceil(W / size) * ceil(H / size)
};

// The smallest depth separation is taken between fragments of two primitives at one pixel,
// over the pixel's visible stack: fragments sorted by exact depth up to the nearest opaque one
// and the first one behind it (the one z-fighting would let through). Pairs of primitives
// sharing a window vertex (one connected surface, folding over at a silhouette) are skipped.
struct SceneAnalysis {
  int width = 0, height = 0;
  uint64_t fragments = 0;       // the triangles' fragments at pixel centres
  uint64_t covered_pixels = 0;  // pixels with at least one fragment

  // Depth complexity: fragments per pixel.
  int max_depth_complexity = 0;
  double mean_depth_complexity = 0;          // over covered pixels
  std::vector<uint64_t> depth_histogram;     // [n]: pixels with n fragments, n = 0..max

  // Transparent layers: transparent fragments nearer than the pixel's nearest opaque one (what
  // the reference composites).
  int max_layers = 0;
  std::vector<uint64_t> layer_histogram;     // [k]: pixels with k layers, k = 0..max
  double share_over(int k) const;            // share of covered pixels with more than k layers
  std::vector<uint16_t> pixel_layers;        // per pixel, row-major

  // Depth separation, in window depth [0, 1] (RasterizedScene::z_exact).
  uint64_t separated_pixels = 0;  // pixels with a pair of fragments of unconnected primitives
  double min_separation = 0;      // smallest over those pixels; 0 with none
  int min_separation_x = -1, min_separation_y = -1;
  double p1_separation = 0;       // 1% of those pixels have a smaller one
  int depth_bits_needed = 0;      // depth_bits_to_resolve(min_separation); 0 with no pair
  int depth_bits_needed_p1 = 0;   // the same for p1_separation

  std::vector<TilesTouched> tiles;  // one per kAnalysisTileSizes

  // Anti-aliasing at 16 samples (coverage.h): pixels where a triangle covers 1 to 15 samples
  // and more than one colour meets (the triangles' flat colours, and the background when their
  // counts sum to fewer than 16).
  uint64_t aa_edge_pixels = 0;
  bool aa_visible() const { return aa_edge_pixels > 0; }
};

SceneAnalysis analyse_scene(const RasterizedScene& rs);

// Returned by depth_bits_to_resolve when no width resolves the separation.
constexpr int kUnresolvable = 99;

// The narrowest depth width B >= kMinDepthBits with separation * (2^B - 1) > 2: a fragment's
// depth is within one unit of its exact depth times 2^B - 1 (half a unit from rounding the
// vertices, half from rounding the interpolation), so two fragments more than two units apart
// keep their order. kUnresolvable when no B <= 32 does (a separation of 0 included).
int depth_bits_to_resolve(double separation);

}  // namespace zb
