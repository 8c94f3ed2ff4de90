// libFuzzer: the glTF loader on arbitrary bytes, as a .glb when they start with the GLB magic
// "glTF", else as .gltf JSON. Any external file ending in .bin is a fixed 60-byte buffer (four
// VEC3 FLOAT positions, six UNSIGNED_SHORT indices); other files do not exist.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_check.h"
#include "io/scene_file.h"

namespace {

std::string fixed_buffer() {
  const float pos[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const uint16_t idx[6] = {0, 1, 2, 1, 3, 2};
  std::string b(60, '\0');
  std::memcpy(b.data(), pos, 48);
  std::memcpy(b.data() + 48, idx, 12);
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const bool binary = bytes.compare(0, 4, "glTF") == 0;
  const zb::SceneFileReader read = [](const std::string& path, std::string& out) {
    if (path.size() < 4 || path.compare(path.size() - 4, 4, ".bin") != 0) return zb::FileRead::kMissing;
    out = fixed_buffer();
    return zb::FileRead::kOk;
  };
  const std::string name = binary ? "fuzz/scene.glb" : "fuzz/scene.gltf";
  zb::Scene scene;
  try {
    scene = zb::load_scene_bytes(name, bytes, read);
  } catch (const zb::SceneFileError& e) {
    zbfuzz::check_scene_error(e.what(), name);  // the one exception a loader may throw
    return 0;
  }
  zbfuzz::check_loaded_scene(scene);
  zbfuzz::check_rasterized(zb::rasterize_scene(scene, zb::Viewport{24, 16}), scene.triangle_count());
  return 0;
}
