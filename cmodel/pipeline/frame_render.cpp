// Banded, multithreaded golden-model frame (docs/raster.md, "Banded rendering"). The datapath's
// result at a pixel depends only on the order of that pixel's fragments, and every frame
// operation is per pixel; a band that receives, pass after pass, the fragments of its rows in
// primitive order therefore ends exactly as those rows of the whole frame. The rasterizers'
// row scissor gives a band exactly those fragments; the datapath is GoldenRop itself.
#include "frame_render.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "executor.h"
#include "internal/band_bins.h"
#include "raster/sample_coverage.h"
#include "raster/internal/edge_functions.h"
#include "raster/lines.h"
#include "raster/raster.h"
#include "rop/rop.h"
#include "parallel/parallel.h"

namespace zb {
namespace {

// A thread's cache of fragments drawn again by a later pass: 330 KB (2^16 measured 2 MB more
// peak memory for 1-4% less time on bunny-glass); beyond it triangles are rasterized again.
constexpr size_t kCacheFragments = size_t{1} << 14;
// Triangles fetched ahead in a band's list.
constexpr size_t kPrefetch = 8;
// Everything the bands share, read-only while they run.
struct FrameJob {
  const FrameGeometry& geometry;
  const PassPlan& plan;
  int band_rows = 0;
  int bands = 0;
  Bins triangles;  // triangles some triangle pass draws
  Bins lines;      // when a pass draws edges
  std::vector<uint32_t> slopes;  // per prim, when a triangle pass has a depth offset
  uint32_t ordinary_passes = 0;  // bits of the passes (first 32) drawing ordinary fragments
  Framebuffer* frame = nullptr;  // each band writes its own rows
  // A pixel no primitive touches: the plan's frame operations on the cleared planes, from a
  // 1x1 frame drawn with no fragments. Bands without primitives are filled with it (or left
  // as constructed when it is the clear state), so cost follows what the scene touches.
  Framebuffer empty_pixel;
  bool empty_is_clear = false;
};

// Items binned to `band` over all slices.
size_t band_items(const Bins& bins, int band) {
  size_t n = 0;
  for (size_t s = 0; s < bins.slices(); ++s) n += bins.list(s, band).size();
  return n;
}

// One thread's band renderer, and the band's fragment source for the plan executor: each
// primitive rasterized with the band's row scissor, or replayed from the band's cache. Its
// GoldenRop and cache are reused band after band.
class BandRenderer final : public FragmentSource {
 public:
  explicit BandRenderer(const FrameJob& job) : job_(job), stats_(job.plan.passes.size()) {}

  void draw_band(int band) {
    const Viewport& vp = job_.geometry.viewport;
    band_ = band;
    y0_ = band * job_.band_rows;
    const int y1 = std::min(vp.height, y0_ + job_.band_rows);
    rows_ = RowRange{y0_, y1};
    const size_t items = band_items(job_.triangles, band);
    if (items == 0 && band_items(job_.lines, band) == 0) {
      if (!job_.empty_is_clear) fill_rows(y0_, y1);
      return;  // passes without fragments add nothing to the statistics
    }
    // The last band's planes freed first: begin_frame would build the new ones beside them,
    // and freed, they are what malloc hands back, pages already resident.
    rop_ = GoldenRop();
    cached_.assign(items, Span{});
    cache_.clear();
    Viewport band_vp = vp;
    band_vp.height = y1 - y0_;
    const std::vector<PassStats> s = run_plan(job_.plan, band_vp, job_.geometry.background, *this, rop_);
    for (size_t i = 0; i < s.size(); ++i) stats_[i] += s[i];

    const Framebuffer& fb = rop_.framebuffer();
    Framebuffer& frame = *job_.frame;
    const std::ptrdiff_t at = std::ptrdiff_t(frame.index(0, y0_));
    std::copy(fb.color.begin(), fb.color.end(), frame.color.begin() + at);
    std::copy(fb.depth.begin(), fb.depth.end(), frame.depth.begin() + at);
    std::copy(fb.coverage.begin(), fb.coverage.end(), frame.coverage.begin() + at);
    std::copy(fb.peel.begin(), fb.peel.end(), frame.peel.begin() + at);
  }

  const std::vector<PassStats>& stats() const { return stats_; }

