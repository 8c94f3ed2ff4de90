// libFuzzer: geometry and raster on random vertices. The bytes build a small scene (coordinates
// that include NaN, infinities, huge, tiny and repeated values; a few triangles; a camera and
// viewport within their valid limits), then every fragment is checked (fuzz_check.h) and one
// pass plan is rendered on the golden model, with the exact reference.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "fuzz_check.h"
#include "pipeline/passes.h"
#include "reference/reference.h"
#include "rop/rop.h"
#include "io/scene_file.h"
#include "scene/camera.h"

namespace {

// Reads the input front to back; zeros once it runs out.
class Bytes {
 public:
  Bytes(const uint8_t* p, size_t n) : p_(p), n_(n) {}
  uint8_t u8() { return at_ < n_ ? p_[at_++] : 0; }
  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= uint32_t{u8()} << (8 * i);
    return v;
  }
  int below(int n) { return u8() % n; }

  // Mostly values that make shared and degenerate vertices, some that break arithmetic.
  float coordinate() {
    static const float kSpecial[] = {
        0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e-3f, 1e-20f, 1e-38f, 1e-45f,
        1e6f, -1e6f, 1e20f, -1e20f, 1e30f, -1e30f, 1e38f, -1e38f,
        std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest(),
        std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
        std::numeric_limits<float>::quiet_NaN(), 16777216.0f, 16777217.0f};
    const uint8_t kind = u8();
    switch (kind % 4) {
      case 0: return kSpecial[u8() % (sizeof kSpecial / sizeof kSpecial[0])];
      case 1: return static_cast<float>(static_cast<int8_t>(u8())) / 16.0f;  // a fine grid
      case 2: {
        const uint32_t bits = u32();
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
      }
      default: return static_cast<float>(static_cast<int16_t>(u8() | (u8() << 8))) / 256.0f;
    }
  }
  glm::vec3 vec3() { return {coordinate(), coordinate(), coordinate()}; }
  glm::vec3 small_vec3() {
    return glm::vec3(static_cast<int8_t>(u8()), static_cast<int8_t>(u8()), static_cast<int8_t>(u8())) / 8.0f;
  }

 private:
  const uint8_t* p_;
  size_t n_;
  size_t at_ = 0;
};

zb::Viewport viewport(Bytes& in) {
  zb::Viewport vp;
  switch (in.below(8)) {
    case 0: vp.width = zb::kMaxFrameSize; vp.height = 1 + in.below(4); break;  // the widest
    case 1: vp.width = 1 + in.below(4); vp.height = zb::kMaxFrameSize; break;
    default: vp.width = 1 + in.below(200); vp.height = 1 + in.below(200); break;
  }
  vp.depth_bits = zb::kMinDepthBits + in.below(zb::kMaxDepthBits - zb::kMinDepthBits + 1);
  vp.coverage_samples = 1 << in.below(5);
  return vp;
}

// A camera within the limits zblend accepts: finite, eye apart from at, 1 <= fov <= 179,
// 0 < near < far; or one aimed at the scene by aim_camera (false when it refuses).
bool set_camera(Bytes& in, zb::Scene& scene) {
  zb::Camera& c = scene.camera;
  c.eye = in.small_vec3();
  c.at = in.small_vec3();
  if (c.eye == c.at) c.at.z -= 1.0f;
  c.fov_y_deg = 1.0f + static_cast<float>(in.below(179));
  const glm::vec3 ups[] = {{0, 1, 0}, {0, 0, -1}, {1, 0, 0}, {0.6f, 0.8f, 0}};
  c.up = ups[in.below(4)];
  if (glm::length(glm::cross(glm::normalize(c.at - c.eye), c.up)) < 1e-3f) c.up = {1, 0, 0};
  if (glm::length(glm::cross(glm::normalize(c.at - c.eye), c.up)) < 1e-3f) c.up = {0, 1, 0};
  c.near = std::ldexp(1.0f, -in.below(16)) * (1.0f + in.below(100));
  c.far = c.near * (1.0f + static_cast<float>(in.u8()) * 4.0f + 1e-3f * static_cast<float>(in.below(256)));
  if (!(c.far > c.near)) c.far = c.near * 2.0f;
  if (in.below(4) == 0) {
    zb::CameraSpec spec;
    spec.eye = c.eye;
    spec.at = c.at;
    spec.fov_y_deg = c.fov_y_deg;
    try {
      zb::aim_camera(scene, spec);
    } catch (const std::invalid_argument&) {
      return false;  // the whole scene behind the eye
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  const zb::Viewport vp = viewport(in);
  zb::Scene scene;
  scene.background = {in.u8(), in.u8(), in.u8(), 255};
  const int materials = 1 + in.below(3);
  for (int m = 0; m < materials; ++m) {
    const uint8_t alpha = in.below(2) ? 255 : in.u8();  // transparent ones too
    scene.materials.push_back(zb::Material{"m", {in.u8(), in.u8(), in.u8(), alpha}});
  }
  const int objects = 1 + in.below(2);
  for (int o = 0; o < objects; ++o) {
    zb::Object obj;
    obj.name = "o";
    obj.material = static_cast<uint32_t>(in.below(materials));
    if (in.below(4) == 0) obj.transform = glm::mat4(in.coordinate());  // a uniform scale, maybe 0 or NaN
    const int vertices = 3 + in.below(6);
    for (int v = 0; v < vertices; ++v) obj.mesh.positions.push_back(in.vec3());
    if (in.below(2)) {
      for (int v = 0; v < vertices; ++v) obj.mesh.normals.push_back(in.vec3());
    }
    const int triangles = 1 + in.below(4);
    for (int t = 0; t < triangles; ++t)
      obj.mesh.triangles.emplace_back(in.below(vertices), in.below(vertices), in.below(vertices));
    scene.objects.push_back(std::move(obj));
  }
  if (!set_camera(in, scene)) return 0;

  const zb::RasterizedScene rs = zb::rasterize_scene(scene, vp);
  zbfuzz::check_rasterized(rs, scene.triangle_count());

  const std::vector<zb::PassPlan>& plans = zb::pass_plans();
  const zb::PassPlan& plan = plans[in.below(static_cast<int>(plans.size()))];
  for (const zb::PassState& pass : plan.passes)
    for (const zb::Fragment& f : zb::pass_fragments(rs, pass)) {
      FUZZ_CHECK(f.x < vp.width && f.y < vp.height);
      FUZZ_CHECK(f.z <= zb::depth_max(vp.depth_bits));
      FUZZ_CHECK(f.coverage <= vp.coverage_samples);
    }
  zb::GoldenRop rop;
  const zb::RenderResult r = zb::render(rs, plan, rop);
  FUZZ_CHECK(r.passes.size() == plan.passes.size());
  FUZZ_CHECK(r.framebuffer.color.size() == size_t(vp.width) * size_t(vp.height));
  for (uint32_t z : r.framebuffer.depth) FUZZ_CHECK(z <= zb::depth_max(vp.depth_bits));
  const zb::Framebuffer ref = zb::render_reference(rs);
  FUZZ_CHECK(ref.color.size() == r.framebuffer.color.size());
  return 0;
}
