// Geometry stage (docs/raster.md): object -> world -> clip in GLM float, flat Lambert shading,
// Sutherland-Hodgman clipping in homogeneous clip space, perspective divide, viewport to
// fixed-point window coordinates (y down), facing from the fixed-point winding.
#include "geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>

namespace zb {
namespace {

// Guard band: |x| <= G*w and |y| <= G*w, so window coordinates stay in [-1.5W, 2.5W].
constexpr float kGuardBand = 4.0f;
constexpr int kClipPlanes = 6;
// A triangle clipped by six planes has at most 3 + 6 vertices.
constexpr int kMaxPolygon = 3 + kClipPlanes;
// Any window coordinate in 1/256 pixel beyond this is a bug or overflow: the triangle is dropped.
// The guard band keeps |x|, |y| < 2.5 * 8192 * 256 < 2^23.
constexpr double kFixedLimit = double(1 << 24);

struct Polygon {
  glm::vec4 v[kMaxPolygon + 1];
  bool facing[kMaxPolygon + 1] = {};  // per vertex; a crossing takes its inside end's flag
  int n = 0;
};

// Signed distance-like value of `c` to clip plane `plane`; inside when >= 0.
// Order of the planes: near, far, left, right, bottom, top.
float plane_distance(int plane, const glm::vec4& c) {
  switch (plane) {
    case 0: return c.w + c.z;                // near: z >= -w
    case 1: return c.w - c.z;                // far:  z <= w
    case 2: return kGuardBand * c.w + c.x;   // x >= -G*w
    case 3: return kGuardBand * c.w - c.x;   // x <= G*w
    case 4: return kGuardBand * c.w + c.y;   // y >= -G*w
    default: return kGuardBand * c.w - c.y;  // y <= G*w
  }
}

// The point where segment (in, out) crosses the plane, always interpolated from the inside
// end toward the outside end, so that the two triangles sharing an edge compute the same
// bits for the same crossing whatever their winding.
glm::vec4 crossing(int plane, const glm::vec4& in, float d_in, const glm::vec4& out,
                   float d_out) {
  const float t = d_in / (d_in - d_out);
  glm::vec4 c = in + t * (out - in);
  // On the plane exactly: with huge coordinates the interpolated point can miss it by far more
  // than the frame, and a later plane would then cut the polygon away.
  switch (plane) {
    case 0: c.z = -c.w; break;
    case 1: c.z = c.w; break;
    case 2: c.x = -kGuardBand * c.w; break;
    case 3: c.x = kGuardBand * c.w; break;
    case 4: c.y = -kGuardBand * c.w; break;
    default: c.y = kGuardBand * c.w; break;
  }
  return c;
}

// Sutherland-Hodgman against one plane.
void clip_polygon(int plane, const Polygon& src, Polygon& dst) {
  dst.n = 0;
  if (src.n == 0) return;
  float d[kMaxPolygon + 1];
  for (int i = 0; i < src.n; ++i) d[i] = plane_distance(plane, src.v[i]);
  for (int i = 0; i < src.n; ++i) {
    const int j = (i + 1) % src.n;
    const bool in_i = d[i] >= 0.0f;
    const bool in_j = d[j] >= 0.0f;
    if (in_i) {
      dst.facing[dst.n] = src.facing[i];
      dst.v[dst.n++] = src.v[i];
    }
    if (in_i != in_j) {
      dst.facing[dst.n] = in_i ? src.facing[i] : src.facing[j];
      dst.v[dst.n++] = in_i ? crossing(plane, src.v[i], d[i], src.v[j], d[j])
                            : crossing(plane, src.v[j], d[j], src.v[i], d[i]);
    }
  }
}

bool finite4(const glm::vec4& c) {
  return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
}

// Clips the triangle in clip space. Returns the polygon, empty when wholly outside.
Polygon clip_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                      const bool facing[3]) {
  Polygon p[2];
  p[0].v[0] = a;
  p[0].v[1] = b;
  p[0].v[2] = c;
  for (int k = 0; k < 3; ++k) p[0].facing[k] = facing[k];
  p[0].n = 3;
  int cur = 0;
  bool clipped = false;
  for (int plane = 0; plane < kClipPlanes; ++plane) {
    // Every plane is applied in order. Skipping a plane while the polygon is still the input
    // triangle and all three vertices are inside is exact (clipping would return it unchanged);
    // after the first cut new vertices may sit a rounding error outside a later plane, so from
    // then on every plane is run.
    if (!clipped && plane_distance(plane, a) >= 0.0f && plane_distance(plane, b) >= 0.0f &&
        plane_distance(plane, c) >= 0.0f)
      continue;
    clip_polygon(plane, p[cur], p[cur ^ 1]);
    cur ^= 1;
    clipped = true;
    if (p[cur].n < 3) return Polygon{};
  }
  return p[cur];
}

// Flat Lambert shading of one triangle (docs/raster.md, "Shading").
Rgba8 shade_triangle(const Material& mat, const glm::vec3 world[3], const glm::vec3* normals[3],
                     const glm::mat3& normal_matrix, const glm::vec3& eye) {
  glm::vec3 n(0.0f);
  bool have_n = false;
  if (normals[0] && normals[1] && normals[2]) {
    const glm::vec3 avg = (*normals[0] + *normals[1] + *normals[2]) / 3.0f;
    const float longest = std::max({glm::dot(*normals[0], *normals[0]),
                                    glm::dot(*normals[1], *normals[1]),
                                    glm::dot(*normals[2], *normals[2])});
    // Degenerate: the average is shorter than 1/1000 of the longest vertex normal (the
    // normals cancel), or the transformed normal has zero or non-finite length.
    if (glm::dot(avg, avg) > 1e-6f * longest) {
      n = normal_matrix * avg;
      const float len2 = glm::dot(n, n);
      have_n = len2 > 0.0f && std::isfinite(len2);
    }
  }
  if (!have_n) {
    n = glm::cross(world[1] - world[0], world[2] - world[0]);
    const float len2 = glm::dot(n, n);
    have_n = len2 > 0.0f && std::isfinite(len2);
  }
  float cosine = 0.0f;  // no usable normal or light direction: ambient only
  if (have_n) {
    const glm::vec3 centroid = (world[0] + world[1] + world[2]) / 3.0f;
    const glm::vec3 to_eye = eye - centroid;
    const float l2 = glm::dot(to_eye, to_eye);
    if (l2 > 0.0f && std::isfinite(l2)) {
      cosine = std::fabs(glm::dot(glm::normalize(n), glm::normalize(to_eye)));
      if (!std::isfinite(cosine)) cosine = 0.0f;
    }
  }
  const float shade = kAmbient + (1.0f - kAmbient) * cosine;
  auto channel = [shade](uint8_t c) {
    const long v = std::lround(float(c) * shade);
    return static_cast<uint8_t>(std::clamp(v, 0L, 255L));
  };
  return Rgba8{channel(mat.color.r), channel(mat.color.g), channel(mat.color.b), mat.color.a};
}

// Twice the signed area of (a, b, c) in fixed-point window coordinates. Positive when the
// triangle turns clockwise on the y-down screen.
int64_t area2(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  return (int64_t{b.x} - a.x) * (int64_t{c.y} - a.y) - (int64_t{c.x} - a.x) * (int64_t{b.y} - a.y);
}

// Perspective divide and viewport. Returns false when the vertex is unusable.
bool to_window(const glm::vec4& c, const Viewport& vp, ScreenVertex& out) {
  if (!(c.w > 0.0f) || !finite4(c)) return false;
  // Divide in float, as the rest of the float pipeline; the viewport mapping is exact in
  // double: (ndc + 1) is exact, the products with W, H <= 2^13 and 1/2 and 256 are exact.
  const float nx = c.x / c.w, ny = c.y / c.w, nz = c.z / c.w;
  const double xs = (double(nx) + 1.0) * vp.width * 0.5 * kSubpixelOne;
  const double ys = (1.0 - double(ny)) * vp.height * 0.5 * kSubpixelOne;
  if (!(std::fabs(xs) < kFixedLimit) || !(std::fabs(ys) < kFixedLimit)) return false;
  double zw = (double(nz) + 1.0) * 0.5;
  if (!std::isfinite(zw)) return false;
  zw = std::clamp(zw, 0.0, 1.0);
  out.x = static_cast<int32_t>(std::llround(xs));
  out.y = static_cast<int32_t>(std::llround(ys));
  out.z_exact = zw;
  out.z = static_cast<uint32_t>(std::llround(zw * double(depth_max(vp.depth_bits))));
  return true;
}

}  // namespace

