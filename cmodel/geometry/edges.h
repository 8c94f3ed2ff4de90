// Tessellation edges for hidden-line rendering (US 5,359,704; docs/raster.md, "Edges"):
// unique edges per object from the index buffer, set up to window coordinates like the
// triangles, each with the depth slope its depth offset uses.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry.h"
#include "scene/scene.h"

namespace zb {

// No face: an edge bounded by fewer than two triangles (a mesh's border).
constexpr uint32_t kNoFace = UINT32_MAX;

// An edge of a mesh: vertex indices (welded, see unique_edges) in the order of the first
// triangle that has it, and the first two triangles (mesh indices) that have it.
struct MeshEdge {
  uint32_t a = 0;
  uint32_t b = 0;
  uint32_t faces[2] = {kNoFace, kNoFace};
};

// The unique edges of `mesh`, each once, in order of first appearance: triangles in index
// order, edges (v0 v1), (v1 v2), (v2 v0) of each. Vertices with bit-equal positions are welded
// first (to the lowest index with that position), so an edge shared by two triangles counts
// once even when the mesh splits vertices for normals (as make_box does). Degenerate edges
// (both ends welded to one vertex) are skipped.
std::vector<MeshEdge> unique_edges(const Mesh& mesh);

// A face an edge bounds, as the edge's setup hands it on: the plane a depth offset taken from
// the edge's own faces is measured against (raster.md "Depth offset"), and which triangle it is.
struct EdgeFace {
  uint32_t prim = kNoFace;  // the source triangle (ScreenTriangle::prim); kNoFace: none
  ScreenVertex v[3];        // its set-up triangle (its first fan piece when clipped)
  // The side of the edge it lies on: the sign of the edge's line function (line_side) at the
  // vertex farthest from the line; 0 when it has none off the line.
  int side = 0;
};

// A unique edge in window coordinates.
struct ScreenLine {
  ScreenVertex v[2];
  uint32_t depth_slope = 0;  // depth units per pixel (raster.md, "Depth offset")
  uint32_t prim = 0;         // running index of the edge over the scene's unique edges
  EdgeFace faces[2];         // its own faces (MeshEdge::faces) as set up
};

// The line function of a screen line at p (1/256 pixel): (x1 - x0)(p.y - y0) -
// (y1 - y0)(p.x - x0), exact; its sign says on which side of the line p lies.
int64_t line_side(const ScreenLine& l, int64_t px, int64_t py);

// Depth slope of a triangle: ceil(max(|dz/dx|, |dz/dy|)) in depth units per pixel, exact from
// its fixed-point vertices, saturating at 2^32 - 1; 0 for a zero-area triangle.
uint32_t depth_slope(const ScreenTriangle& t);

// Every object's unique edges, in scene order, transformed exactly as setup_triangles
// transforms their vertices, clipped as segments against the same planes, projected. An edge's
// depth slope is the largest depth_slope of the set-up triangles (of `triangles`, matched by
// prim) that touch either of its welded end vertices; its faces are the set-up triangles of
// its own two (MeshEdge::faces), where they were not dropped.
std::vector<ScreenLine> setup_lines(const Scene& scene, const Viewport& vp,
                                    const std::vector<ScreenTriangle>& triangles);

}  // namespace zb