  // FragmentSource: the band's triangles in primitive order, each rasterized into `out` with
  // the band's rows (or replayed from the cache).
  void triangles(size_t index, const PassState& pass, FragmentKind kind,
                 std::vector<Fragment>& out, const TriangleDone& done) override {
    const FrameGeometry& g = job_.geometry;
    const uint32_t bit = index < 32 ? uint32_t{1} << index : 0;
    // Passes after this one, among the first 32 (the ones with bits).
    const uint32_t later = index < 31 ? ~((uint32_t{2} << index) - 1) : 0;
    for_each_item(job_.triangles, band_, g.triangles, [&](const BinItem& item, size_t ordinal) {
      const ScreenTriangle& t = g.triangles[item.index];
      if (bit ? !(item.passes & bit) : !pass_draws(pass, t)) return;
      const size_t from = out.size();
      Span& cached = cached_[ordinal];
      if (kind == FragmentKind::kCoverage) {
        rasterize_coverage(t, g.viewport, out, nullptr, rows_);
        to_band_rows(out, from);
      } else if (cached.end > cached.begin) {
        out.insert(out.end(), cache_.begin() + cached.begin, cache_.begin() + cached.end);
      } else {
        rasterize(t, g.viewport, out, nullptr, rows_);
        to_band_rows(out, from);
        // Drawn again by a later pass (three-pass draws the transparent ones twice): kept,
        // as rasterized, while the band's cache has room.
        const size_t n = out.size() - from;
        if ((item.passes & job_.ordinary_passes & later) != 0 && n > 0 &&
            cache_.size() + n <= kCacheFragments) {
          cached.begin = static_cast<uint32_t>(cache_.size());
          cache_.insert(cache_.end(), out.begin() + std::ptrdiff_t(from), out.end());
          cached.end = static_cast<uint32_t>(cache_.size());
        }
      }
      done(t, from);
    });
  }

  void lines(std::vector<Fragment>& out, const LineDone& done) override {
    const FrameGeometry& g = job_.geometry;
    for_each_item(job_.lines, band_, g.lines, [&](const BinItem& item, size_t) {
      const ScreenLine& l = g.lines[item.index];
      const size_t from = out.size();
      rasterize_line(l.v[0], l.v[1], g.viewport, Rgba8{0, 0, 0, 255}, l.prim, out, rows_);
      to_band_rows(out, from);
      done(l, from);
    });
  }

  uint32_t slope(const ScreenTriangle& t) override { return job_.slopes[t.prim]; }
  int row_origin() const override { return y0_; }

 private:
  void fill_rows(int y0, int y1) {
    Framebuffer& frame = *job_.frame;
    const Framebuffer& e = job_.empty_pixel;
    const auto first = std::ptrdiff_t(frame.index(0, y0)), last = std::ptrdiff_t(frame.index(0, y1));
    std::fill(frame.color.begin() + first, frame.color.begin() + last, e.color[0]);
    std::fill(frame.depth.begin() + first, frame.depth.begin() + last, e.depth[0]);
    std::fill(frame.coverage.begin() + first, frame.coverage.begin() + last, e.coverage[0]);
    std::fill(frame.peel.begin() + first, frame.peel.begin() + last, e.peel[0]);
  }

  // Calls fn(item, ordinal) for band `band`'s items in primitive order, ordinal counting them
  // from 0. A band's primitives lie scattered over the scene's (a mesh's order is not the
  // screen's): each is fetched a few items ahead, or it would be a cache miss.
  template <class T, class Fn>
  static void for_each_item(const Bins& bins, int band, const std::vector<T>& all, Fn&& fn) {
    size_t ordinal = 0;
    for (size_t s = 0; s < bins.slices(); ++s) {
      const std::vector<BinItem>& list = bins.list(s, band);
      for (size_t k = 0; k < list.size(); ++k) {
        if (k + kPrefetch < list.size()) {
          const char* ahead = reinterpret_cast<const char*>(&all[list[k + kPrefetch].index]);
          __builtin_prefetch(ahead);
          __builtin_prefetch(ahead + sizeof(T) - 1);
        }
        fn(list[k], ordinal++);
      }
    }
  }

  // Rows of out[from..] made relative to the band.
  void to_band_rows(std::vector<Fragment>& out, size_t from) const {
    const uint16_t y0 = static_cast<uint16_t>(y0_);
    for (size_t k = from; k < out.size(); ++k) out[k].y = static_cast<uint16_t>(out[k].y - y0);
  }

  // A triangle's fragments in cache_, [begin, end); empty when not cached.
  struct Span {
    uint32_t begin = 0;
    uint32_t end = 0;
  };

