// Banded, multithreaded golden-model frame (docs/raster.md, "Banded rendering"). The datapath's
// result at a pixel depends only on the order of that pixel's fragments, and every frame
// operation is per pixel; a band that receives, pass after pass, the fragments of its rows in
// primitive order therefore ends exactly as those rows of the whole frame. The rasterizers'
// row scissor gives a band exactly those fragments; the datapath is GoldenRop itself.
#include "frame_render.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include "coverage.h"
#include "fixed_point_setup.h"
#include "lines.h"
#include "raster.h"
#include "rop.h"

namespace zb {
namespace {

using setup::floor_div;

// Fragments handed to the datapath at a time: a per-thread buffer that stays in the cache.
constexpr size_t kChunk = 4096;
// A thread's cache of fragments drawn again by a later pass: 330 KB (2^16 measured 2 MB more
// peak memory for 1-4% less time on bunny-glass); beyond it triangles are rasterized again.
constexpr size_t kCacheFragments = size_t{1} << 14;
// Triangles fetched ahead in a band's list.
constexpr size_t kPrefetch = 8;
// Below this many triangles per thread the setup is not split: little work per thread start.
constexpr size_t kMinParallelSetup = 4096;

int resolve_threads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Runs work(i) for i in [0, n): i = 0 on the calling thread, the others on threads of their
// own. Rethrows the exception of the lowest-numbered worker that threw.
template <class Work>
void run_workers(int n, Work&& work) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(n));
  auto guarded = [&](int i) {
    try {
      work(i);
    } catch (...) {
      errors[size_t(i)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(size_t(n > 0 ? n - 1 : 0));
  int spawned = 1;
  try {
    for (; spawned < n; ++spawned) pool.emplace_back(guarded, spawned);
  } catch (const std::system_error&) {
    // No more threads to be had: the caller does the rest of the work itself.
  }
  guarded(0);
  for (int i = spawned; i < n; ++i) guarded(i);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// The part of `scene` holding its triangles [first, last) in scene order, with every object
// that has some of them. setup_triangles numbers the part's triangles from 0. An object's
// vertices are cut down to those the part's triangles use (each transformed as in the whole
// scene: the same bits) when every vertex has a normal or none has; otherwise, where which
// vertices have one depends on their index, the whole arrays are kept. Throws
// std::out_of_range for a missing vertex (the caller then lets the serial setup report it).
Scene scene_part(const Scene& scene, size_t first, size_t last) {
  Scene part;
  part.materials = scene.materials;
  part.camera = scene.camera;
  part.background = scene.background;
  size_t base = 0;
  std::vector<uint32_t> remap;
  for (const Object& obj : scene.objects) {
    const Mesh& mesh = obj.mesh;
    const size_t n = mesh.triangles.size();
    const size_t lo = std::max(first, base), hi = std::min(last, base + n);
    base += n;
    if (lo >= hi) continue;
    Object o;
    o.name = obj.name;
    o.material = obj.material;
    o.transform = obj.transform;
    const auto tri_first = mesh.triangles.begin() + std::ptrdiff_t(lo - (base - n));
    const auto tri_last = mesh.triangles.begin() + std::ptrdiff_t(hi - (base - n));
    const bool compact = mesh.normals.empty() || mesh.normals.size() == mesh.positions.size();
    if (!compact) {
      o.mesh.positions = mesh.positions;
      o.mesh.normals = mesh.normals;
      o.mesh.triangles.assign(tri_first, tri_last);
    } else {
      constexpr uint32_t kUnused = UINT32_MAX;
      remap.assign(mesh.positions.size(), kUnused);
      o.mesh.triangles.reserve(hi - lo);
      for (auto t = tri_first; t != tri_last; ++t) {
        glm::uvec3 c;
        for (int k = 0; k < 3; ++k) {
          const uint32_t v = (*t)[k];
          if (v >= remap.size()) throw std::out_of_range("scene part: missing vertex");
          if (remap[v] == kUnused) {
            remap[v] = static_cast<uint32_t>(o.mesh.positions.size());
            o.mesh.positions.push_back(mesh.positions[v]);
            if (!mesh.normals.empty()) o.mesh.normals.push_back(mesh.normals[v]);
          }
          c[k] = remap[v];
        }
        o.mesh.triangles.push_back(c);
      }
    }
    part.objects.push_back(std::move(o));
  }
  return part;
}

// A primitive in a band's list: its index and the passes that draw it (bit i: pass i; plans of
// more than 32 passes ask pass_draws for the others), so a pass skips what it filters out
// without touching the primitive.
struct BinItem {
  uint32_t index = 0;
  uint32_t passes = 0;
};

// Primitives binned by band, in primitive order. The primitives are cut into contiguous
// slices binned by different threads: band b's list is slice 0's list for b, then slice 1's...
struct Bins {
  int bands = 0;
  std::vector<std::vector<BinItem>> lists;  // [slice * bands + band]
  size_t slices() const { return bands ? lists.size() / size_t(bands) : 0; }
  const std::vector<BinItem>& list(size_t slice, int band) const {
    return lists[slice * size_t(bands) + size_t(band)];
  }
};

// Bins `count` primitives on `threads` threads. rows(i, lo, hi, passes) gives the rows
// primitive i may touch (false: none; hi inclusive, both within the frame) and its pass bits.
// The threads find each primitive's bands and count; the lists are then allocated by the
// caller at their exact sizes (lists grown in the workers' own malloc arenas cost megabytes of
// resident memory, measured) and filled.
template <class Rows>
Bins bin_by_band(size_t count, int bands, int band_rows, int threads, Rows&& rows) {
  const int slices = static_cast<int>(std::clamp<size_t>(count / 4096, 1, size_t(threads)));
  auto slice_range = [&](int s, size_t& first, size_t& last) {
    first = count * size_t(s) / size_t(slices);
    last = count * size_t(s + 1) / size_t(slices);
  };
  struct Span {
    int32_t lo = 0, hi = -1;  // bands; none when hi < lo
    uint32_t passes = 0;
  };
  std::vector<Span> spans(count);
  std::vector<size_t> sizes(size_t(slices) * size_t(bands), 0);
  run_workers(slices, [&](int s) {
    size_t first = 0, last = 0;
    slice_range(s, first, last);
    size_t* n = &sizes[size_t(s) * size_t(bands)];
    for (size_t i = first; i < last; ++i) {
      int lo = 0, hi = 0;
      Span& sp = spans[i];
      if (!rows(i, lo, hi, sp.passes)) continue;
      sp.lo = lo / band_rows;
      sp.hi = hi / band_rows;
      for (int b = sp.lo; b <= sp.hi; ++b) ++n[b];
    }
  });
  Bins bins;
  bins.bands = bands;
  bins.lists.resize(sizes.size());
  for (size_t k = 0; k < sizes.size(); ++k) bins.lists[k].reserve(sizes[k]);
  run_workers(slices, [&](int s) {
    size_t first = 0, last = 0;
    slice_range(s, first, last);
    std::vector<BinItem>* lists = &bins.lists[size_t(s) * size_t(bands)];
    for (size_t i = first; i < last; ++i)
      for (int b = spans[i].lo; b <= spans[i].hi; ++b)
        lists[b].push_back(BinItem{static_cast<uint32_t>(i), spans[i].passes});
  });
  return bins;
}

// Rows [floor(y_lo / 256), floor(y_hi / 256)] clipped to the frame; false when the box misses
// it. Every rasterizer (pixel centres, coverage samples, lines) stays inside this box.
inline bool box_rows(const Viewport& vp, int64_t x_lo, int64_t x_hi, int64_t y_lo,
                     int64_t y_hi, int& lo, int& hi) {
  if (floor_div(x_hi, kSubpixelOne) < 0 || floor_div(x_lo, kSubpixelOne) >= vp.width) return false;
  const int64_t r0 = std::max<int64_t>(0, floor_div(y_lo, kSubpixelOne));
  const int64_t r1 = std::min<int64_t>(vp.height - 1, floor_div(y_hi, kSubpixelOne));
  if (r0 > r1) return false;
  lo = static_cast<int>(r0);
  hi = static_cast<int>(r1);
  return true;
}

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

// One thread's band renderer: its GoldenRop and fragment buffer are reused band after band.
class BandRenderer {
 public:
  explicit BandRenderer(const FrameJob& job) : job_(job), stats_(job.plan.passes.size()) {
    buf_.reserve(kChunk + 4 * size_t(job.geometry.viewport.width));
  }

  void draw_band(int band) {
    const Viewport& vp = job_.geometry.viewport;
    const Rgba8 bg = job_.geometry.background;
    y0_ = band * job_.band_rows;
    const int y1 = std::min(vp.height, y0_ + job_.band_rows);
    const RowRange rows{y0_, y1};
    if (band_items(job_.triangles, band) == 0 && band_items(job_.lines, band) == 0) {
      if (!job_.empty_is_clear) fill_rows(y0_, y1);
      return;  // passes without fragments add nothing to the statistics
    }
    // The last band's planes freed first: begin_frame would build the new ones beside them,
    // and freed, they are what malloc hands back, pages already resident.
    rop_ = GoldenRop();
    rop_.begin_frame(vp.width, y1 - y0_, vp.depth_bits, bg, vp.coverage_samples);
    size_t items = 0;
    for (size_t s = 0; s < job_.triangles.slices(); ++s)
      items += job_.triangles.list(s, band).size();
    cached_.assign(items, Span{});
    cache_.clear();
    for (size_t i = 0; i < job_.plan.passes.size(); ++i) {
      const PassState& pass = job_.plan.passes[i];
      for (const FrameOp& op : pass.frame_ops) rop_.frame_op(resolve_op(op, bg));
      rop_.begin_pass(pass.rop);
      feed(i, band, rows);
      stats_[i] += rop_.end_pass();
    }
    for (const FrameOp& op : job_.plan.final_ops) rop_.frame_op(resolve_op(op, bg));

    const Framebuffer& fb = rop_.framebuffer();
    Framebuffer& frame = *job_.frame;
    const std::ptrdiff_t at = std::ptrdiff_t(frame.index(0, y0_));
    std::copy(fb.color.begin(), fb.color.end(), frame.color.begin() + at);
    std::copy(fb.depth.begin(), fb.depth.end(), frame.depth.begin() + at);
    std::copy(fb.coverage.begin(), fb.coverage.end(), frame.coverage.begin() + at);
    std::copy(fb.peel.begin(), fb.peel.end(), frame.peel.begin() + at);
  }

  const std::vector<PassStats>& stats() const { return stats_; }

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

  // The feeder for one pass over the band's rows: the primitives in order, each rasterized
  // (or replayed from the band's cache) into the buffer, the feeder's rules applied.
  void feed(size_t pass_index, int band, RowRange rows) {
    const PassState& pass = job_.plan.passes[pass_index];
    const FrameGeometry& g = job_.geometry;
    const bool rewrite = pass.filter == PrimFilter::kEdges || feeder_rewrites(pass);
    buf_.clear();
    if (pass.filter == PrimFilter::kEdges) {
      for_each_item(job_.lines, band, g.lines, [&](const BinItem& item, size_t) {
        const ScreenLine& l = g.lines[item.index];
        const size_t from = buf_.size();
        rasterize_line(l.v[0], l.v[1], g.viewport, Rgba8{0, 0, 0, 255}, l.prim, buf_, rows);
        to_band_rows(from);
        finish(pass, rewrite, from,
               pass.offset.any() ? depth_offset_of(pass.offset, l.depth_slope) : 0);
      });
    } else {
      const bool coverage = is_coverage_pass(pass.rop);
      const bool offset = rewrite && pass.offset.any();
      const uint32_t bit = pass_index < 32 ? uint32_t{1} << pass_index : 0;
      // Passes after this one, among the first 32 (the ones with bits).
      const uint32_t later = pass_index < 31 ? ~((uint32_t{2} << pass_index) - 1) : 0;
      for_each_item(job_.triangles, band, g.triangles, [&](const BinItem& item, size_t ordinal) {
        const ScreenTriangle& t = g.triangles[item.index];
        if (bit ? !(item.passes & bit) : !pass_draws(pass, t)) return;
        const size_t from = buf_.size();
        Span& cached = cached_[ordinal];
        if (coverage) {
          rasterize_coverage(t, g.viewport, buf_, nullptr, rows);
          to_band_rows(from);
        } else if (cached.end > cached.begin) {
          buf_.insert(buf_.end(), cache_.begin() + cached.begin, cache_.begin() + cached.end);
        } else {
          rasterize(t, g.viewport, buf_, nullptr, rows);
          to_band_rows(from);
          // Drawn again by a later pass (three-pass draws the transparent ones twice): kept,
          // as rasterized, while the band's cache has room.
          const size_t n = buf_.size() - from;
          if ((item.passes & job_.ordinary_passes & later) != 0 && n > 0 &&
              cache_.size() + n <= kCacheFragments) {
            cached.begin = static_cast<uint32_t>(cache_.size());
            cache_.insert(cache_.end(), buf_.begin() + std::ptrdiff_t(from), buf_.end());
            cached.end = static_cast<uint32_t>(cache_.size());
          }
        }
        finish(pass, rewrite, from, offset ? depth_offset_of(pass.offset, job_.slopes[t.prim]) : 0);
      });
    }
    if (!buf_.empty()) rop_.draw(buf_.data(), buf_.size());
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

  // Rows of buf_[from..] made relative to the band.
  void to_band_rows(size_t from) {
    const uint16_t y0 = static_cast<uint16_t>(y0_);
    for (size_t k = from; k < buf_.size(); ++k) buf_[k].y = static_cast<uint16_t>(buf_[k].y - y0);
  }

  // The fragments of one primitive, buf_[from..]: filtered and rewritten by the feeder when the
  // pass asks for it; the buffer drawn once it holds a chunk.
  void finish(const PassState& pass, bool rewrite, size_t from, uint64_t offset) {
    if (rewrite) {
      size_t keep = from;
      for (size_t k = from; k < buf_.size(); ++k) {
        Fragment f = buf_[k];
        if (feed_fragment(pass, offset, f)) buf_[keep++] = f;
      }
      buf_.resize(keep);
    }
    if (buf_.size() >= kChunk) {
      rop_.draw(buf_.data(), buf_.size());
      buf_.clear();
    }
  }

  // A triangle's fragments in cache_, [begin, end); empty when not cached.
  struct Span {
    uint32_t begin = 0;
    uint32_t end = 0;
  };

  const FrameJob& job_;
  GoldenRop rop_;
  std::vector<Fragment> buf_;
  std::vector<PassStats> stats_;
  // The band's fragments of triangles that a later pass draws again, band rows, as rasterized
  // (before the feeder's rules, which differ per pass); cached_ per item of the band's list.
  std::vector<Fragment> cache_;
  std::vector<Span> cached_;
  int y0_ = 0;
};

}  // namespace

bool plan_draws_edges(const PassPlan& plan) {
  return std::any_of(plan.passes.begin(), plan.passes.end(),
                     [](const PassState& p) { return p.filter == PrimFilter::kEdges; });
}

std::vector<ScreenTriangle> setup_triangles_parallel(const Scene& scene, const Viewport& vp,
                                                     int threads) {
  const size_t total = scene.triangle_count();
  const int n = static_cast<int>(
      std::min<size_t>(size_t(resolve_threads(threads)), total / kMinParallelSetup));
  if (n <= 1) return setup_triangles(scene, vp);
  std::vector<std::vector<ScreenTriangle>> parts(static_cast<size_t>(n));
  try {
    run_workers(n, [&](int i) {
      const size_t first = total * size_t(i) / size_t(n), last = total * size_t(i + 1) / size_t(n);
      parts[size_t(i)] = setup_triangles(scene_part(scene, first, last), vp);
      for (ScreenTriangle& t : parts[size_t(i)]) t.prim += static_cast<uint32_t>(first);
    });
  } catch (const std::exception&) {
    // A bad scene: the whole setup says what is wrong, in its own words.
    return setup_triangles(scene, vp);
  }
  size_t count = 0;
  for (const auto& p : parts) count += p.size();
  std::vector<ScreenTriangle> out;
  out.reserve(count);
  for (auto& p : parts) {
    out.insert(out.end(), p.begin(), p.end());
    std::vector<ScreenTriangle>().swap(p);
  }
  return out;
}

FrameGeometry setup_frame(const Scene& scene, const Viewport& vp, bool with_lines, int threads) {
  FrameGeometry g;
  g.viewport = vp;
  g.background = scene.background;
  g.triangles = setup_triangles_parallel(scene, vp, threads);
  if (with_lines) g.lines = setup_lines(scene, vp, g.triangles);
  return g;
}

RenderResult render_frame(const FrameGeometry& geometry, const PassPlan& plan,
                          const FrameRenderOptions& options) {
  const Viewport& vp = geometry.viewport;
  if (vp.width < 1 || vp.width > kMaxFrameSize || vp.height < 1 || vp.height > kMaxFrameSize)
    throw std::invalid_argument("render_frame: viewport " + std::to_string(vp.width) + "x" +
                                std::to_string(vp.height) + " outside 1.." +
                                std::to_string(kMaxFrameSize));
  Framebuffer empty_pixel;
  {
    // Rejects what the golden model rejects, before any thread starts; then draws the plan
    // with no fragments: the value of every pixel no primitive touches.
    GoldenRop probe;
    probe.begin_frame(1, 1, vp.depth_bits, geometry.background, vp.coverage_samples);
    for (const PassState& pass : plan.passes) {
      for (const FrameOp& op : pass.frame_ops) probe.frame_op(resolve_op(op, geometry.background));
      probe.begin_pass(pass.rop);
      probe.end_pass();
    }
    for (const FrameOp& op : plan.final_ops) probe.frame_op(resolve_op(op, geometry.background));
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
  for (const std::vector<PassStats>& s : stats)
    for (size_t i = 0; i < s.size(); ++i) result.passes[i] += s[i];
  return result;
}

RenderResult render_frame(const Scene& scene, const Viewport& vp, const PassPlan& plan,
                          const FrameRenderOptions& options) {
  return render_frame(
      setup_frame(scene, vp, plan_draws_edges(plan), options.parallel_setup ? options.threads : 1),
      plan, options);
}

}  // namespace zb
