// The exact hidden-line reference (docs/raster.md "The hidden-line reference"): every
// tessellation edge's pixels, by the line rule the methods draw with, each decided visible or
// hidden against the exact depth of the faces not adjacent to that edge, in double precision.
// Ground truth for the hidden-line methods, not a hardware method.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/edges.h"
#include "pipeline/render.h"
#include "raster/lines.h"
#include "rop/framebuffer.h"

namespace zb {

// A face hides an edge point when it is nearer there by more than this (window depth, 0..1):
// about 1/64 of a 24-bit unit, far above the double arithmetic's error and far below any
// depth buffer's resolution. It separates faces through the point (coplanar, or sharing it)
// from faces in front of it.
constexpr double kLineDepthTolerance = 1.0 / (1u << 30);

enum class EdgePixel : uint8_t { kNone, kHidden, kVisible };

// Per pixel: no edge, hidden (every edge fragment there hidden) or visible (some visible).
struct LineVisibility {
  int width = 0;
  int height = 0;
  std::vector<EdgePixel> pixels;  // row-major
  size_t edge_pixels = 0;         // pixels with an edge fragment
  size_t visible_pixels = 0;      // of which visible
  EdgePixel at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// Whether fragment `p` of `line` is hidden at the point of the edge the line rule evaluates
// it at (walk_line): one of `faces` (set-up triangles) not adjacent to the edge (its prim is
// not one of line.faces) covers that point, its edges included, and is nearer there than the
// edge by more than kLineDepthTolerance. A face that shares an end vertex of the line (a
// window vertex equal in x, y and exact depth) is not counted within one pixel of that vertex
// along the major axis. `candidates` are the indices of the faces to test.
bool edge_point_hidden(const ScreenLine& line, const LineAxes& axes, const LinePoint& p,
                       const std::vector<ScreenTriangle>& faces,
                       const std::vector<uint32_t>& candidates);

// Every edge pixel of `lines` in the viewport, decided against every face of `faces`.
LineVisibility line_visibility(const std::vector<ScreenTriangle>& faces,
                               const std::vector<ScreenLine>& lines, const Viewport& vp);
LineVisibility line_visibility(const RasterizedScene& rs);

// The reference's picture: visible edge pixels in `visible`, hidden ones in `hidden` when
// given (a method that dims them) or left as the background.
Framebuffer line_reference_image(const LineVisibility& v, const Viewport& vp, Rgba8 background,
                                 Rgba8 visible, std::optional<Rgba8> hidden);

}  // namespace zb