  const FrameJob& job_;
  GoldenRop rop_;
  std::vector<PassStats> stats_;
  // The band's fragments of triangles that a later pass draws again, band rows, as rasterized
  // (before the feeder's rules, which differ per pass); cached_ per item of the band's list.
  std::vector<Fragment> cache_;
  std::vector<Span> cached_;
  int band_ = 0;
  int y0_ = 0;
  RowRange rows_{0, 0};
};

// A source with no fragments: the plan drawn over nothing.
class NoFragments final : public FragmentSource {
 public:
  void triangles(size_t, const PassState&, FragmentKind, std::vector<Fragment>&,
                 const TriangleDone&) override {}
  void lines(std::vector<Fragment>&, const LineDone&) override {}
  uint32_t slope(const ScreenTriangle&) override { return 0; }
};

}  // namespace

RenderResult render_frame(const FrameGeometry& geometry, const PassPlan& plan,
                          const FrameRenderOptions& options) {
  const Viewport& vp = geometry.viewport;
  if (vp.width < 1 || vp.width > kMaxFrameSize || vp.height < 1 || vp.height > kMaxFrameSize)
    throw std::invalid_argument("render_frame: viewport " + std::to_string(vp.width) + "x" +
                                std::to_string(vp.height) + " outside 1.." +
                                std::to_string(kMaxFrameSize));
  // Rejects what the golden model rejects, before any thread starts; then draws the plan with
  // no fragments: the value of every pixel no primitive touches.
  Framebuffer empty_pixel;
  {
    GoldenRop probe;
    NoFragments none;
    Viewport pixel = vp;
    pixel.width = pixel.height = 1;
    run_plan(plan, pixel, geometry.background, none, probe);
    empty_pixel = probe.framebuffer();
  }
  const int band_rows = options.band_rows > 0 ? options.band_rows : kDefaultBandRows;
  FrameJob job{geometry, plan, band_rows, (vp.height + band_rows - 1) / band_rows, {}, {}, {},
               0, nullptr, {}, false};

  bool offset = false;
  std::vector<std::pair<size_t, const PassState*>> triangle_passes;
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    const PassState& p = plan.passes[i];
    if (p.filter == PrimFilter::kEdges) continue;
    triangle_passes.emplace_back(i, &p);
    offset = offset || p.offset.any();
    if (i < 32 && !is_coverage_pass(p.rop)) job.ordinary_passes |= uint32_t{1} << i;
  }
  // The feeder's filter and cull decide by a triangle's transparency and winding alone
  // (datapath.md "The feeder"): pass_draws asked once per kind, not per triangle.
  struct Kind {
    bool drawn = false;
    uint32_t passes = 0;
  };
  Kind kinds[2][2];  // [transparent][front]
  for (int transparent = 0; transparent < 2; ++transparent) {
    for (int front = 0; front < 2; ++front) {
      ScreenTriangle probe;
      probe.transparent = transparent != 0;
      probe.front = front != 0;
      Kind& kind = kinds[transparent][front];
      for (const auto& [index, pass] : triangle_passes) {
        if (!pass_draws(*pass, probe)) continue;
        kind.drawn = true;
        if (index < 32) kind.passes |= uint32_t{1} << index;
      }
    }
  }
  const std::vector<ScreenTriangle>& tris = geometry.triangles;
  const int threads = std::min(resolve_threads(options.threads), job.bands);
  job.triangles = bin_by_band(tris.size(), job.bands, band_rows, threads,
                              [&](size_t i, int& lo, int& hi, uint32_t& passes) {
    const ScreenTriangle& t = tris[i];
    const Kind& kind = kinds[t.transparent][t.front];
    if (!kind.drawn) return false;
    passes = kind.passes;
    const auto [x_lo, x_hi] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y_lo, y_hi] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    return box_rows(vp, x_lo, x_hi, y_lo, y_hi, lo, hi);
  });
  if (plan_draws_edges(plan)) {
    const std::vector<ScreenLine>& lines = geometry.lines;
    job.lines = bin_by_band(lines.size(), job.bands, band_rows, threads,
                            [&](size_t i, int& lo, int& hi, uint32_t&) {
      const ScreenLine& l = lines[i];
      return box_rows(vp, std::min(l.v[0].x, l.v[1].x), std::max(l.v[0].x, l.v[1].x),
                      std::min(l.v[0].y, l.v[1].y), std::max(l.v[0].y, l.v[1].y), lo, hi);
    });
  }
  if (offset) job.slopes = primitive_slopes(tris);

  RenderResult result;
  result.framebuffer =
      Framebuffer(vp.width, vp.height, vp.depth_bits, geometry.background, vp.coverage_samples);
  job.frame = &result.framebuffer;
  const Framebuffer& f = result.framebuffer;
  job.empty_is_clear = empty_pixel.color[0] == f.color[0] && empty_pixel.depth[0] == f.depth[0] &&
                       empty_pixel.coverage[0] == f.coverage[0] && empty_pixel.peel[0] == f.peel[0];
  job.empty_pixel = std::move(empty_pixel);

  const int n = threads;
  std::vector<std::vector<PassStats>> stats(static_cast<size_t>(n));
  std::atomic<int> next{0};
  run_workers(n, [&](int w) {
    BandRenderer r(job);
    try {
      for (int band = next++; band < job.bands; band = next++) r.draw_band(band);
    } catch (...) {
      next = job.bands;  // the others stop at their next band
      throw;
    }
    stats[size_t(w)] = r.stats();
  });
  result.passes.assign(plan.passes.size(), PassStats{});
  result.triangles = tris.size();
  for (const std::vector<PassStats>& s : stats)
    for (size_t i = 0; i < s.size(); ++i) result.passes[i] += s[i];
  return result;
}

RenderResult render_frame(const Scene& scene, const Viewport& vp, const PassPlan& plan,
                          const FrameRenderOptions& options) {
  return render_frame(
      make_frame_geometry(scene, vp, plan_draws_edges(plan), options.parallel_setup ? options.threads : 1),
      plan, options);
}

}  // namespace zb
