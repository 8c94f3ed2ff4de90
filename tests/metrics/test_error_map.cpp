// Error maps (cmodel/metrics/error_map.h): the scale, the worst pixel, the picture and its
// legend, the hidden-line map's two colours; CIELAB back to sRGB.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "metrics/color_difference.h"
#include "metrics/error_map.h"

namespace zb {
namespace {

size_t count(const Framebuffer& fb, Rgba8 c, int y0 = 0, int y1 = 1 << 30) {
  size_t n = 0;
  for (int y = y0; y < std::min(fb.height, y1); ++y)
    for (int x = 0; x < fb.width; ++x) n += fb.color[fb.index(x, y)] == c;
  return n;
}

TEST(LabToSrgb, InvertsSrgbToLabAndRefusesOutOfGamut) {
  for (const Rgba8 c : {Rgba8{0, 0, 0, 255}, Rgba8{255, 255, 255, 255}, Rgba8{200, 30, 7, 255},
                        Rgba8{12, 250, 99, 255}, Rgba8{0, 0, 255, 255}}) {
    Rgba8 back;
    ASSERT_TRUE(lab_to_srgb8(srgb8_to_lab(c), back));
    EXPECT_EQ(back, c);
  }
  Rgba8 out;
  EXPECT_FALSE(lab_to_srgb8(Lab{50, 150, 0}, out));  // far beyond sRGB's red
  EXPECT_FALSE(lab_to_srgb8(Lab{100, 0, 100}, out));
}

TEST(ErrorMap, RampIsPerceptuallyUniform) {
  EXPECT_EQ(error_ramp(0.0), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(error_ramp(1e9), error_ramp(1.0));
  EXPECT_EQ(error_ramp(-3), error_ramp(0));
  EXPECT_EQ(error_ramp(std::nan("")), error_ramp(0));
  EXPECT_GT(srgb8_to_lab(error_ramp(1.0)).L, 95.0);  // pale yellow, nearly white
  // Perceptually uniform: CIELAB lightness rises at every step of 1/32, and neighbours 1/64
  // apart differ by about the same CIEDE2000 (1.4 to 3.1 as built; 8-bit rounding and
  // CIEDE2000's own unevenness keep them from being equal).
  double last_l = -1;
  for (int k = 0; k <= 32; ++k) {
    const double l = srgb8_to_lab(error_ramp(k / 32.0)).L;
    EXPECT_GT(l, last_l) << k;
    last_l = l;
  }
  for (int k = 1; k <= 64; ++k) {
    const double step = delta_e2000(error_ramp((k - 1) / 64.0), error_ramp(k / 64.0));
    EXPECT_GT(step, 1.0) << k;
    EXPECT_LT(step, 4.0) << k;
  }

}

TEST(ErrorMap, NiceScaleRoundsUpToOneTwoOrFive) {
  EXPECT_EQ(nice_error_scale(0), kMinErrorScale);
  EXPECT_EQ(nice_error_scale(0.3), 1.0);
  EXPECT_EQ(nice_error_scale(1.0), 1.0);
  EXPECT_EQ(nice_error_scale(1.2), 2.0);
  EXPECT_EQ(nice_error_scale(3.0), 5.0);
  EXPECT_EQ(nice_error_scale(7.0), 10.0);
  EXPECT_EQ(nice_error_scale(50.0), 50.0);
  EXPECT_EQ(nice_error_scale(51.0), 100.0);
}

TEST(ErrorMap, PercentileAndWorstPixel) {
  std::vector<float> v(100);
  for (size_t i = 0; i < v.size(); ++i) v[i] = float(i + 1);  // 1..100
  EXPECT_EQ(percentile(v, 0.99), 99.0);
  EXPECT_EQ(percentile(v, 1.0), 100.0);
  EXPECT_EQ(percentile(v, 0.0), 1.0);
  EXPECT_EQ(percentile({}, 0.5), 0.0);
  // Mostly exact maps (zeros first, the rest ordered), and values below 0 (all ordered).
  const std::vector<float> z{0, 0, 0, 5, 1, 0, 3};  // sorted: 0 0 0 0 1 3 5
  EXPECT_EQ(percentile(z, 0.5), 0.0);
  EXPECT_EQ(percentile(z, 0.75), 3.0);
  EXPECT_EQ(percentile(z, 0.9), 5.0);
  EXPECT_EQ(percentile({-1, 0, 2}, 0.1), -1.0);
  EXPECT_EQ(percentile({-1, 0, 2}, 0.5), 0.0);
  EXPECT_EQ(percentile({0, 0}, 1.0), 0.0);
  // Maps side by side: the largest 99th percentile (99 here; an empty map counts 0), rounded up.
  EXPECT_EQ(shared_error_scale({{}, v, std::vector<float>(10, 3.0f)}), 100.0);
  EXPECT_EQ(shared_error_scale({{}, std::vector<float>(10, 3.0f)}), 5.0);
  EXPECT_EQ(shared_error_scale({}), kMinErrorScale);
  const std::vector<float> m = {0, 1, 5, 2, 5, 0};  // 3 x 2: the first 5 is at (2, 0)
  EXPECT_EQ(worst_pixel(m, 3), (std::pair<int, int>{2, 0}));
}

TEST(ErrorMap, PixelsOnTheRampAndALegendBelow) {
  constexpr int w = 30, h = 20;
  std::vector<float> de(size_t(w) * h, 0.0f);
  de[size_t(5) * w + 7] = 10;   // (7, 5): full scale
  de[size_t(15) * w + 20] = 5;  // (20, 15): half
  const Framebuffer fb = error_map_image(de, w, h, 10.0);
  ASSERT_EQ(fb.width, kLegendWidth);  // a narrow frame gets room for its legend
  ASSERT_GT(fb.height, h);
  EXPECT_EQ(fb.color_at(0, 0), kExactColor);  // no error: not the ramp's black
  EXPECT_EQ(fb.color_at(7, 5), error_ramp(1));
  EXPECT_EQ(fb.color_at(20, 15), error_ramp(0.5));
  // The legend: its ramp shows the brightest colour, and text strokes are drawn.
  EXPECT_GT(count(fb, error_ramp(1), h, fb.height), 0u);
  EXPECT_GT(count(fb, Rgba8{230, 230, 230, 255}, h, fb.height), 20u);
  EXPECT_EQ(count(fb, Rgba8{0, 255, 255, 255}), 0u);  // no ring unasked
  const Framebuffer marked = error_map_image(de, w, h, 10.0, std::pair<int, int>{7, 5});
  EXPECT_GT(count(marked, Rgba8{0, 255, 255, 255}, 0, h), 20u);
  EXPECT_EQ(marked.color_at(7, 5), error_ramp(1));  // the ring leaves the pixel itself
}

// An exact pixel is told apart from the smallest error, and the ramp never takes its colour; a
// map with no error and one with an error say so in their legends (text drawn differs).
TEST(ErrorMap, ExactPixelsStandApart) {
  for (int i = 0; i <= 1000; ++i) ASSERT_NE(error_ramp(i / 1000.0), kExactColor) << i;
  constexpr int w = 40, h = 10;
  std::vector<float> de(size_t(w) * h, 0.0f);
  const Framebuffer exact = error_map_image(de, w, h, 50.0);
  EXPECT_EQ(count(exact, kExactColor, 0, h), size_t(w) * h);
  de[3] = 0.01f;
  const Framebuffer tiny = error_map_image(de, w, h, 50.0);
  EXPECT_NE(tiny.color_at(3, 0), kExactColor);
  EXPECT_EQ(tiny.color_at(3, 0), error_ramp(0.01 / 50.0));
  const Rgba8 text{230, 230, 230, 255};
  EXPECT_NE(count(exact, text, h, exact.height), count(tiny, text, h, tiny.height));
  // The legend's own swatch of the exact colour.
  EXPECT_GT(count(exact, kExactColor, h, exact.height), 50u);
}

TEST(ErrorMap, LegendTicks) {
  EXPECT_EQ(error_scale_ticks(50), (std::vector<double>{0, 10, 20, 30, 40, 50}));
  EXPECT_EQ(error_scale_ticks(2), (std::vector<double>{0, 0.5, 1, 1.5, 2}));
  const std::vector<double> one = error_scale_ticks(1);
  ASSERT_EQ(one.size(), 6u);
  for (size_t i = 0; i < one.size(); ++i) EXPECT_NEAR(one[i], 0.2 * double(i), 1e-12);
  EXPECT_EQ(error_scale_ticks(7), (std::vector<double>{0, 1.75, 3.5, 5.25, 7}));
  EXPECT_EQ(error_scale_ticks(0), (std::vector<double>{0}));
  // Drawn: a tick mark under the ramp at each inner value.
  constexpr int w = 400, h = 4;
  const Framebuffer fb = error_map_image(std::vector<float>(size_t(w) * h, 1.0f), w, h, 50.0);
  const Rgba8 text{230, 230, 230, 255};
  int marks = 0;
  const int row = h + 4 + 10 + 1;  // just under the ramp
  for (int x = 0; x + 1 < fb.width; ++x) marks += fb.color_at(x, row) == text && fb.color_at(x + 1, row) != text;
  EXPECT_EQ(marks, 5);  // 0, 10, 20, 30, 40 (50 is the end label's)
}

TEST(ErrorMap, DeltaEMapIsPerPixel) {
  Framebuffer a(2, 1, kDefaultDepthBits, Rgba8{255, 255, 255, 255});
  Framebuffer b = a;
  b.color[1] = Rgba8{0, 0, 0, 255};
  const std::vector<float> de = delta_e_map(b, a);
  ASSERT_EQ(de.size(), 2u);
  EXPECT_EQ(de[0], 0.0f);
  EXPECT_NEAR(de[1], 100.0, 1e-3);
  EXPECT_TRUE(delta_e_map(Framebuffer(3, 1, 24, Rgba8{}), a).empty());
}

TEST(ErrorMap, LineMapShowsHiddenDrawnAndVisibleMissing) {
  LineVisibility ref;
  ref.width = 4;
  ref.height = 1;
  ref.pixels = {EdgePixel::kHidden, EdgePixel::kVisible, EdgePixel::kHidden, EdgePixel::kVisible};
  const Rgba8 edge{0, 0, 0, 255}, bg{255, 255, 255, 255};
  Framebuffer img(4, 1, kDefaultDepthBits, bg);
  img.color = {edge, edge, bg, bg};  // hidden drawn, visible right, hidden right, visible missing
  const Framebuffer fb = line_error_map_image(img, ref, edge);
  EXPECT_EQ(fb.color_at(0, 0), kHiddenDrawnColor);
  EXPECT_EQ(fb.color_at(3, 0), kVisibleMissingColor);
  EXPECT_NE(fb.color_at(1, 0), kVisibleMissingColor);
  EXPECT_NE(fb.color_at(2, 0), kHiddenDrawnColor);
  // The legend's swatches.
  EXPECT_GT(count(fb, kHiddenDrawnColor, 1, fb.height), 50u);
  EXPECT_GT(count(fb, kVisibleMissingColor, 1, fb.height), 50u);
  // The greys of edges drawn right are named too.
  EXPECT_EQ(fb.color_at(1, 0), kVisibleRightColor);
  EXPECT_EQ(fb.color_at(2, 0), kHiddenRightColor);
  EXPECT_GT(count(fb, kVisibleRightColor, 1, fb.height), 50u);
  EXPECT_GT(count(fb, kHiddenRightColor, 1, fb.height), 50u);
}

}  // namespace
}  // namespace zb
