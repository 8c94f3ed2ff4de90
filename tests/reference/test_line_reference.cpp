// The exact hidden-line reference and its error shares, against values worked out here on
// hand-made faces and edges in window coordinates (docs/raster.md "The hidden-line reference").
#include <gtest/gtest.h>

#include "metrics/line_metrics.h"
#include "pipeline/passes.h"
#include "reference/line_reference.h"

namespace {

using zb::EdgePixel;
using zb::ScreenLine;
using zb::ScreenTriangle;
using zb::ScreenVertex;

constexpr int32_t kPx = zb::kSubpixelOne;
const zb::Viewport kVp{8, 4, 24};

// A vertex at (x, y) pixels (multiples of 1/256) with exact depth ze and its 24-bit rounding.
ScreenVertex at(double x, double y, double ze) {
  return {int32_t(x * kPx), int32_t(y * kPx),
          uint32_t(ze * zb::depth_max(24) + 0.5), ze};
}

ScreenTriangle face(ScreenVertex a, ScreenVertex b, ScreenVertex c, uint32_t prim) {
  ScreenTriangle t;
  t.v[0] = a;
  t.v[1] = b;
  t.v[2] = c;
  t.prim = prim;
  return t;
}

ScreenLine edge(ScreenVertex a, ScreenVertex b, uint32_t own_face = zb::kNoFace) {
  ScreenLine l;
  l.v[0] = a;
  l.v[1] = b;
  l.faces[0].prim = own_face;
  return l;
}

std::vector<EdgePixel> row(const zb::LineVisibility& v, int y) {
  std::vector<EdgePixel> out;
  for (int x = 0; x < v.width; ++x) out.push_back(v.at(x, y));
  return out;
}

constexpr EdgePixel V = EdgePixel::kVisible, H = EdgePixel::kHidden, N = EdgePixel::kNone;

// One face at window depth 0.5 from x = 3 pixels rightwards over every row. An edge along
// row 1's centres (y = 1.5) from x = 0.5 at depth 0.2 to x = 7.5 at 0.9: its fragment in column
// i is evaluated at x = i + 0.5 (dM = 7 pixels, s = i pixels), where its depth is 0.2 + 0.1 i.
// The face covers the centres with x > 3: i >= 3. Hidden where 0.2 + 0.1 i > 0.5:
// i = 4..7; at i = 3 the depths are equal, and an equal face does not hide.
TEST(LineReference, InFrontVisibleBehindHiddenEqualKept) {
  const std::vector<ScreenTriangle> faces = {
      face(at(3, -10, 0.5), at(3, 20, 0.5), at(30, 5, 0.5), 0)};
  const zb::LineVisibility v =
      zb::line_visibility(faces, {edge(at(0.5, 1.5, 0.2), at(7.5, 1.5, 0.9))}, kVp);
  EXPECT_EQ(row(v, 1), (std::vector<EdgePixel>{V, V, V, V, H, H, H, H}));
  EXPECT_EQ(row(v, 0), std::vector<EdgePixel>(8, N));
  EXPECT_EQ(v.edge_pixels, 8u);
  EXPECT_EQ(v.visible_pixels, 4u);

  // The same edge bounding that face (its prim among the edge's faces): never hidden by it.
  const zb::LineVisibility own =
      zb::line_visibility(faces, {edge(at(0.5, 1.5, 0.2), at(7.5, 1.5, 0.9), 0)}, kVp);
  EXPECT_EQ(own.visible_pixels, 8u);

  // Drawn the other way round: the same points, the same answer.
  const zb::LineVisibility back =
      zb::line_visibility(faces, {edge(at(7.5, 1.5, 0.9), at(0.5, 1.5, 0.2))}, kVp);
  EXPECT_EQ(row(back, 1), row(v, 1));
}

// A face through the edge's end vertex A = (4.5, 3.5) at depth 0.5, opening leftwards to
// B = (2, 0) and C = (2, 6) at 0.1: along y = 3.5 its depth is 0.1 + 0.16 (x - 2) for
// 2 <= x <= 4.5. The edge runs from (0.5, 3.5) at 0.9 to A: depth 0.9 - 0.1 (x - 0.5).
// Column 2 (x = 2.5): edge 0.7, face 0.18: hidden. Column 3 (x = 3.5): edge 0.6, face 0.34, but
// one pixel from the shared vertex along the major axis: not counted. Column 4 is evaluated at
// A itself. Columns 0 and 1 lie left of the face.
TEST(LineReference, FacesAtASharedVertexCountBeyondOnePixel) {
  const ScreenVertex a = at(4.5, 3.5, 0.5);
  const std::vector<ScreenTriangle> faces = {face(a, at(2, 0, 0.1), at(2, 6, 0.1), 5)};
  const zb::LineVisibility v = zb::line_visibility(faces, {edge(at(0.5, 3.5, 0.9), a)}, kVp);
  EXPECT_EQ(row(v, 3), (std::vector<EdgePixel>{V, V, H, V, V, N, N, N}));

  // With the edge's end a hair behind A (another vertex), the face counts at column 3 too.
  ScreenVertex a2 = a;
  a2.z_exact += 1e-6;
  const zb::LineVisibility u = zb::line_visibility(faces, {edge(at(0.5, 3.5, 0.9), a2)}, kVp);
  EXPECT_EQ(u.at(3, 3), H);
}

// The verdict is the edge point's, not the pixel centre's: an edge along y = 1.9 (row 1, its
// points at y = 1.9, the centres at 1.5) behind a face that ends at y = 1.7 (covering the
// centres, not the points) is visible; behind one that starts at y = 1.8 (covering the points,
// not the centres), hidden.
TEST(LineReference, FacesAreTakenAtTheEdgesPoint) {
  const std::vector<ScreenLine> lines = {edge(at(0.5, 1.9, 0.5), at(7.5, 1.9, 0.5))};
  const zb::LineVisibility above = zb::line_visibility(
      {face(at(-20, 1.7, 0.1), at(30, 1.7, 0.1), at(5, -30, 0.1), 0)}, lines, kVp);
  EXPECT_EQ(row(above, 1), std::vector<EdgePixel>(8, V));
  const zb::LineVisibility below = zb::line_visibility(
      {face(at(-20, 1.8, 0.1), at(5, 30, 0.1), at(30, 1.8, 0.1), 0)}, lines, kVp);
  EXPECT_EQ(row(below, 1), std::vector<EdgePixel>(8, H));
}

// A face through the edge that is not its own (a coplanar duplicate, as coplanar's boxes drawn
// twice) has the edge's depth at its points: within the tolerance, it does not hide it, however
// its plane is tilted.
TEST(LineReference, ACoplanarDuplicateDoesNotHide) {
  // A tilted face with the edge (0.5, 1.5)-(7.5, 1.5) at depth 0.2 + 0.1 (x - 0.5) on it:
  // depth 0.2 + 0.1 (x - 0.5) + 0.05 (y - 1.5) over the plane.
  auto d = [](double x, double y) { return 0.2 + 0.1 * (x - 0.5) + 0.05 * (y - 1.5); };
  const std::vector<ScreenTriangle> faces = {
      face(at(0.5, 1.5, d(0.5, 1.5)), at(7.5, 1.5, d(7.5, 1.5)), at(4, 9, d(4, 9)), 3),
      face(at(0.5, 1.5, d(0.5, 1.5)), at(4, -6, d(4, -6)), at(7.5, 1.5, d(7.5, 1.5)), 4)};
  const zb::LineVisibility v =
      zb::line_visibility(faces, {edge(at(0.5, 1.5, 0.2), at(7.5, 1.5, 0.9))}, kVp);
  EXPECT_EQ(v.visible_pixels, 8u);
  // The same faces moved 0.001 nearer hide it everywhere.
  std::vector<ScreenTriangle> nearer = faces;
  for (ScreenTriangle& t : nearer)
    for (ScreenVertex& p : t.v) p.z_exact -= 0.001;
  EXPECT_EQ(zb::line_visibility(nearer, {edge(at(0.5, 1.5, 0.2), at(7.5, 1.5, 0.9))}, kVp)
                .visible_pixels,
            0u);
}

// Where two edges share a pixel, it is visible when either is.
TEST(LineReference, APixelIsVisibleWhenAnyEdgeThereIs) {
  const std::vector<ScreenTriangle> faces = {
      face(at(3, -10, 0.5), at(3, 20, 0.5), at(30, 5, 0.5), 0)};
  const zb::LineVisibility v = zb::line_visibility(
      faces, {edge(at(0.5, 1.5, 0.9), at(7.5, 1.5, 0.9)), edge(at(5.5, 0.5, 0.1), at(5.5, 3.5, 0.1))},
      kVp);
  EXPECT_EQ(row(v, 1), (std::vector<EdgePixel>{V, V, V, H, H, V, H, H}));
  EXPECT_EQ(v.at(5, 0), V);
  EXPECT_EQ(v.edge_pixels, 8u + 3u);
}

TEST(LineError, SharesOfTheReferencesEdgePixels) {
  const std::vector<ScreenTriangle> faces = {
      face(at(3, -10, 0.5), at(3, 20, 0.5), at(30, 5, 0.5), 0)};
  const zb::LineVisibility v =
      zb::line_visibility(faces, {edge(at(0.5, 1.5, 0.2), at(7.5, 1.5, 0.9))}, kVp);
  const zb::Rgba8 white{255, 255, 255, 255};
  // The exact image itself: no error. Its dimmed form, judged as dimmed, neither.
  const zb::Framebuffer exact = zb::line_reference_image(v, kVp, white, zb::kEdgeColor, {});
  EXPECT_EQ(exact.color_at(3, 1), zb::kEdgeColor);
  EXPECT_EQ(exact.color_at(4, 1), white);
  zb::LineError e = zb::compare_lines(exact, v, zb::kEdgeColor);
  EXPECT_EQ(e.edge_pixels, 8u);
  EXPECT_EQ(e.hidden_drawn + e.visible_missing, 0u);
  const zb::Framebuffer dim =
      zb::line_reference_image(v, kVp, white, zb::kEdgeColor, zb::kHiddenEdgeColor);
  EXPECT_EQ(dim.color_at(4, 1), zb::kHiddenEdgeColor);
  EXPECT_EQ(zb::compare_lines(dim, v, zb::kEdgeColor).hidden_drawn, 0u);
  // Column 3 missing, columns 5 and 6 drawn: 1 and 2 of 8.
  zb::Framebuffer wrong = exact;
  wrong.color[wrong.index(3, 1)] = white;
  wrong.color[wrong.index(5, 1)] = zb::kEdgeColor;
  wrong.color[wrong.index(6, 1)] = zb::kEdgeColor;
  wrong.color[wrong.index(2, 3)] = zb::kEdgeColor;  // not an edge pixel: not counted
  e = zb::compare_lines(wrong, v, zb::kEdgeColor);
  EXPECT_EQ(e.visible_missing, 1u);
  EXPECT_EQ(e.hidden_drawn, 2u);
  EXPECT_DOUBLE_EQ(e.visible_missing_share(), 1.0 / 8);
  EXPECT_DOUBLE_EQ(e.hidden_drawn_share(), 2.0 / 8);
  // A visible pixel drawn dimmed is missing from the visible style.
  wrong.color[wrong.index(0, 1)] = zb::kHiddenEdgeColor;
  EXPECT_EQ(zb::compare_lines(wrong, v, zb::kEdgeColor).visible_missing, 2u);
}

}  // namespace
