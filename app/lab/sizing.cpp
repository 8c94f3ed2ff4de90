#include "sizing.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>

#include <fmt/core.h>

#include "geometry/frame_geometry.h"
#include "pipeline/passes.h"
#include "reference/reference.h"
#include "pipeline/render.h"
#include "rop/rop.h"

namespace zb {

bool uses_coverage(const std::string& method) {
  const PassPlan* plan = find_plan(method);
  if (!plan) return false;
  return std::any_of(plan->passes.begin(), plan->passes.end(),
                     [](const PassState& p) { return is_coverage_pass(p.rop); });
}

namespace {

int channel_error(Rgba8 a, Rgba8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

void check_sizes(const Framebuffer& a, const Framebuffer& b, size_t n) {
  if (a.color.size() != b.color.size() || a.color.size() != n)
    throw std::invalid_argument("sizing: images and per-pixel figures differ in size");
}

}  // namespace

std::vector<uint16_t> rounding_allowance(const Framebuffer& exact_order,
                                         const Framebuffer& reference,
                                         const std::vector<uint16_t>& pixel_layers) {
  check_sizes(exact_order, reference, pixel_layers.size());
  std::vector<uint16_t> out(pixel_layers.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = uint16_t(std::min<int>(channel_error(exact_order.color[i], reference.color[i]),
                                    pixel_layers[i]));
  return out;
}

int error_beyond_rounding(const Framebuffer& image, const Framebuffer& reference,
                          const std::vector<uint16_t>& allowance) {
  check_sizes(image, reference, allowance.size());
  int worst = 0;
  for (size_t i = 0; i < allowance.size(); ++i)
    worst = std::max(worst, channel_error(image.color[i], reference.color[i]) - int(allowance[i]));
  return worst;
}

namespace {

// Cheaper: fewer cycles, then fewer bytes, then fewer passes (ties keep the earlier method).
bool cheaper(const SizingTrial& a, const SizingTrial& b) {
  return std::make_tuple(a.cycles(), a.traffic_bytes(), a.cost.passes) <
         std::make_tuple(b.cycles(), b.traffic_bytes(), b.cost.passes);
}

// Closer to the bound: less error beyond rounding, then the cheaper.
bool closer(const SizingTrial& a, const SizingTrial& b) {
  if (a.beyond_rounding != b.beyond_rounding) return a.beyond_rounding < b.beyond_rounding;
  return cheaper(a, b);
}

void check_options(const SizingOptions& o) {
  auto ascending = [](const std::vector<int>& v) { return std::is_sorted(v.begin(), v.end()); };
  if (o.depth_bits.empty() || !ascending(o.depth_bits) || o.depth_bits.front() < kMinDepthBits ||
      o.depth_bits.back() > kMaxDepthBits)
    throw std::invalid_argument("sizing: depth bits must ascend within 8..32");
  if (o.coverage_samples.empty() || !ascending(o.coverage_samples) ||
      !std::all_of(o.coverage_samples.begin(), o.coverage_samples.end(), valid_coverage_samples))
    throw std::invalid_argument("sizing: coverage samples must ascend, each 1, 2, 4, 8 or 16");
  if (o.max_error < 0 || o.max_error > 255)
    throw std::invalid_argument("sizing: the error bound is an 8-bit value, 0 to 255");
}

class Search {
 public:
  Search(const Scene& scene, const SizingOptions& o, SizingResult& out)
      : scene_(scene), o_(o), out_(out) {}

  void run() {
    const int widest = o_.depth_bits.back();
    const RasterizedScene& rs = raster(widest, kDefaultCoverageSamples);
    reference_ = render_reference(rs);
    out_.analysis = analyse_scene(rs);
    // The rounding floor: every layer in order, through the datapath.
    out_.floor_layers = std::max(1, out_.analysis.max_layers);
    GoldenRop golden;
    const Framebuffer exact_order =
        render(rs, make_depth_peel_plan(out_.floor_layers), golden).framebuffer;
    allowance_ = rounding_allowance(exact_order, reference_, out_.analysis.pixel_layers);
    out_.floor_max = *std::max_element(allowance_.begin(), allowance_.end());

    // 1. The cheapest method within E, each at the widest depth; coverage-aa at the fewest
    // samples within E at that depth. Wireframes (edge passes) draw no shaded image: the
    // hidden-line offset search sizes them (offset_plan.h).
    std::vector<SizingTrial> firsts;
    for (const PassPlan& plan : pass_plans()) {
      if (plan_draws_edges(plan)) continue;
      if (!uses_coverage(plan.name)) {
        firsts.push_back(trial("method", plan.name, widest, kDefaultCoverageSamples));
        continue;
      }
      std::optional<SizingTrial> best;  // the first within E, else the closest
      for (const int c : o_.coverage_samples) {
        SizingTrial t = trial("method", plan.name, widest, c);
        if (!best || t.meets || closer(t, *best)) best = t;
        if (t.meets) break;
      }
      firsts.push_back(*best);
    }
    const SizingTrial* pick = nullptr;
    for (const SizingTrial& t : firsts)
      if (t.meets && (!pick || cheaper(t, *pick))) pick = &t;
    if (!pick) {
      out_.found = false;
      out_.choice = out_.trials.front();
      for (const SizingTrial& t : out_.trials)
        if (closer(t, out_.choice)) out_.choice = t;
      return;
    }
    const std::string method = pick->method;
    int samples = pick->coverage_samples;

    // 2. The narrowest depth within E at those samples.
    int depth = widest;
    for (const int d : o_.depth_bits) {
      if (d == widest || trial("depth", method, d, samples).meets) {
        depth = d;
        break;
      }
    }
    // 3. The fewest samples within E at that depth (coverage-aa only).
    if (uses_coverage(method)) {
      for (const int c : o_.coverage_samples) {
        if (c == samples || trial("samples", method, depth, c).meets) {
          samples = c;
          break;
        }
      }
    }
    // 4. The tile size comes with the trial (MethodCost::best_tile). 5. Verify: everything
    // again from the scene, the reference included.
    cache_.reset();
    const RasterizedScene& fresh = raster(depth, samples);
    reference_ = render_reference(fresh);
    out_.choice = trial("verify", method, depth, samples);
    out_.found = out_.choice.meets;
  }

 private:
  // The scene rasterized at these widths; one kept, as the search moves a width at a time.
  const RasterizedScene& raster(int depth_bits, int samples) {
    if (!cache_ || cache_->viewport.depth_bits != depth_bits ||
        cache_->viewport.coverage_samples != samples) {
      cache_.reset();
      Viewport vp{o_.width, o_.height, depth_bits, samples};
      cache_ = std::make_unique<RasterizedScene>(rasterize_scene(scene_, vp));
    }
    return *cache_;
  }

  SizingTrial trial(const char* step, const std::string& method, int depth_bits, int samples) {
    const RasterizedScene& rs = raster(depth_bits, samples);
    GoldenRop golden;
    CostCounter counter(golden);
    const Framebuffer image = render(rs, *find_plan(method), counter).framebuffer;
    SizingTrial t;
    t.step = step;
    t.method = method;
    t.depth_bits = depth_bits;
    t.coverage_samples = samples;
    t.error = compare_images(image, reference_);
    t.beyond_rounding = error_beyond_rounding(image, reference_, allowance_);
    t.meets = t.beyond_rounding <= o_.max_error;
    t.cost = counter.cost();
    t.tile = t.cost.best_tile(depth_bits, samples);
    if (o_.progress)
      o_.progress(fmt::format("plan: {:<7} {:<16} {:>2}-bit depth, {:>2} samples: error {} "
                              "beyond rounding (max {}), {} cycles at {}x{} tiles", step, method,
                              depth_bits, samples, t.beyond_rounding, t.error.max_abs, t.cycles(),
                              t.tile, t.tile));
    out_.trials.push_back(t);
    return t;
  }

  const Scene& scene_;
  const SizingOptions& o_;
  SizingResult& out_;
  std::unique_ptr<RasterizedScene> cache_;
  Framebuffer reference_;
  std::vector<uint16_t> allowance_;  // rounding_allowance, per pixel
};

}  // namespace

SizingResult size_model(const Scene& scene, const SizingOptions& options) {
  check_options(options);
  SizingResult result;
  Search(scene, options, result).run();
  return result;
}

}  // namespace zb
