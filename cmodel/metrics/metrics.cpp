#include "metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "color_difference.h"

namespace zb {

ImageError compare_images(const Framebuffer& image, const Framebuffer& reference) {
  ImageError e;
  const size_t n = image.color.size();
  if (n == 0 || n != reference.color.size()) return e;
  double sum_sq = 0, sum_de = 0;
  size_t over2 = 0, over16 = 0;
  for (size_t i = 0; i < n; ++i) {
    const Rgba8 a = image.color[i], b = reference.color[i];
    const int d[3] = {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)};
    int worst = 0;
    for (int c : d) {
      sum_sq += double(c) * c;
      worst = std::max(worst, c);
    }
    e.max_abs = std::max(e.max_abs, worst);
    over2 += worst > 2;
    over16 += worst > 16;
    if (worst > 0) {
      const double de = delta_e2000(a, b);
      sum_de += de;
      e.delta_e_max = std::max(e.delta_e_max, de);
    }
  }
  e.rmse = std::sqrt(sum_sq / (3.0 * double(n)));
  e.psnr = e.rmse == 0 ? std::numeric_limits<double>::infinity()
                       : 20.0 * std::log10(255.0 / e.rmse);
  e.share_over_2 = double(over2) / double(n);
  e.share_over_16 = double(over16) / double(n);
  e.delta_e_mean = sum_de / double(n);
  return e;
}

Rgba8 error_ramp(double t) {
  // A path through CIELAB: lightness 0 to 97 (black to pale yellow), the hue turning from violet
  // (300 degrees) through red and orange to yellow (100), at the largest chroma up to 70 sRGB
  // holds. Its 256 entries are spaced evenly along the path's CIEDE2000 length, so every step
  // looks alike; lightness rises throughout, so brighter reads as worse.
  static const std::array<Rgba8, 256> ramp = [] {
    constexpr int kFine = 4096;
    std::vector<Rgba8> path(kFine + 1);
    std::vector<double> length(kFine + 1, 0.0);
    for (int k = 0; k <= kFine; ++k) {
      const double u = double(k) / kFine;
      const double L = 97.0 * u, h = (300.0 + 160.0 * u) * 3.14159265358979323846 / 180.0;
      double lo = 0, hi = k ? 70.0 : 0.0;  // black at 0
      Rgba8 c{0, 0, 0, 255};
      lab_to_srgb8(Lab{L, 0, 0}, c);
      for (int i = 0; i < 20 && k; ++i) {
        const double mid = 0.5 * (lo + hi);
        Rgba8 m;
        if (lab_to_srgb8(Lab{L, mid * std::cos(h), mid * std::sin(h)}, m)) {
          lo = mid;
          c = m;
        } else {
          hi = mid;
        }
      }
      path[size_t(k)] = c;
      if (k) length[size_t(k)] = length[size_t(k) - 1] + delta_e2000(path[size_t(k) - 1], c);
    }
    std::array<Rgba8, 256> r{};
    size_t k = 0;
    for (size_t i = 0; i < r.size(); ++i) {
      const double at = length.back() * double(i) / double(r.size() - 1);
      while (k < size_t(kFine) && length[k] < at) ++k;
      r[i] = path[k];
    }
    return r;
  }();
  const double u = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0);
  return ramp[size_t(std::lround(u * double(ramp.size() - 1)))];
}

Rgba8 error_color(double delta_e) { return error_ramp(delta_e / kErrorImageFullScale); }

Framebuffer error_image(const Framebuffer& image, const Framebuffer& reference) {
  Framebuffer out(reference.width, reference.height, reference.depth_bits, Rgba8{0, 0, 0, 255});
  if (image.color.size() != reference.color.size()) return out;
  for (size_t i = 0; i < out.color.size(); ++i)
    out.color[i] = error_color(delta_e2000(image.color[i], reference.color[i]));
  return out;
}

}  // namespace zb
