// The hidden-line offset sweep: the polygon offset's constant, slope factor and clamp, and the
// offset from the edge's own faces, against face tilt and against the leak (docs/sweeps.md).
#include <cmath>
#include <limits>

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/passes.h"
#include "reference/line_reference.h"
#include "rop/rop.h"
#include "scene/builtin_scenes.h"
#include "scene/meshes.h"
#include "scene/scene_build.h"
#include "sweeps.h"

namespace zb::lab {

namespace {

constexpr double kNoClamp = std::numeric_limits<double>::infinity();

bool same_offset(const DepthOffset& a, const DepthOffset& b) {
  return a.units == b.units && a.slope_q8 == b.slope_q8 && a.clamp == b.clamp &&
         a.faces == b.faces;
}

}  // namespace

std::vector<OffsetSetting> offset_settings() {
  std::vector<OffsetSetting> out;
  const DepthOffset base = kEdgeSlopeOffset;
  // Units up to 2^20: at 24 bits a scene fitted to its depth range needs thousands to move.
  for (const uint32_t u : {0u, 1u, 4u, 16u, 64u, 256u, 1024u, 4096u, 16384u, 65536u, 262144u,
                           1048576u}) {
    DepthOffset o = base;
    o.units = u;
    out.push_back({"units", double(u), o});
  }
  for (const uint32_t q : {0u, 32u, 64u, 128u, 192u, 256u, 384u, 512u, 1024u}) {
    DepthOffset o = base;
    o.slope_q8 = q;
    out.push_back({"slope", q / 256.0, o});
  }
  for (const uint32_t c : {4u, 16u, 64u, 256u, 1024u, 4096u, 16384u, 65536u, 262144u, 0u}) {
    DepthOffset o = base;
    o.clamp = c;
    out.push_back({"clamp", c == 0 ? kNoClamp : double(c), o});
  }
  for (const uint32_t u : {0u, 1u, 2u, 4u, 16u, 64u, 256u, 1024u, 4096u, 16384u}) {
    DepthOffset o = kEdgeFacesOffset;
    o.units = u;
    out.push_back({"faces", double(u), o});
  }
  return out;
}

bool is_default_offset(const DepthOffset& o) { return same_offset(o, kEdgeOffset); }

Scene tilted_plate_scene(float deg) {
  using namespace build;
  Scene s;
  s.name = fmt::format("tilt-{:g}", deg);
  s.description = "a plate tilted away from the eye, a ball behind it";
  s.camera.eye = {0.0f, 0.0f, 5.0f};
  s.camera.at = {0.0f, 0.0f, 0.0f};
  s.camera.fov_y_deg = 45.0f;
  const uint32_t steel = add_material(s, "plate", Rgba8{120, 140, 170, 255});
  const uint32_t ball = add_material(s, "ball", Rgba8{170, 120, 80, 255});
  // The plate's normal: the direction to the eye turned by the tilt about the x axis.
  add_object(s, "plate", make_box({0.8f, 0.8f, 0.06f}), steel, rotate(deg, {1.0f, 0.0f, 0.0f}));
  add_object(s, "ball", make_sphere(0.35f, 24, 12), ball, translate({0.0f, 0.0f, -0.6f}));
  fit_depth_range(s);
  return s;
}

std::vector<double> default_tilts() {
  std::vector<double> t;
  for (int d = 0; d <= 80; d += 10) t.push_back(d);
  for (const double d : {85.0, 87.0, 88.0, 89.0, 89.5, 89.9}) t.push_back(d);
  return t;
}

std::vector<OffsetRow> offset_sweep(const OffsetOptions& o, const SweepProgress& progress) {
  const std::vector<double> tilts = o.tilts.empty() ? default_tilts() : o.tilts;
  const std::vector<OffsetSetting> settings = offset_settings();
  struct Case {
    std::string scene;
    double tilt;
    Scene s;
  };
  std::vector<Case> cases;
  for (const double t : tilts) cases.push_back({"tilt", t, tilted_plate_scene(float(t))});
  for (const std::string& name : o.scenes) {
    const auto s = builtin_scene(name);
    if (!s) throw std::invalid_argument("offset_sweep: unknown scene '" + name + "'");
    cases.push_back({name, std::numeric_limits<double>::quiet_NaN(), *s});
  }
  std::vector<OffsetRow> rows;
  for (size_t i = 0; i < cases.size(); ++i) {
    // The scene's fragments and its line reference do not depend on the offset.
    const RasterizedScene rs = rasterize_scene(cases[i].s, o.viewport);
    const LineVisibility truth = line_visibility(rs);
    double worst = 0;
    for (const OffsetSetting& st : settings) {
      GoldenRop rop;
      const Framebuffer image = render(rs, make_hidden_line_plan(false, st.offset), rop).framebuffer;
      OffsetRow r{st.knob, st.value, is_default_offset(st.offset), cases[i].scene, cases[i].tilt,
                  compare_lines(image, truth, kEdgeColor)};
      worst = std::max(worst, r.error.hidden_drawn_share() + r.error.visible_missing_share());
      rows.push_back(std::move(r));
    }
    if (progress)
      progress(fmt::format("offset: {}/{} {}{}, {} edge pixels, {} settings, worst error {:.1f}%",
                           i + 1, cases.size(), cases[i].scene,
                           std::isnan(cases[i].tilt) ? "" : fmt::format(" {:g} deg", cases[i].tilt),
                           truth.edge_pixels, settings.size(), 100 * worst));
  }
  return rows;
}

double offset_tilt_error(const std::vector<OffsetRow>& rows, const std::string& knob, double value) {
  double sum = 0;
  size_t n = 0;
  for (const OffsetRow& r : rows)
    if (r.knob == knob && r.value == value && r.scene == "tilt") {
      sum += r.error.hidden_drawn_share() + r.error.visible_missing_share();
      ++n;
    }
  return n ? sum / double(n) : std::numeric_limits<double>::quiet_NaN();
}

double offset_knee(const std::vector<OffsetRow>& rows, const std::string& knob) {
  std::vector<double> values;
  for (const OffsetSetting& s : offset_settings())
    if (s.knob == knob) values.push_back(s.value);
  double least = std::numeric_limits<double>::infinity();
  for (const double v : values) least = std::min(least, offset_tilt_error(rows, knob, v));
  for (const double v : values)
    if (offset_tilt_error(rows, knob, v) <= least + 1e-3) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace zb::lab