bool vertex_faces_eye(const glm::vec3& normal_world, const glm::vec3& vertex_world,
                      const glm::vec3& eye) {
  return glm::dot(normal_world, eye - vertex_world) > 0.0f;
}

float clip_plane_distance(int plane, const glm::vec4& c) { return plane_distance(plane, c); }

glm::vec4 clip_crossing(int plane, const glm::vec4& in, float d_in, const glm::vec4& out,
                        float d_out) {
  return crossing(plane, in, d_in, out, d_out);
}

bool clip_to_window(const glm::vec4& c, const Viewport& vp, ScreenVertex& out) {
  return to_window(c, vp, out);
}

namespace {

void check_viewport(const Viewport& vp) {
  if (vp.width < 1 || vp.width > kMaxFrameSize || vp.height < 1 || vp.height > kMaxFrameSize)
    throw std::invalid_argument("viewport " + std::to_string(vp.width) + "x" +
                                std::to_string(vp.height) + " outside 1.." +
                                std::to_string(kMaxFrameSize));
  if (vp.depth_bits < kMinDepthBits || vp.depth_bits > kMaxDepthBits)
    throw std::invalid_argument("depth bits " + std::to_string(vp.depth_bits) + " outside " +
                                std::to_string(kMinDepthBits) + ".." +
                                std::to_string(kMaxDepthBits));
}

}  // namespace

