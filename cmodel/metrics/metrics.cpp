#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "color_difference.h"

namespace zb {

ImageError compare_images(const Framebuffer& image, const Framebuffer& reference,
                          std::vector<float>* delta_e) {
  ImageError e;
  const size_t n = image.color.size();
  if (delta_e) delta_e->clear();
  if (n == 0 || n != reference.color.size()) return e;
  if (delta_e) delta_e->assign(n, 0.0f);
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
      if (de > e.delta_e_max) {
        e.delta_e_max = de;
        e.worst_x = int(i % size_t(image.width));
        e.worst_y = int(i / size_t(image.width));
      }
      if (delta_e) (*delta_e)[i] = float(de);
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

}  // namespace zb
