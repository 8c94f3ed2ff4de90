#include "error_maps.h"

#include <filesystem>

#include "cli.h"
#include "io/image.h"
#include "lab.h"
#include "metrics/error_map.h"
#include "output_paths.h"
#include "pipeline/passes.h"
#include "reference/reference.h"

namespace zb::app {

namespace fs = std::filesystem;

std::string error_map_path(const std::string& out, const std::string& out_dir, const std::string& method) {
  if (!out_dir.empty()) return (fs::path(out_dir) / (method + "-error.png")).string();
  fs::path p(out);
  return (p.parent_path() / (p.stem().string() + "-error.png")).string();
}

double write_error_maps(const std::vector<MethodRun>& runs, const Framebuffer& reference,
                        const std::optional<LineVisibility>& lines, const Scene& scene,
                        const Viewport& vp, const std::string& out, const std::string& out_dir) {
  const int supersample = lab::LabOptions{}.supersample;  // the lab's fair reference, the same
  std::optional<Framebuffer> supersampled;
  std::vector<const MethodRun*> shown;
  std::vector<std::vector<float>> de;  // per shown run; empty for a hidden-line method
  for (const MethodRun& r : runs) {
    if (r.method == kReferenceMethod) continue;
    const lab::FairReference fair = lab::fair_reference(r.method);
    shown.push_back(&r);
    de.emplace_back();
    if (fair == lab::FairReference::kLines) continue;
    if (fair == lab::FairReference::kSupersampled && !supersampled)
      supersampled = render_reference_supersampled(scene, vp, supersample);
    de.back() = delta_e_map(r.image, fair == lab::FairReference::kExact ? reference : *supersampled);
  }
  const double scale = shared_error_scale(de);
  for (size_t i = 0; i < shown.size(); ++i) {
    const Framebuffer picture =
        de[i].empty() ? line_error_map_image(shown[i]->image, *lines, kEdgeColor)
                      : error_map_image(de[i], vp.width, vp.height, scale, worst_pixel(de[i], vp.width));
    cli::write_or_fail(write_png(error_map_path(out, out_dir, shown[i]->method), picture));
  }
  return scale;
}

}  // namespace zb::app
