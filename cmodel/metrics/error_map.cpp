#include "error_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include <fmt/core.h>

#include <stb_easy_font.h>

#include "color_difference.h"
#include "line_metrics.h"

namespace zb {

namespace {

constexpr int kStrip = 44;  // the legend strip's height: the ramp and its ticks, then a line of text
constexpr Rgba8 kBlack{0, 0, 0, 255};
constexpr Rgba8 kText{230, 230, 230, 255};

void fill(Framebuffer& fb, int x0, int y0, int x1, int y1, Rgba8 c) {
  for (int y = std::max(0, y0); y < std::min(fb.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(fb.width, x1); ++x) fb.color[fb.index(x, y)] = c;
}

int text_width(std::string text) { return stb_easy_font_width(text.data()); }

// `text` at (x, y), top-left, in stb_easy_font's built-in strokes (no font file). Returns the
// x just past it.
int draw_text(Framebuffer& fb, int x, int y, const std::string& text, Rgba8 c) {
  std::string s = text;
  static thread_local std::vector<char> buffer(64 * 1024);
  const int quads = stb_easy_font_print(float(x), float(y), s.data(), nullptr, buffer.data(),
                                        int(buffer.size()));
  struct Vertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  const auto* v = reinterpret_cast<const Vertex*>(buffer.data());
  for (int q = 0; q < quads; ++q) {
    const Vertex* a = v + 4 * q;  // corners 0 and 2 are opposite
    fill(fb, int(std::lround(a[0].x)), int(std::lround(a[0].y)), int(std::lround(a[2].x)),
         int(std::lround(a[2].y)), c);
  }
  return x + text_width(text);
}

// A canvas: the frame's pixels above a legend strip, at least kLegendWidth wide, black. A
// picture: the colour plane alone (the others would triple a map's memory).
Framebuffer canvas(int width, int height) {
  Framebuffer fb(0, 0, kDefaultDepthBits, kBlack);
  fb.width = std::max(width, kLegendWidth);
  fb.height = height + kStrip;
  fb.color.assign(size_t(fb.width) * size_t(fb.height), kBlack);
  return fb;
}

std::string scale_text(double v) {
  return v >= 10 || v == std::floor(v) ? fmt::format("{:.0f}", v) : fmt::format("{:g}", v);
}

}  // namespace

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

std::vector<float> delta_e_map(const Framebuffer& image, const Framebuffer& reference) {
  std::vector<float> de;
  if (image.width != reference.width || image.height != reference.height) return de;
  de.resize(reference.color.size());
  // Flat-shaded frames hold few distinct pairs of colours: each pair's CIEDE2000 once.
  std::unordered_map<uint64_t, float> known;
  auto rgb = [](Rgba8 c) { return uint64_t{c.r} | uint64_t{c.g} << 8 | uint64_t{c.b} << 16; };
  for (size_t i = 0; i < de.size(); ++i) {
    const Rgba8 a = image.color[i], b = reference.color[i];
    if (rgb(a) == rgb(b)) continue;  // 0, as resize left it
    const auto [it, added] = known.try_emplace(rgb(a) << 24 | rgb(b), 0.0f);
    if (added) it->second = float(delta_e2000(a, b));
    de[i] = it->second;
  }
  return de;
}

double percentile(const std::vector<float>& values, double p) {
  if (values.empty()) return 0;
  const double rank = std::ceil(std::clamp(p, 0.0, 1.0) * double(values.size()));
  const size_t k = std::min(values.size() - 1, size_t(std::max(rank, 1.0)) - 1);
  // An error map is mostly exact pixels: with no value below 0, the zeros come first, and only
  // the others need ordering.
  std::vector<float> above;
  size_t zeros = 0;
  bool negative = false;
  for (const float v : values) {
    negative = negative || v < 0;
    if (v == 0) ++zeros; else above.push_back(v);
  }
  if (negative) {
    above = values;
    zeros = 0;
  }
  if (k < zeros) return 0;
  std::nth_element(above.begin(), above.begin() + std::ptrdiff_t(k - zeros), above.end());
  return above[k - zeros];
}

double nice_error_scale(double value) {
  if (!(value > kMinErrorScale)) return kMinErrorScale;
  double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (;; decade *= 10)
    for (const double m : {1.0, 2.0, 5.0})
      if (m * decade >= value * (1 - 1e-12)) return m * decade;
}

double error_scale(const std::vector<float>& map) { return nice_error_scale(percentile(map, 0.99)); }

double shared_error_scale(const std::vector<std::vector<float>>& maps) {
  double top = kMinErrorScale;
  for (const std::vector<float>& m : maps) top = std::max(top, error_scale(m));
  return top;
}

std::optional<std::pair<int, int>> worst_pixel(const std::vector<float>& values, int width) {
  if (values.empty() || width <= 0) return std::nullopt;
  const auto it = std::max_element(values.begin(), values.end());
  if (!(*it > 0)) return std::nullopt;
  const size_t i = size_t(it - values.begin());
  return std::pair<int, int>{int(i % size_t(width)), int(i / size_t(width))};
}

std::vector<double> error_scale_ticks(double scale) {
  if (!(scale > 0)) return {0};
  // 1, 2, 5 x 10^k: steps of a fifth, a quarter, a fifth; any other scale in quarters.
  const double mantissa = scale / std::pow(10.0, std::floor(std::log10(scale)));
  const int steps = std::abs(mantissa - 2) < 1e-9 ? 4 : (std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 5) < 1e-9) ? 5 : 4;
  std::vector<double> t;
  for (int i = 0; i <= steps; ++i) t.push_back(scale * i / steps);
  return t;
}

Framebuffer error_map_image(const std::vector<float>& de, int width, int height, double scale,
                            std::optional<std::pair<int, int>> mark) {
  Framebuffer fb = canvas(width, height);
  const bool sized = de.size() == size_t(width) * size_t(height);
  size_t exact = 0;
  float top = 0;
  if (sized)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float e = de[size_t(y) * size_t(width) + size_t(x)];
        exact += e == 0;
        top = std::max(top, e);
        fb.color[fb.index(x, y)] = e == 0 ? kExactColor : error_ramp(e / scale);
      }
  if (mark) {  // a ring of radius 6, in a colour the ramp never takes
    const auto [mx, my] = *mark;
    for (int a = 0; a < 96; ++a) {
      const double t = a * 2 * 3.14159265358979323846 / 96;
      for (const int r : {6, 7}) {
        const int x = mx + int(std::lround(r * std::cos(t))), y = my + int(std::lround(r * std::sin(t)));
        if (x >= 0 && y >= 0 && x < width && y < height) fb.color[fb.index(x, y)] = Rgba8{0, 255, 255, 255};
      }
    }
  }
  // The legend: the exact colour, the ramp from just above 0 to the scale with its ticks, and a
  // line with this map's own largest error and where it is.
  const int y0 = height + 4, bar = 10;
  fill(fb, 4, y0, 14, y0 + bar, kExactColor);
  const int x = draw_text(fb, 17, y0 + 2, "exact", kText) + 10;
  const std::string end_text = scale_text(scale) + "+";
  const int bar_end = fb.width - 8 - text_width(end_text);
  for (int bx = x; bx < bar_end; ++bx)
    fill(fb, bx, y0, bx + 1, y0 + bar, error_ramp(double(bx - x + 1) / std::max(1, bar_end - x)));
  draw_text(fb, bar_end + 4, y0 + 2, end_text, kText);
  const std::vector<double> ticks = error_scale_ticks(scale);
  int room = bar_end - x;
  for (const double t : ticks) room = std::min(room, (bar_end - x) / std::max<int>(1, int(ticks.size()) - 1) - text_width(scale_text(t)));
  for (size_t i = 0; i + 1 < ticks.size(); ++i) {
    const int tx = x + int(std::lround(ticks[i] / scale * (bar_end - x)));
    fill(fb, tx, y0 + bar, tx + 1, y0 + bar + 3, kText);
    if (room >= 4 || i == 0)
      draw_text(fb, tx - text_width(scale_text(ticks[i])) / 2, y0 + bar + 4, scale_text(ticks[i]), kText);
  }
  std::string line;
  if (!sized) {
    line = "not measured";
  } else if (top == 0) {
    line = "exact at every pixel";
  } else {
    line = fmt::format("max {} dE2000", top >= 10 ? fmt::format("{:.1f}", top) : fmt::format("{:.2f}", top));
    if (const auto w = worst_pixel(de, width)) line += fmt::format(" at ({}, {})", w->first, w->second);
    line += fmt::format("; exact {:.1f}%", 100.0 * double(exact) / double(de.size()));
  }
  draw_text(fb, 4, y0 + bar + 15, line, kText);
  return fb;
}

