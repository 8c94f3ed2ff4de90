#include "memory_use.h"

#include <sys/resource.h>

#include "rop/framebuffer.h"

namespace zb {

uint64_t frame_bytes(int width, int height) {
  const Framebuffer probe;  // element sizes of the planes, whatever their types become
  const uint64_t per_pixel = sizeof(probe.color[0]) + sizeof(probe.depth[0]) +
                             sizeof(probe.coverage[0]) + sizeof(probe.peel[0]);
  return uint64_t(width) * uint64_t(height) * per_pixel;
}

uint64_t scene_bytes(const Scene& scene) {
  uint64_t bytes = sizeof(Scene) + scene.materials.size() * sizeof(Material);
  for (const Object& o : scene.objects)
    bytes += sizeof(Object) + o.mesh.positions.size() * sizeof(glm::vec3) +
             o.mesh.normals.size() * sizeof(glm::vec3) +
             o.mesh.triangles.size() * sizeof(glm::uvec3);
  return bytes;
}

uint64_t peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return uint64_t(u.ru_maxrss) * 1024;  // Linux: kilobytes
}

}  // namespace zb
