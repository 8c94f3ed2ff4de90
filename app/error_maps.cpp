#include "error_maps.h"

#include <algorithm>
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
  struct Map {
    const MethodRun* run;
    std::vector<float> de;  // empty for a hidden-line method
  };
  std::vector<Map> maps;
  double top = 0;
  for (const MethodRun& r : runs) {
    if (r.method == kReferenceMethod) continue;
    const lab::FairReference fair = lab::fair_reference(r.method);
    Map m{&r, {}};
    if (fair != lab::FairReference::kLines) {
      if (fair == lab::FairReference::kSupersampled && !supersampled)
        supersampled = render_reference_supersampled(scene, vp, supersample);
      m.de = delta_e_map(r.image, fair == lab::FairReference::kExact ? reference : *supersampled);
      top = std::max(top, percentile(m.de, 0.99));
    }
    maps.push_back(std::move(m));
  }
  const double scale = nice_error_scale(top);
  for (const Map& m : maps) {
    const Framebuffer picture =
        m.de.empty() ? line_error_map_image(m.run->image, *lines, kEdgeColor)
                     : error_map_image(m.de, vp.width, vp.height, scale, worst_pixel(m.de, vp.width));
    cli::write_or_fail(write_png(error_map_path(out, out_dir, m.run->method), picture));
  }
  return scale;
}

}  // namespace zb::app
