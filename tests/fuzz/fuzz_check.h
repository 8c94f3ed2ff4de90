// What every fuzz target checks. A broken invariant aborts with a message, and libFuzzer saves
// the input as a crash (docs/fuzzing.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pipeline/render.h"
#include "scene/scene.h"

#define FUZZ_CHECK(cond)                                                                 \
  do {                                                                                   \
    if (!(cond)) {                                                                       \
      std::fprintf(stderr, "%s:%d: invariant broken: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                      \
    }                                                                                    \
  } while (0)

namespace zbfuzz {

inline bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A loader's message: one line, "NAME: PLACE: what" or "scene 'NAME': no triangles".
inline void check_scene_error(const std::string& what, const std::string& name) {
  FUZZ_CHECK(what.rfind(name + ": ", 0) == 0 || what == "scene '" + name + "': no triangles");
  FUZZ_CHECK(what.find_first_of("\r\n") == std::string::npos);
}

// A scene as the loaders promise it: triangles, indices and materials in range, a normal per
// position, finite coordinates and transforms, a usable camera.
inline void check_loaded_scene(const zb::Scene& s) {
  FUZZ_CHECK(s.triangle_count() > 0);
  for (const zb::Object& o : s.objects) {
    FUZZ_CHECK(o.material < s.materials.size());
    FUZZ_CHECK(o.mesh.normals.size() == o.mesh.positions.size());
    for (const glm::vec3& p : o.mesh.positions) FUZZ_CHECK(finite3(p));
    for (const glm::vec3& n : o.mesh.normals) FUZZ_CHECK(finite3(n));
    for (const glm::uvec3& t : o.mesh.triangles)
      for (int k = 0; k < 3; ++k) FUZZ_CHECK(t[k] < o.mesh.positions.size());
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) FUZZ_CHECK(std::isfinite(o.transform[c][r]));
  }
  FUZZ_CHECK(std::isfinite(s.camera.near) && std::isfinite(s.camera.far));
  FUZZ_CHECK(s.camera.near > 0.0f && s.camera.far > s.camera.near);
}

// The raster output: fragments inside the viewport with depths inside their triangle's range
// and the depth width, per-triangle and per-line ranges consistent.
inline void check_rasterized(const zb::RasterizedScene& rs, size_t scene_triangles) {
  const zb::Viewport& vp = rs.viewport;
  const uint32_t zmax = zb::depth_max(vp.depth_bits);
  FUZZ_CHECK(rs.first_fragment.size() == rs.triangles.size() + 1);
  FUZZ_CHECK(rs.first_fragment.back() == rs.fragments.size());
  FUZZ_CHECK(rs.z_exact.size() == rs.fragments.size());
  for (size_t i = 0; i < rs.triangles.size(); ++i) {
    const zb::ScreenTriangle& t = rs.triangles[i];
    FUZZ_CHECK(t.prim < scene_triangles);
    uint32_t lo = zmax, hi = 0;
    for (const zb::ScreenVertex& v : t.v) {
      FUZZ_CHECK(v.z <= zmax);
      FUZZ_CHECK(v.z_exact >= 0.0 && v.z_exact <= 1.0);
      lo = std::min(lo, v.z);
      hi = std::max(hi, v.z);
    }
    FUZZ_CHECK(rs.first_fragment[i] <= rs.first_fragment[i + 1]);
    for (size_t f = rs.first_fragment[i]; f < rs.first_fragment[i + 1]; ++f) {
      const zb::Fragment& g = rs.fragments[f];
      FUZZ_CHECK(g.x < vp.width && g.y < vp.height);
      FUZZ_CHECK(g.z >= lo && g.z <= hi);
      FUZZ_CHECK(g.prim == t.prim);
      FUZZ_CHECK(g.coverage == vp.coverage_samples);
      FUZZ_CHECK(rs.z_exact[f] >= -1e-9 && rs.z_exact[f] <= 1.0 + 1e-9);
    }
  }
  FUZZ_CHECK(rs.first_line_fragment.size() == rs.lines.size() + 1);
  FUZZ_CHECK(rs.first_line_fragment.back() == rs.line_fragments.size());
  for (const zb::Fragment& g : rs.line_fragments) {
    FUZZ_CHECK(g.x < vp.width && g.y < vp.height);
    FUZZ_CHECK(g.z <= zmax);
  }
}

}  // namespace zbfuzz