Framebuffer line_error_map_image(const Framebuffer& image, const LineVisibility& reference,
                                 Rgba8 visible) {
  const int w = reference.width, h = reference.height;
  Framebuffer fb = canvas(w, h);
  if (image.color.size() == reference.pixels.size())
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        static constexpr Rgba8 kColors[] = {kBlack, kHiddenRightColor, kVisibleRightColor,
                                            kHiddenDrawnColor, kVisibleMissingColor};  // LinePixel
        const LinePixel p = line_pixel(image, reference, visible, size_t(y) * size_t(w) + size_t(x));
        fb.color[fb.index(x, y)] = kColors[size_t(p)];
      }
  // Every colour the map takes but black (no edge there: not measured), named.
  const int y0 = h + 4;
  int x = 4;
  const std::pair<Rgba8, const char*> keys[] = {{kHiddenDrawnColor, "hidden drawn"},
                                                 {kVisibleMissingColor, "visible missing"},
                                                 {kVisibleRightColor, "visible ok"},
                                                 {kHiddenRightColor, "hidden ok"}};
  for (size_t k = 0; k < 4; ++k) {
    const int row = y0 + int(k / 2) * 16, col = k % 2 ? x : 4;
    fill(fb, col, row, col + 10, row + 10, keys[k].first);
    const int end = draw_text(fb, col + 14, row + 2, keys[k].second, kText) + 10;
    if (k % 2 == 0) x = std::max(x, end);
  }
  return fb;
}

}  // namespace zb
