#include "scene_analysis.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>

#include "raster/sample_coverage.h"

namespace zb {
namespace {

// Fragment indices bucketed per pixel, submit order kept within a pixel.
struct PixelBuckets {
  std::vector<uint32_t> start;  // one per pixel, and one past the end
  std::vector<uint32_t> order;
};

PixelBuckets bucket_by_pixel(const RasterizedScene& rs) {
  const size_t w = size_t(rs.viewport.width), pixels = w * size_t(rs.viewport.height);
  PixelBuckets b;
  b.start.assign(pixels + 1, 0);
  for (const Fragment& f : rs.fragments) ++b.start[f.y * w + f.x + 1];
  for (size_t p = 0; p < pixels; ++p) b.start[p + 1] += b.start[p];
  b.order.resize(rs.fragments.size());
  std::vector<uint32_t> fill(b.start.begin(), b.start.end() - 1);
  for (uint32_t i = 0; i < rs.fragments.size(); ++i) {
    const Fragment& f = rs.fragments[i];
    b.order[fill[f.y * w + f.x]++] = i;
  }
  return b;
}

// Which primitives share a window vertex (same fixed-point x, y and the same exact depth):
// pieces of one connected surface.
class Connectivity {
 public:
  explicit Connectivity(const std::vector<ScreenTriangle>& triangles) {
    std::map<std::tuple<int32_t, int32_t, uint64_t>, uint32_t> ids;
    for (const ScreenTriangle& t : triangles) {
      if (t.prim >= verts_.size()) verts_.resize(size_t(t.prim) + 1);
      for (const ScreenVertex& v : t.v) {
        uint64_t zbits = 0;
        std::memcpy(&zbits, &v.z_exact, sizeof zbits);
        const auto key = std::make_tuple(v.x, v.y, zbits);
        const uint32_t id = ids.emplace(key, uint32_t(ids.size())).first->second;
        verts_[t.prim].push_back(id);
      }
    }
    for (std::vector<uint32_t>& v : verts_) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
  }

  // True for one primitive, or two that share a vertex.
  bool connected(uint32_t a, uint32_t b) const {
    if (a == b) return true;
    const std::vector<uint32_t>& x = verts_[a];
    const std::vector<uint32_t>& y = verts_[b];
    for (size_t i = 0, j = 0; i < x.size() && j < y.size();) {
      if (x[i] == y[j]) return true;
      if (x[i] < y[j]) ++i; else ++j;
    }
    return false;
  }

