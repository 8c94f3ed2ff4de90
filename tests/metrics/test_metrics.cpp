// Error metrics, the CIEDE2000 colour difference and the supersampled reference, against
// hand-computed and published values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include "metrics/color_difference.h"
#include "metrics/metrics.h"
#include "pipeline/render.h"
#include "reference/reference.h"
#include "scene/builtin_scenes.h"
#include "scene/meshes.h"

namespace {

using zb::Rgba8;

// ---- CIEDE2000: Sharma, Wu and Dalal (2005), Table 1, all 34 pairs, expected to 4 decimals.
struct SharmaPair {
  zb::Lab x, y;
  double delta_e;
};
constexpr SharmaPair kSharma[] = {
    {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
    {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
    {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
    {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
    {{50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}, 2.3669},
    {{50.0000, -1.0000, 2.0000}, {50.0000, 0.0000, 0.0000}, 2.3669},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0009}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0010}, 7.1792},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0011}, 7.2195},
    {{50.0000, 2.4900, -0.0010}, {50.0000, -2.4900, 0.0012}, 7.2195},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0009, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0010, -2.4900}, 4.8045},
    {{50.0000, -0.0010, 2.4900}, {50.0000, 0.0011, -2.4900}, 4.7461},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 0.0000, -2.5000}, 4.3065},
    {{50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}, 27.1492},
    {{50.0000, 2.5000, 0.0000}, {61.0000, -5.0000, 29.0000}, 22.8977},
    {{50.0000, 2.5000, 0.0000}, {56.0000, -27.0000, -3.0000}, 31.9030},
    {{50.0000, 2.5000, 0.0000}, {58.0000, 24.0000, 15.0000}, 19.4535},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.1736, 0.5854}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2972, 0.0000}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 1.8634, 0.5757}, 1.0000},
    {{50.0000, 2.5000, 0.0000}, {50.0000, 3.2592, 0.3350}, 1.0000},
    {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
    {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
    {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
    {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
    {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
    {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
    {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
    {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
};

TEST(Ciede2000, SharmaWuDalalTable1) {
  int pair = 1;
  for (const SharmaPair& p : kSharma) {
    EXPECT_NEAR(zb::ciede2000(p.x, p.y), p.delta_e, 5e-5) << "pair " << pair;
    EXPECT_NEAR(zb::ciede2000(p.y, p.x), p.delta_e, 5e-5) << "pair " << pair << " swapped";
    ++pair;
  }
}

// Neutral colours: only lightness differs, and at mean L = 50 the weight S_L is 1, so the
// difference is the lightness difference itself.
TEST(Ciede2000, NeutralLightnessAroundFifty) {
  EXPECT_NEAR(zb::ciede2000({0, 0, 0}, {100, 0, 0}), 100.0, 1e-9);
  EXPECT_NEAR(zb::ciede2000({40, 0, 0}, {60, 0, 0}), 20.0, 1e-9);
  EXPECT_EQ(zb::ciede2000({37, 12, -5}, {37, 12, -5}), 0.0);
}

// ---- sRGB to CIELAB, against values worked by hand from the sRGB curve, the sRGB-to-XYZ
// matrix and the CIELAB formulas.
TEST(SrgbToLab, WhiteBlackGreyAndPrimaries) {
  const zb::Lab white = zb::srgb8_to_lab({255, 255, 255, 255});
  EXPECT_NEAR(white.L, 100.0, 1e-3);
  EXPECT_NEAR(white.a, 0.0, 1e-3);
  EXPECT_NEAR(white.b, 0.0, 1e-3);
  const zb::Lab black = zb::srgb8_to_lab({0, 0, 0, 255});
  EXPECT_NEAR(black.L, 0.0, 1e-9);
  EXPECT_NEAR(black.a, 0.0, 1e-9);
  EXPECT_NEAR(black.b, 0.0, 1e-9);
  // 128: linear ((128/255 + 0.055) / 1.055)^2.4 = 0.215861, L = 116 * 0.215861^(1/3) - 16.
  const zb::Lab grey = zb::srgb8_to_lab({128, 128, 128, 0});
  EXPECT_NEAR(grey.L, 53.585, 2e-3);
  EXPECT_NEAR(grey.a, 0.0, 1e-3);
  EXPECT_NEAR(grey.b, 0.0, 1e-3);
  // Red: XYZ = (0.41246, 0.21267, 0.01933), white (0.95047, 1, 1.08883).
  const zb::Lab red = zb::srgb8_to_lab({255, 0, 0, 255});
  EXPECT_NEAR(red.L, 53.24, 0.01);
  EXPECT_NEAR(red.a, 80.09, 0.01);
  EXPECT_NEAR(red.b, 67.20, 0.01);
  // Blue: XYZ = (0.18044, 0.07218, 0.95030).
  const zb::Lab blue = zb::srgb8_to_lab({0, 0, 255, 255});
  EXPECT_NEAR(blue.L, 32.30, 0.01);
  EXPECT_NEAR(blue.a, 79.19, 0.01);
  EXPECT_NEAR(blue.b, -107.86, 0.01);
}

TEST(SrgbToLab, TransferCurve) {
  EXPECT_EQ(zb::srgb8_to_linear(0), 0.0);
  EXPECT_NEAR(zb::srgb8_to_linear(255), 1.0, 1e-12);
  EXPECT_NEAR(zb::srgb8_to_linear(10), 10.0 / 255.0 / 12.92, 1e-12);  // linear segment
  EXPECT_NEAR(zb::srgb8_to_linear(128), 0.2158605, 1e-6);
}

// ---- Frame metrics on hand-made 2x2 frames.
zb::Framebuffer frame(std::initializer_list<Rgba8> pixels) {
  zb::Framebuffer fb(2, 2, zb::kDefaultDepthBits, Rgba8{0, 0, 0, 255});
  fb.color.assign(pixels);
  return fb;
}

// Channel differences: 0; 3; 20; 1, 1, 1. Sum of squares 9 + 400 + 3 = 412 over 12 channel
// values: RMSE sqrt(412 / 12) = 5.859465, PSNR 20 log10(255 / 5.859465) = 32.773644 dB.
TEST(ImageError, HandComputedFrame) {
  const Rgba8 g{100, 100, 100, 255};
  const zb::Framebuffer ref = frame({g, g, g, g});
  const zb::Framebuffer img = frame({g, {103, 100, 100, 255}, {100, 80, 100, 255}, {101, 101, 101, 255}});
  const zb::ImageError e = zb::compare_images(img, ref);
  EXPECT_NEAR(e.rmse, 5.859465, 1e-6);
  EXPECT_NEAR(e.psnr, 32.773644, 1e-6);
  EXPECT_EQ(e.max_abs, 20);
  EXPECT_DOUBLE_EQ(e.share_over_2, 0.5);    // the pixels off by 3 and by 20
  EXPECT_DOUBLE_EQ(e.share_over_16, 0.25);  // the one off by 20
  EXPECT_GT(e.delta_e_mean, 0.0);
}

TEST(ImageError, IdenticalFramesHaveNoError) {
  const zb::Framebuffer f = frame({{1, 2, 3, 255}, {40, 50, 60, 255}, {255, 0, 9, 255}, {7, 7, 7, 0}});
  const zb::ImageError e = zb::compare_images(f, f);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr));
  EXPECT_EQ(e.max_abs, 0);
  EXPECT_EQ(e.share_over_2, 0.0);
  EXPECT_EQ(e.delta_e_mean, 0.0);
  EXPECT_EQ(e.delta_e_max, 0.0);
  EXPECT_EQ(e.worst_x, -1);  // no worst pixel to point at
  EXPECT_EQ(e.worst_y, -1);
  std::vector<float> de{1, 2};
  zb::compare_images(f, f, &de);
  EXPECT_EQ(de, std::vector<float>(4, 0.0f));
}

// The worst pixel: the one of the largest CIEDE2000, the first in row-major order on a tie, and
// the per-pixel values are the ones the mean and the largest are of.
TEST(ImageError, WorstPixelAndPerPixelDeltaE) {
  const Rgba8 w{255, 255, 255, 255};
  const zb::Framebuffer ref = frame({w, w, w, w});  // 2x2
  const zb::Framebuffer img = frame({{250, 255, 255, 255}, w, {0, 0, 0, 255}, {0, 0, 0, 255}});
  std::vector<float> de;
  const zb::ImageError e = zb::compare_images(img, ref, &de);
  EXPECT_EQ(e.worst_x, 0);  // (0, 1): row 1, the first of the two black pixels
  EXPECT_EQ(e.worst_y, 1);
  ASSERT_EQ(de.size(), 4u);
  EXPECT_EQ(de[1], 0.0f);
  EXPECT_GT(de[0], 0.0f);
  EXPECT_FLOAT_EQ(de[2], float(e.delta_e_max));
  EXPECT_FLOAT_EQ(de[3], de[2]);
  EXPECT_NEAR((de[0] + de[2] + de[3]) / 4.0, e.delta_e_mean, 1e-4);
}

// One pixel black where the reference is white: CIEDE2000 100 (L 0 against 100, mean L 50 so
// S_L = 1), the other three exact: mean 25. Alpha is not compared.
TEST(ImageError, DeltaEMeanAndMax) {
  const Rgba8 w{255, 255, 255, 255};
  const zb::Framebuffer ref = frame({w, w, w, w});
  const zb::Framebuffer img = frame({{0, 0, 0, 255}, w, w, {255, 255, 255, 0}});
  const zb::ImageError e = zb::compare_images(img, ref);
  EXPECT_NEAR(e.delta_e_max, 100.0, 1e-3);
  EXPECT_NEAR(e.delta_e_mean, 25.0, 1e-3);
  EXPECT_NEAR(e.rmse, std::sqrt(3.0 * 255 * 255 / 12.0), 1e-9);  // 127.5
  EXPECT_EQ(e.max_abs, 255);
}

// A black quad covering world x in [-2, 0] in front of a white background, seen head-on from
// (0, 0, 5): x = 0 projects to the middle of the frame, so in a 3x3 frame the edge runs down
// the middle of column 1 (window x 1.5).
zb::Scene half_covered_scene() {
  zb::Scene s;
  s.materials.push_back({"black", {0, 0, 0, 255}});
  zb::Object o;
  o.mesh = zb::make_quad(1.0f, 1.0f);
  o.transform = glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 0.0f, 0.0f));
  s.objects.push_back(o);
  s.camera.eye = {0, 0, 5};
  s.background = {255, 255, 255, 255};
  return s;
}

// At factor 2 the centre pixel's four sub-pixel centres sit at x 1.25 and 1.75: two black, two
// white, so its colour is 255 / 2 = 127.5, rounded to 128. Factor 4: eight of sixteen, the same.
TEST(SupersampledReference, HalfCoveredPixelIsTheMean) {
  const zb::Viewport vp{3, 3, zb::kDefaultDepthBits};
  for (int factor : {2, 4}) {
    const zb::Framebuffer fb = zb::render_reference_supersampled(half_covered_scene(), vp, factor);
    ASSERT_EQ(fb.width, 3);
    ASSERT_EQ(fb.height, 3);
    EXPECT_EQ(fb.color_at(1, 1), (zb::Rgba8{128, 128, 128, 255})) << "factor " << factor;
    EXPECT_EQ(fb.color_at(0, 1), (zb::Rgba8{0, 0, 0, 255})) << "factor " << factor;
    EXPECT_EQ(fb.color_at(2, 1), (zb::Rgba8{255, 255, 255, 255})) << "factor " << factor;
    EXPECT_LT(fb.depth_at(1, 1), zb::depth_max(vp.depth_bits));  // nearest sub-pixel: the quad
    EXPECT_EQ(fb.depth_at(2, 1), zb::depth_max(vp.depth_bits));
  }
  // Without supersampling the centre (1.5, 1.5) is on the edge: all or nothing.
  const zb::Rgba8 c = zb::render_reference_supersampled(half_covered_scene(), vp, 1).color_at(1, 1);
  EXPECT_TRUE(c.r == 0 || c.r == 255);
}

// The banded reference against the whole frame's: the exact reference of the scene at the
// enlarged size, box-filtered here, on one thread and on three (bands straddled by triangles,
// a last band shorter than the rest).
TEST(SupersampledReference, BandsAreTheWholeFramesReference) {
  const zb::Scene scene = *zb::builtin_scene("cad");
  const zb::Viewport vp{37, 29, zb::kDefaultDepthBits};
  const int factor = 3;
  zb::Viewport big = vp;
  big.width *= factor;
  big.height *= factor;
  const zb::Framebuffer whole = zb::render_reference(zb::rasterize_scene(scene, big));
  for (int threads : {1, 3}) {
    const zb::Framebuffer fb = zb::render_reference_supersampled(scene, vp, factor, threads);
    for (int y = 0; y < vp.height; ++y)
      for (int x = 0; x < vp.width; ++x) {
        int sum[3] = {0, 0, 0};
        uint32_t nearest = zb::depth_max(vp.depth_bits);
        for (int s = 0; s < factor * factor; ++s) {
          const int bx = x * factor + s % factor, by = y * factor + s / factor;
          const zb::Rgba8 c = whole.color_at(bx, by);
          sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
          nearest = std::min(nearest, whole.depth_at(bx, by));
        }
        // The whole frame's sub-pixels are rounded once already: within one of the mean.
        const zb::Rgba8 got = fb.color_at(x, y);
        const int want[3] = {sum[0] / 9, sum[1] / 9, sum[2] / 9};
        ASSERT_LE(std::abs(got.r - want[0]), 1) << x << "," << y << " threads " << threads;
        ASSERT_LE(std::abs(got.g - want[1]), 1) << x << "," << y << " threads " << threads;
        ASSERT_LE(std::abs(got.b - want[2]), 1) << x << "," << y << " threads " << threads;
        ASSERT_EQ(fb.depth_at(x, y), nearest) << x << "," << y << " threads " << threads;
      }
    if (threads == 3) {
      const zb::Framebuffer one = zb::render_reference_supersampled(scene, vp, factor, 1);
      EXPECT_EQ(fb.color, one.color);
    }
  }
}

TEST(SupersampledReference, RejectsBadFactors) {
  const zb::Viewport vp{3, 3, zb::kDefaultDepthBits};
  EXPECT_THROW(zb::render_reference_supersampled(half_covered_scene(), vp, 0), std::invalid_argument);
  const zb::Viewport wide{zb::kMaxFrameSize / 2 + 1, 2, zb::kDefaultDepthBits};
  EXPECT_THROW(zb::render_reference_supersampled(half_covered_scene(), wide, 2), std::invalid_argument);
}

}  // namespace
