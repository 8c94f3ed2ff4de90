// The exact hidden-line reference (docs/raster.md, "The hidden-line reference").
#include "line_reference.h"

#include <algorithm>
#include <cstdlib>

#include "raster/internal/edge_functions.h"

namespace zb {
namespace {

__extension__ typedef __int128 i128;

// Faces binned by the pixel cells their vertices' box touches, so that an edge point is
// tested against the few faces that can cover it.
constexpr int kCellPixels = 8;

struct FaceGrid {
  int cols = 0, rows = 0;
  std::vector<std::vector<uint32_t>> cells;
  const std::vector<uint32_t>& at(int64_t x, int64_t y) const {
    return cells[size_t(y / kCellPixels) * size_t(cols) + size_t(x / kCellPixels)];
  }
};

FaceGrid bin_faces(const std::vector<ScreenTriangle>& faces, const Viewport& vp) {
  FaceGrid g;
  g.cols = (vp.width + kCellPixels - 1) / kCellPixels;
  g.rows = (vp.height + kCellPixels - 1) / kCellPixels;
  g.cells.resize(size_t(g.cols) * size_t(g.rows));
  for (size_t i = 0; i < faces.size(); ++i) {
    const ScreenVertex(&v)[3] = faces[i].v;
    auto pixel = [](int64_t c) { return edge::floor_div(c, kSubpixelOne); };
    const int64_t x0 = std::max<int64_t>(0, pixel(std::min({v[0].x, v[1].x, v[2].x})));
    const int64_t x1 = std::min<int64_t>(vp.width - 1, pixel(std::max({v[0].x, v[1].x, v[2].x})));
    const int64_t y0 = std::max<int64_t>(0, pixel(std::min({v[0].y, v[1].y, v[2].y})));
    const int64_t y1 = std::min<int64_t>(vp.height - 1, pixel(std::max({v[0].y, v[1].y, v[2].y})));
    for (int64_t cy = y0 / kCellPixels; cy <= y1 / kCellPixels && x0 <= x1; ++cy)
      for (int64_t cx = x0 / kCellPixels; cx <= x1 / kCellPixels; ++cx)
        g.cells[size_t(cy) * size_t(g.cols) + size_t(cx)].push_back(uint32_t(i));
  }
  return g;
}

bool same_vertex(const ScreenVertex& a, const ScreenVertex& b) {
  return a.x == b.x && a.y == b.y && a.z_exact == b.z_exact;
}

bool adjacent(const ScreenLine& line, const ScreenTriangle& t) {
  return t.prim == line.faces[0].prim || t.prim == line.faces[1].prim;
}

}  // namespace

bool edge_point_hidden(const ScreenLine& line, const LineAxes& axes, const LinePoint& p,
                       const std::vector<ScreenTriangle>& faces,
                       const std::vector<uint32_t>& candidates) {
  // The point Q, in 1/256 pixel times D (exact integers): (M0 + s, m0 + dm s / dM).
  const int64_t dM = axes.dM();
  const i128 D = dM == 0 ? 1 : dM;
  const i128 major = (i128(axes.M0) + p.s) * D;
  const i128 minor = dM == 0 ? i128(axes.m0) : i128(axes.m0) * dM + i128(axes.dm()) * p.s;
  const i128 qx = axes.x_major ? major : minor, qy = axes.x_major ? minor : major;
  const double z_edge =
      dM == 0 ? std::min(axes.start.z_exact, axes.end.z_exact)
              : axes.start.z_exact +
                    (axes.end.z_exact - axes.start.z_exact) * (double(p.s) / double(dM));

  for (const uint32_t i : candidates) {
    const ScreenTriangle& face = faces[i];
    if (adjacent(line, face)) continue;
    // A face through an end vertex meets the edge there: not counted within a pixel of it.
    bool near_shared = false;
    for (const ScreenVertex& end : line.v) {
      const i128 end_major = i128(axes.x_major ? end.x : end.y) * D;
      const i128 gap = major > end_major ? major - end_major : end_major - major;
      if (gap > i128(kSubpixelOne) * D) continue;
      for (const ScreenVertex& fv : face.v) near_shared = near_shared || same_vertex(fv, end);
    }
    if (near_shared) continue;
    edge::OrientedTriangle t;
    if (!edge::orient(face, t)) continue;
    // Edge functions at Q times D; Q is covered, edges included, when all are >= 0.
    i128 w[3];
    for (int k = 0; k < 3; ++k) {
      const ScreenVertex& a = t.v[(k + 1) % 3];
      const ScreenVertex& b = t.v[(k + 2) % 3];
      w[k] = i128(int64_t{b.x} - a.x) * (qy - i128(a.y) * D) -
             i128(int64_t{b.y} - a.y) * (qx - i128(a.x) * D);
    }
    if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
    const double z_face = (double(w[0]) * t.v[0].z_exact + double(w[1]) * t.v[1].z_exact +
                           double(w[2]) * t.v[2].z_exact) /
                          (double(t.area) * double(D));
    if (z_face < z_edge - kLineDepthTolerance) return true;
  }
  return false;
}

LineVisibility line_visibility(const std::vector<ScreenTriangle>& faces,
                               const std::vector<ScreenLine>& lines, const Viewport& vp) {
  LineVisibility v;
  v.width = vp.width;
  v.height = vp.height;
  v.pixels.assign(size_t(vp.width) * size_t(vp.height), EdgePixel::kNone);
  const FaceGrid grid = bin_faces(faces, vp);
  for (const ScreenLine& line : lines) {
    walk_line(line.v[0], line.v[1], vp, {}, [&](const LineAxes& axes, const LinePoint& p) {
      EdgePixel& px = v.pixels[size_t(p.y) * size_t(vp.width) + size_t(p.x)];
      if (px == EdgePixel::kVisible) return;  // some edge already shows here
      px = edge_point_hidden(line, axes, p, faces, grid.at(p.x, p.y)) ? EdgePixel::kHidden
                                                                       : EdgePixel::kVisible;
    });
  }
  for (const EdgePixel p : v.pixels) {
    v.edge_pixels += p != EdgePixel::kNone;
    v.visible_pixels += p == EdgePixel::kVisible;
  }
  return v;
}

LineVisibility line_visibility(const RasterizedScene& rs) {
  return line_visibility(rs.triangles, rs.lines, rs.viewport);
}

Framebuffer line_reference_image(const LineVisibility& v, const Viewport& vp, Rgba8 background,
                                 Rgba8 visible, std::optional<Rgba8> hidden) {
  Framebuffer fb(vp.width, vp.height, vp.depth_bits, background, vp.coverage_samples);
  for (size_t i = 0; i < v.pixels.size() && i < fb.color.size(); ++i) {
    if (v.pixels[i] == EdgePixel::kVisible) fb.color[i] = visible;
    else if (v.pixels[i] == EdgePixel::kHidden && hidden) fb.color[i] = *hidden;
  }
  return fb;
}

}  // namespace zb