 private:
  std::vector<std::vector<uint32_t>> verts_;  // per primitive, its vertex ids, sorted
};

// Per pixel: the layers and the smallest separation of its visible stack.
struct PixelStack {
  int layers = 0;
  double separation = -1;  // < 0: no pair of unconnected primitives
};

// `s` sorted by exact depth, ties in submit order (as the reference sorts).
PixelStack analyse_stack(const RasterizedScene& rs, const Connectivity& conn,
                         const uint32_t* s, size_t n) {
  PixelStack out;
  size_t opaque = n;
  for (size_t i = 0; i < n && opaque == n; ++i) {
    if (rs.fragments[s[i]].color.a == 255) opaque = i;
    else ++out.layers;
  }
  // The visible stack and the first fragment behind its opaque base.
  const size_t end = std::min(n, opaque + 2);
  for (size_t i = 0; i < end; ++i) {
    // Sorted: the first unconnected fragment behind s[i] is the nearest one to it.
    for (size_t j = i + 1; j < end; ++j) {
      if (conn.connected(rs.fragments[s[i]].prim, rs.fragments[s[j]].prim)) continue;
      const double d = rs.z_exact[s[j]] - rs.z_exact[s[i]];
      if (out.separation < 0 || d < out.separation) out.separation = d;
      break;
    }
  }
  return out;
}

std::vector<TilesTouched> count_tiles(const RasterizedScene& rs) {
  std::vector<TilesTouched> out;
  const int w = rs.viewport.width, h = rs.viewport.height;
  for (const int size : kAnalysisTileSizes) {
    const int tx = (w + size - 1) / size, ty = (h + size - 1) / size;
    std::vector<char> hit(size_t(tx) * ty, 0);
    for (const Fragment& f : rs.fragments) hit[size_t(f.y / size) * tx + f.x / size] = 1;
    out.push_back({size, uint64_t(std::count(hit.begin(), hit.end(), 1)), hit.size()});
  }
  return out;
}

// Pixels where a partly covered triangle meets another colour, at 16 samples.
uint64_t count_aa_edges(const RasterizedScene& rs) {
  constexpr int kSamples = 16;
  Viewport vp = rs.viewport;
  vp.coverage_samples = kSamples;
  struct Pixel {
    int samples = 0;
    bool partial = false, colored = false, mixed = false;
    Rgba8 color;
  };
  std::vector<Pixel> px(size_t(vp.width) * vp.height);
  std::vector<Fragment> frags;
  for (const ScreenTriangle& t : rs.triangles) {
    frags.clear();
    rasterize_coverage(t, vp, frags);
    for (const Fragment& f : frags) {
      Pixel& p = px[size_t(f.y) * vp.width + f.x];
      p.samples += f.coverage;
      p.partial |= f.coverage < kSamples;
      if (p.colored && p.color != f.color) p.mixed = true;
      p.color = f.color;
      p.colored = true;
    }
  }
  uint64_t n = 0;
  for (const Pixel& p : px)
    n += p.partial && (p.mixed || (p.samples < kSamples && p.color != rs.background));
  return n;
}

}  // namespace

double SceneAnalysis::share_over(int k) const {
  if (covered_pixels == 0) return 0;
  uint64_t n = 0;
  for (size_t i = size_t(std::max(0, k + 1)); i < layer_histogram.size(); ++i)
    n += layer_histogram[i];
  // Uncovered pixels sit in bin 0, which share_over never counts for k >= 0.
  return double(n) / double(covered_pixels);
}

int depth_bits_to_resolve(double separation) {
  for (int b = kMinDepthBits; b <= kMaxDepthBits; ++b)
    if (separation * double(depth_max(b)) > 2.0) return b;
  return kUnresolvable;
}

SceneAnalysis analyse_scene(const RasterizedScene& rs) {
  SceneAnalysis a;
  a.width = rs.viewport.width;
  a.height = rs.viewport.height;
  a.fragments = rs.fragments.size();
  a.tiles = count_tiles(rs);
  a.aa_edge_pixels = count_aa_edges(rs);

  PixelBuckets b = bucket_by_pixel(rs);
  const Connectivity conn(rs.triangles);
  std::vector<double> separations;
  a.depth_histogram.assign(1, 0);
  a.layer_histogram.assign(1, 0);
  a.pixel_layers.assign(b.start.size() - 1, 0);
  for (size_t p = 0; p + 1 < b.start.size(); ++p) {
    uint32_t* first = b.order.data() + b.start[p];
    const size_t n = b.start[p + 1] - b.start[p];
    if (n >= a.depth_histogram.size()) a.depth_histogram.resize(n + 1, 0);
    ++a.depth_histogram[n];
    if (n == 0) {
      ++a.layer_histogram[0];
      continue;
    }
    ++a.covered_pixels;
    a.max_depth_complexity = std::max(a.max_depth_complexity, int(n));
    std::stable_sort(first, first + n,
                     [&](uint32_t x, uint32_t y) { return rs.z_exact[x] < rs.z_exact[y]; });
    const PixelStack s = analyse_stack(rs, conn, first, n);
    if (size_t(s.layers) >= a.layer_histogram.size()) a.layer_histogram.resize(s.layers + 1, 0);
    ++a.layer_histogram[s.layers];
    a.pixel_layers[p] = uint16_t(std::min(s.layers, 65535));
    a.max_layers = std::max(a.max_layers, s.layers);
    if (s.separation >= 0) {
      if (separations.empty() || s.separation < a.min_separation) {
        a.min_separation = s.separation;
        a.min_separation_x = int(p % size_t(a.width));
        a.min_separation_y = int(p / size_t(a.width));
      }
      separations.push_back(s.separation);
    }
  }
  if (a.covered_pixels) a.mean_depth_complexity = double(a.fragments) / double(a.covered_pixels);
  a.separated_pixels = separations.size();
  if (!separations.empty()) {
    auto nth = separations.begin() + ptrdiff_t(separations.size() / 100);
    std::nth_element(separations.begin(), nth, separations.end());
    a.p1_separation = *nth;
    a.depth_bits_needed = depth_bits_to_resolve(a.min_separation);
    a.depth_bits_needed_p1 = depth_bits_to_resolve(a.p1_separation);
  }
  return a;
}

}  // namespace zb
