#include "color_difference.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace zb {
namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180.0; }
double deg(double rad) { return rad * 180.0 / kPi; }

// Linear sRGB to XYZ, the D65 matrix of the sRGB primaries.
constexpr double kToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                 {0.2126729, 0.7151522, 0.0721750},
                                 {0.0193339, 0.1191920, 0.9503041}};

// The white point is the matrix applied to RGB (1, 1, 1), so white lands exactly on a = b = 0.
constexpr double kWhite[3] = {kToXyz[0][0] + kToXyz[0][1] + kToXyz[0][2],
                              kToXyz[1][0] + kToXyz[1][1] + kToXyz[1][2],
                              kToXyz[2][0] + kToXyz[2][1] + kToXyz[2][2]};

double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// Hue angle in degrees, [0, 360); 0 for a neutral colour.
double hue_deg(double b, double a) {
  if (a == 0 && b == 0) return 0;
  const double h = deg(std::atan2(b, a));
  return h < 0 ? h + 360.0 : h;
}

double pow7(double v) {
  const double v2 = v * v;
  return v2 * v2 * v2 * v;
}

}  // namespace

double srgb8_to_linear(uint8_t v) {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[i] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return t;
  }();
  return table[v];
}

Lab srgb8_to_lab(Rgba8 c) {
  const double rgb[3] = {srgb8_to_linear(c.r), srgb8_to_linear(c.g), srgb8_to_linear(c.b)};
  double f[3];
  for (int i = 0; i < 3; ++i) {
    const double xyz = kToXyz[i][0] * rgb[0] + kToXyz[i][1] * rgb[1] + kToXyz[i][2] * rgb[2];
    f[i] = lab_f(xyz / kWhite[i]);
  }
  return {116.0 * f[1] - 16.0, 500.0 * (f[0] - f[1]), 200.0 * (f[1] - f[2])};
}

bool lab_to_srgb8(const Lab& lab, Rgba8& out) {
  constexpr double d = 6.0 / 29.0;
  auto finv = [](double t) { return t > d ? t * t * t : 3.0 * d * d * (t - 4.0 / 29.0); };
  const double fy = (lab.L + 16.0) / 116.0;
  const double xyz[3] = {kWhite[0] * finv(fy + lab.a / 500.0), kWhite[1] * finv(fy),
                         kWhite[2] * finv(fy - lab.b / 200.0)};
  // The inverse of kToXyz (the sRGB primaries' D65 matrix).
  static constexpr double kToRgb[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                          {-0.9692660, 1.8760108, 0.0415560},
                                          {0.0556434, -0.2040259, 1.0572252}};
  uint8_t v[3];
  for (int i = 0; i < 3; ++i) {
    const double lin = kToRgb[i][0] * xyz[0] + kToRgb[i][1] * xyz[1] + kToRgb[i][2] * xyz[2];
    if (lin < -1e-4 || lin > 1.0 + 1e-4) return false;
    const double c = std::clamp(lin, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    v[i] = static_cast<uint8_t>(std::lround(255.0 * s));
  }
  out = Rgba8{v[0], v[1], v[2], 255};
  return true;
}

double ciede2000(const Lab& x, const Lab& y) {
  const double k25_7 = pow7(25.0);
  // a' stretches a* for near-neutral colours (G), which evens out hue near the grey axis.
  const double c_mean = (std::hypot(x.a, x.b) + std::hypot(y.a, y.b)) / 2.0;
  const double g = 0.5 * (1.0 - std::sqrt(pow7(c_mean) / (pow7(c_mean) + k25_7)));
  const double a1 = (1.0 + g) * x.a, a2 = (1.0 + g) * y.a;
  const double c1 = std::hypot(a1, x.b), c2 = std::hypot(a2, y.b);
  const double h1 = hue_deg(x.b, a1), h2 = hue_deg(y.b, a2);

  const double dl = y.L - x.L;
  const double dc = c2 - c1;
  double dh = 0;
  if (c1 * c2 != 0) {
    dh = h2 - h1;
    if (dh > 180.0) dh -= 360.0;
    else if (dh < -180.0) dh += 360.0;
  }
  const double dH = 2.0 * std::sqrt(c1 * c2) * std::sin(rad(dh) / 2.0);

  const double l_bar = (x.L + y.L) / 2.0;
  const double c_bar = (c1 + c2) / 2.0;
  double h_bar = h1 + h2;
  if (c1 * c2 != 0) {
    if (std::fabs(h1 - h2) <= 180.0) h_bar = (h1 + h2) / 2.0;
    else if (h1 + h2 < 360.0) h_bar = (h1 + h2 + 360.0) / 2.0;
    else h_bar = (h1 + h2 - 360.0) / 2.0;
  }
  const double t = 1.0 - 0.17 * std::cos(rad(h_bar - 30.0)) + 0.24 * std::cos(rad(2.0 * h_bar)) +
                   0.32 * std::cos(rad(3.0 * h_bar + 6.0)) - 0.20 * std::cos(rad(4.0 * h_bar - 63.0));
  const double d_theta = 30.0 * std::exp(-std::pow((h_bar - 275.0) / 25.0, 2.0));
  const double r_c = 2.0 * std::sqrt(pow7(c_bar) / (pow7(c_bar) + k25_7));
  const double l50 = (l_bar - 50.0) * (l_bar - 50.0);
  const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double s_c = 1.0 + 0.045 * c_bar;
  const double s_h = 1.0 + 0.015 * c_bar * t;
  const double r_t = -std::sin(rad(2.0 * d_theta)) * r_c;

  const double tl = dl / s_l, tc = dc / s_c, th = dH / s_h;
  return std::sqrt(tl * tl + tc * tc + th * th + r_t * tc * th);
}

double delta_e2000(Rgba8 x, Rgba8 y) {
  if (x.r == y.r && x.g == y.g && x.b == y.b) return 0;
  return ciede2000(srgb8_to_lab(x), srgb8_to_lab(y));
}

}  // namespace zb
