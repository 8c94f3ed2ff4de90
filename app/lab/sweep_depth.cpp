// The depth sweep: two opaque quads closer and closer, at every depth width; where the far one
// starts to show through the near one (z-fighting).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/core.h>

#include "pipeline/passes.h"
#include "reference/reference.h"
#include "scene/scene_suite.h"
#include "sweeps.h"

namespace zb::lab {

namespace {

// two_layers_scene's quads are red (far) and blue (near), flat shaded: the larger channel
// tells them apart, and the white background is neither.
bool shows_red(Rgba8 c) { return c.r > c.b; }
bool shows_blue(Rgba8 c) { return c.b > c.r; }

// The pixels the near quad covers. The quads are parallel and the near one is on the eye's
// side, so it is in front at each of them: the truth that does not depend on depth precision.
std::vector<bool> near_coverage(const RasterizedScene& rs) {
  std::vector<bool> mask(size_t(rs.viewport.width) * rs.viewport.height, false);
  for (const Fragment& f : rs.fragments)
    if (shows_blue(f.color)) mask[size_t(f.y) * rs.viewport.width + f.x] = true;
  return mask;
}

DepthRow measure(const Framebuffer& image, const Framebuffer& ref, const std::vector<bool>& near) {
  DepthRow r;
  size_t ref_near = 0, ref_near_red = 0;
  for (size_t p = 0; p < image.color.size(); ++p) {
    const bool red = shows_red(image.color[p]);
    if (near[p]) ++r.near_pixels, r.far_shown += red;
    if (shows_blue(ref.color[p])) ++ref_near, ref_near_red += red;
  }
  r.error = r.near_pixels ? double(r.far_shown) / double(r.near_pixels) : 0.0;
  r.error_vs_reference = ref_near ? double(ref_near_red) / double(ref_near) : 0.0;
  return r;
}

}  // namespace

std::vector<double> default_separations() {
  std::vector<double> v;
  for (int k = -48; k <= 0; ++k) v.push_back(std::pow(10.0, k / 8.0));
  return v;
}

std::vector<DepthRow> depth_sweep(const DepthOptions& o, const SweepProgress& progress) {
  const std::vector<double> seps = o.separations.empty() ? default_separations() : o.separations;
  std::vector<DepthRow> rows;
  for (size_t i = 0; i < seps.size(); ++i) {
    const Scene scene = two_layers_scene(float(seps[i]));
    // Rasterized at the widest depth: the reference sorts by unrounded depth, the same at
    // every width, and coverage does not depend on depth.
    Viewport wide = o.viewport;
    wide.depth_bits = kMaxDepthBits;
    const RasterizedScene rs = rasterize_scene(scene, wide);
    const std::vector<bool> near = near_coverage(rs);
    const Framebuffer ref = render_reference(rs);
    auto add = [&](const Framebuffer& image, const char* method, int bits) {
      DepthRow r = measure(image, ref, near);
      r.separation = seps[i];
      r.method = method;
      r.depth_bits = bits;
      rows.push_back(r);
      return r.error;
    };
    std::string note = fmt::format(" reference:{:.1f}%", 100 * add(ref, kReferenceMethod, 0));
    for (const int bits : o.depth_bits) {
      Viewport vp = o.viewport;
      vp.depth_bits = bits;
      const Framebuffer image = render_method(rasterize_scene(scene, vp), "opaque");
      note += fmt::format(" {}:{:.1f}%", bits, 100 * add(image, "opaque", bits));
    }
    if (progress)
      progress(fmt::format("depth: {}/{} separation {:.3g}, near quad showing the far one{}",
                           i + 1, seps.size(), seps[i], note));
  }
  return rows;
}

double onset_separation(const std::vector<DepthRow>& rows, const std::string& method,
                        int depth_bits) {
  double onset = 0;
  for (const DepthRow& r : rows)
    if (r.method == method && r.depth_bits == depth_bits && r.far_shown > 0)
      onset = std::max(onset, r.separation);
  return onset;
}

}  // namespace zb::lab