std::vector<ClipTriangle> transform_triangles(const Scene& scene, const Viewport& vp) {
  check_viewport(vp);
  const glm::mat4 view_proj =
      scene.camera.projection(float(vp.width) / float(vp.height)) * scene.camera.view();
  const glm::vec3 eye = scene.camera.eye;

  std::vector<ClipTriangle> out;
  out.reserve(scene.triangle_count());
  std::vector<glm::vec3> world;
  std::vector<glm::vec4> clip;
  uint32_t prim = 0;
  for (const Object& obj : scene.objects) {
    if (obj.material >= scene.materials.size() && !obj.mesh.triangles.empty())
      throw std::invalid_argument("object '" + obj.name + "': material " +
                                  std::to_string(obj.material) + " out of range");
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(obj.transform));
    const Mesh& mesh = obj.mesh;
    world.resize(mesh.positions.size());
    clip.resize(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      world[i] = glm::vec3(obj.transform * glm::vec4(mesh.positions[i], 1.0f));
      clip[i] = view_proj * glm::vec4(world[i], 1.0f);
    }
    for (const glm::uvec3& t : mesh.triangles) {
      const uint32_t this_prim = prim++;
      if (t.x >= world.size() || t.y >= world.size() || t.z >= world.size())
        throw std::invalid_argument("object '" + obj.name + "': triangle " +
                                    std::to_string(this_prim) + " indexes a missing vertex");
      const uint32_t idx[3] = {t.x, t.y, t.z};
      ClipTriangle ct;
      for (int k = 0; k < 3; ++k) ct.clip[k] = clip[idx[k]];
      if (!finite4(ct.clip[0]) || !finite4(ct.clip[1]) || !finite4(ct.clip[2])) continue;

      // Per-vertex facing (CN 103021015), before clipping: the vertex normal in world space
      // (the face normal when the mesh has none) against the direction to the eye.
      const bool have_normals = idx[0] < mesh.normals.size() && idx[1] < mesh.normals.size() &&
                                idx[2] < mesh.normals.size();
      const glm::vec3 face_n =
          glm::cross(world[idx[1]] - world[idx[0]], world[idx[2]] - world[idx[0]]);
      for (int k = 0; k < 3; ++k)
        ct.facing[k] = vertex_faces_eye(have_normals ? normal_matrix * mesh.normals[idx[k]] : face_n,
                                        world[idx[k]], eye);

      const glm::vec3 w[3] = {world[idx[0]], world[idx[1]], world[idx[2]]};
      const glm::vec3* nrm[3];
      for (int k = 0; k < 3; ++k)
        nrm[k] = idx[k] < mesh.normals.size() ? &mesh.normals[idx[k]] : nullptr;
      const Material& mat = scene.materials[obj.material];
      ct.color = shade_triangle(mat, w, nrm, normal_matrix, eye);
      ct.transparent = mat.transparent();
      ct.prim = this_prim;
      out.push_back(ct);
    }
  }
  return out;
}

std::vector<ScreenTriangle> setup_triangles(const Scene& scene, const Viewport& vp) {
  const std::vector<ClipTriangle> clipped = transform_triangles(scene, vp);
  std::vector<ScreenTriangle> out;
  out.reserve(clipped.size());
  for (const ClipTriangle& ct : clipped) {
    const Polygon poly = clip_triangle(ct.clip[0], ct.clip[1], ct.clip[2], ct.facing);
    if (poly.n < 3) continue;
    ScreenVertex sv[kMaxPolygon];
    bool ok = true;
    for (int i = 0; i < poly.n && ok; ++i) ok = to_window(poly.v[i], vp, sv[i]);
    if (!ok) continue;

    // Facing of the whole polygon from its fixed-point signed area (the sum of its fan
    // triangles). Front = counter-clockwise as seen = negative area2 on the y-down screen.
    int64_t total = 0;
    int64_t fan_area[kMaxPolygon];
    for (int i = 1; i + 1 < poly.n; ++i) {
      fan_area[i] = area2(sv[0], sv[i], sv[i + 1]);
      total += fan_area[i];
    }
    if (total == 0) continue;

    ScreenTriangle st;
    st.color = ct.color;
    st.front = total < 0;
    st.transparent = ct.transparent;
    st.prim = ct.prim;
    for (int i = 1; i + 1 < poly.n; ++i) {
      // Zero-area fan triangles, and rounding slivers that turn against the polygon, are
      // dropped.
      if (fan_area[i] == 0 || (fan_area[i] < 0) != (total < 0)) continue;
      st.v[0] = sv[0];
      st.v[1] = sv[i];
      st.v[2] = sv[i + 1];
      st.facing[0] = poly.facing[0];
      st.facing[1] = poly.facing[i];
      st.facing[2] = poly.facing[i + 1];
      out.push_back(st);
    }
  }
  return out;
}

}  // namespace zb
