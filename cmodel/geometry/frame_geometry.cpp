#include "frame_geometry.h"

#include <algorithm>
#include <stdexcept>

#include "edges.h"
#include "parallel/parallel.h"

namespace zb {
namespace {

// Below this many triangles per thread the setup is not split: little work per thread start.
constexpr size_t kMinParallelSetup = 4096;

// The part of `scene` holding its triangles [first, last) in scene order, with every object
// that has some of them. setup_triangles numbers the part's triangles from 0. An object's
// vertices are cut down to those the part's triangles use (each transformed as in the whole
// scene: the same bits) when every vertex has a normal or none has; otherwise, where which
// vertices have one depends on their index, the whole arrays are kept. Throws
// std::out_of_range for a missing vertex (the caller then lets the serial setup report it).
Scene scene_part(const Scene& scene, size_t first, size_t last) {
  Scene part;
  part.materials = scene.materials;
  part.camera = scene.camera;
  part.background = scene.background;
  size_t base = 0;
  std::vector<uint32_t> remap;
  for (const Object& obj : scene.objects) {
    const Mesh& mesh = obj.mesh;
    const size_t n = mesh.triangles.size();
    const size_t lo = std::max(first, base), hi = std::min(last, base + n);
    base += n;
    if (lo >= hi) continue;
    Object o;
    o.name = obj.name;
    o.material = obj.material;
    o.transform = obj.transform;
    const auto tri_first = mesh.triangles.begin() + std::ptrdiff_t(lo - (base - n));
    const auto tri_last = mesh.triangles.begin() + std::ptrdiff_t(hi - (base - n));
    const bool compact = mesh.normals.empty() || mesh.normals.size() == mesh.positions.size();
    if (!compact) {
      o.mesh.positions = mesh.positions;
      o.mesh.normals = mesh.normals;
      o.mesh.triangles.assign(tri_first, tri_last);
    } else {
      constexpr uint32_t kUnused = UINT32_MAX;
      remap.assign(mesh.positions.size(), kUnused);
      o.mesh.triangles.reserve(hi - lo);
      for (auto t = tri_first; t != tri_last; ++t) {
        glm::uvec3 c;
        for (int k = 0; k < 3; ++k) {
          const uint32_t v = (*t)[k];
          if (v >= remap.size()) throw std::out_of_range("scene part: missing vertex");
          if (remap[v] == kUnused) {
            remap[v] = static_cast<uint32_t>(o.mesh.positions.size());
            o.mesh.positions.push_back(mesh.positions[v]);
            if (!mesh.normals.empty()) o.mesh.normals.push_back(mesh.normals[v]);
          }
          c[k] = remap[v];
        }
        o.mesh.triangles.push_back(c);
      }
    }
    part.objects.push_back(std::move(o));
  }
  return part;
}

}  // namespace

bool plan_draws_edges(const PassPlan& plan) {
  return std::any_of(plan.passes.begin(), plan.passes.end(),
                     [](const PassState& p) { return p.filter == PrimFilter::kEdges; });
}

std::vector<ScreenTriangle> setup_triangles_parallel(const Scene& scene, const Viewport& vp,
                                                     int threads) {
  const size_t total = scene.triangle_count();
  const int n = static_cast<int>(
      std::min<size_t>(size_t(resolve_threads(threads)), total / kMinParallelSetup));
  if (n <= 1) return setup_triangles(scene, vp);
  std::vector<std::vector<ScreenTriangle>> parts(static_cast<size_t>(n));
  try {
    run_workers(n, [&](int i) {
      const size_t first = total * size_t(i) / size_t(n), last = total * size_t(i + 1) / size_t(n);
      parts[size_t(i)] = setup_triangles(scene_part(scene, first, last), vp);
      for (ScreenTriangle& t : parts[size_t(i)]) t.prim += static_cast<uint32_t>(first);
    });
  } catch (const std::exception&) {
    // A bad scene: the whole setup says what is wrong, in its own words.
    return setup_triangles(scene, vp);
  }
  size_t count = 0;
  for (const auto& p : parts) count += p.size();
  std::vector<ScreenTriangle> out;
  out.reserve(count);
  for (auto& p : parts) {
    out.insert(out.end(), p.begin(), p.end());
    std::vector<ScreenTriangle>().swap(p);
  }
  return out;
}

FrameGeometry make_frame_geometry(const Scene& scene, const Viewport& vp, bool with_lines, int threads) {
  FrameGeometry g;
  g.viewport = vp;
  g.background = scene.background;
  g.triangles = setup_triangles_parallel(scene, vp, threads);
  if (with_lines) g.lines = setup_lines(scene, vp, g.triangles);
  return g;
}

}  // namespace zb
