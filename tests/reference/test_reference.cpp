// The reference against back-to-front composites computed here in double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "support/layers.h"
#include "reference/reference.h"
#include "scene/builtin_scenes.h"

namespace {

using zb::Rgba8;

struct Colour { double r, g, b; };

Colour composite(Colour under, const std::vector<Rgba8>& back_to_front) {
  for (Rgba8 s : back_to_front) {
    const double a = s.a / 255.0;
    under = {a * s.r + (1 - a) * under.r, a * s.g + (1 - a) * under.g,
             a * s.b + (1 - a) * under.b};
  }
  return under;
}

Rgba8 to_rgba8(Colour c) {
  auto q = [](double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 255.0))); };
  return {q(c.r), q(c.g), q(c.b), 255};
}

TEST(Reference, LayersInAnySubmitOrder) {
  const zbtest::Layer opaque{9000, {40, 60, 200, 255}}, a{1000, {230, 30, 30, 128}},
      b{3000, {30, 200, 40, 90}}, behind{9500, {0, 0, 0, 100}};
  const Rgba8 want = to_rgba8(composite({40, 60, 200}, {b.color, a.color}));
  for (const auto& order : {std::vector<zbtest::Layer>{opaque, a, b, behind},
                            std::vector<zbtest::Layer>{b, behind, a, opaque},
                            std::vector<zbtest::Layer>{a, opaque, behind, b}}) {
    const zb::Framebuffer fb = zb::render_reference(zbtest::layer_scene(order, {255, 255, 255, 255}));
    for (Rgba8 c : fb.color) ASSERT_EQ(c, want);
  }
}

// quads: every quad faces the camera, so each has one depth; order fragments by the depth of
// their object in camera space, not by the rasterizer's depth.
TEST(Reference, QuadsEqualExactBackToFrontComposite) {
  const zb::Scene scene = *zb::builtin_scene("quads");
  const zb::Viewport vp{160, 120, zb::kDefaultDepthBits};
  const zb::RasterizedScene rs = zb::rasterize_scene(scene, vp);
  ASSERT_GT(rs.fragments.size(), 0u);

  std::vector<double> object_distance;  // by prim
  std::vector<Rgba8> material_of_prim;
  const glm::mat4 view = scene.camera.view();
  for (const zb::Object& o : scene.objects) {
    const glm::vec4 c = view * o.transform * glm::vec4(0, 0, 0, 1);
    for (size_t t = 0; t < o.mesh.triangles.size(); ++t) object_distance.push_back(-c.z);
  }

  std::vector<std::vector<size_t>> at(size_t(vp.width) * vp.height);
  for (size_t i = 0; i < rs.fragments.size(); ++i)
    at[size_t(rs.fragments[i].y) * vp.width + rs.fragments[i].x].push_back(i);

  const zb::Framebuffer ref = zb::render_reference(rs);
  size_t layered = 0;
  for (size_t p = 0; p < at.size(); ++p) {
    std::vector<size_t> frags = at[p];
    std::stable_sort(frags.begin(), frags.end(), [&](size_t a, size_t b) {
      return object_distance[rs.fragments[a].prim] > object_distance[rs.fragments[b].prim];
    });  // far to near
    Colour c{double(scene.background.r), double(scene.background.g), double(scene.background.b)};
    std::vector<Rgba8> over;
    for (size_t i : frags) {
      const Rgba8 s = rs.fragments[i].color;
      if (s.a == 255) { c = {double(s.r), double(s.g), double(s.b)}; over.clear(); }
      else over.push_back(s);
    }
    layered += over.size() >= 2;
    ASSERT_EQ(ref.color[p], to_rgba8(composite(c, over))) << "pixel " << p % vp.width << ","
                                                           << p / vp.width;
  }
  EXPECT_GT(layered, 0u) << "quads should overlap somewhere";
}

}  // namespace
