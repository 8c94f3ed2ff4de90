#include "error_maps.h"

#include <atomic>
#include <cmath>
#include <filesystem>
#include <list>

#include <fmt/core.h>

#include "cli.h"
#include "io/image.h"
#include "lab.h"
#include "metrics/error_map.h"
#include "output_paths.h"
#include "parallel/parallel.h"
#include "pipeline/passes.h"
#include "reference/reference.h"

namespace zb::app {

namespace fs = std::filesystem;

std::string error_map_path(const std::string& out, const std::string& out_dir, const std::string& method) {
  if (!out_dir.empty()) return (fs::path(out_dir) / (method + "-error.png")).string();
  fs::path p(out);
  return (p.parent_path() / (p.stem().string() + "-error.png")).string();
}

ErrorScale parse_error_scale(const std::string& text) {
  if (text == "auto") return {};
  if (text == "per-method") return {ErrorScale::Kind::kPerMethod, 0};
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(v > 0) || !std::isfinite(v))
    throw cli::UsageError("--error-scale: '" + text + "' is not auto, per-method or a number of "
                          "dE2000 above 0");
  return {ErrorScale::Kind::kFixed, v};
}

std::string write_error_maps(const std::vector<MethodRun>& runs, const Framebuffer& reference,
                             const std::optional<LineVisibility>& lines, const Scene& scene,
                             const Viewport& vp, const std::string& out, const std::string& out_dir,
                             const ErrorScale& scale, int threads) {
  const int supersample = lab::LabOptions{}.supersample;  // the lab's fair reference, the same
  std::optional<Framebuffer> supersampled;
  std::vector<const MethodRun*> shown;
  // Per shown run its CIEDE2000: the run's own (not copied), or made here into `made`; none for
  // a hidden-line method.
  std::vector<const std::vector<float>*> de;
  std::list<std::vector<float>> made;
  static const std::vector<float> kNone;
  for (const MethodRun& r : runs) {
    if (r.method == kReferenceMethod) continue;
    const lab::FairReference fair = lab::fair_reference(r.method);
    shown.push_back(&r);
    de.push_back(&kNone);
    if (fair == lab::FairReference::kLines) continue;
    if (fair == lab::FairReference::kExact && !r.delta_e.empty()) {
      de.back() = &r.delta_e;
      continue;
    }
    if (fair == lab::FairReference::kSupersampled && !supersampled)
      supersampled = render_reference_supersampled(scene, vp, supersample, threads);
    made.push_back(delta_e_map(r.image, fair == lab::FairReference::kExact ? reference : *supersampled));
    de.back() = &made.back();
  }
  // shared_error_scale's rule, over the maps where they are (not copied into one list).
  double shared = scale.value;
  if (scale.kind == ErrorScale::Kind::kShared) {
    shared = kMinErrorScale;
    for (const std::vector<float>* d : de) shared = std::max(shared, error_scale(*d));
  }
  // The maps are independent: drawn and encoded side by side.
  std::vector<std::string> errors(shown.size());
  std::atomic<size_t> next{0};
  run_workers(std::max(1, std::min(resolve_threads(threads), int(shown.size()))), [&](int) {
    for (size_t i; (i = next++) < shown.size();) {
      const std::vector<float>& d = *de[i];
      const double own = scale.kind == ErrorScale::Kind::kPerMethod ? error_scale(d) : shared;
      const Framebuffer picture =
          d.empty() ? line_error_map_image(shown[i]->image, *lines, kEdgeColor)
                    : error_map_image(d, vp.width, vp.height, own, worst_pixel(d, vp.width));
      errors[i] = write_png(error_map_path(out, out_dir, shown[i]->method), picture);
    }
  });
  for (const std::string& e : errors) cli::write_or_fail(e);
  switch (scale.kind) {
    case ErrorScale::Kind::kPerMethod: return "each map on its own scale (its 99th percentile, rounded up)";
    case ErrorScale::Kind::kFixed: return fmt::format("0 to {:g} dE2000 for every method", shared);
    case ErrorScale::Kind::kShared: break;
  }
  return fmt::format("0 to {:g} dE2000 for every method (--error-scale per-method: each its own)", shared);
}

}  // namespace zb::app
