// libFuzzer: the OBJ loader (+ MTL) on arbitrary bytes. Up to the first NUL byte the input is
// the OBJ text; after it, the text of every material library the OBJ names (no NUL: none found).
// A loaded scene must keep the loader's promises and go through geometry and raster.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "io/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const size_t nul = bytes.find('\0');
  const std::string obj = bytes.substr(0, nul);
  std::vector<std::string> asked;  // the MTL files, which messages may name too
  const zb::SceneFileReader read = [&](const std::string& path, std::string& out) {
    asked.push_back(path);
    if (nul == std::string::npos) return zb::FileRead::kMissing;
    out = bytes.substr(nul + 1);
    return zb::FileRead::kOk;
  };
  const std::string name = "fuzz/scene.obj";
  zb::Scene scene;
  try {
    scene = zb::load_scene_bytes(name, obj, read);
  } catch (const zb::SceneFileError& e) {
    // The one exception a loader may throw, naming the OBJ or an MTL it read.
    const std::string what = e.what();
    bool named_mtl = false;
    for (std::string mtl : asked) {
      for (char& c : mtl)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';  // as the loader shows it
      named_mtl = named_mtl || what.rfind(mtl + ": ", 0) == 0;
    }
    if (!named_mtl) zbfuzz::check_scene_error(what, name);
    FUZZ_CHECK(what.find_first_of("\r\n") == std::string::npos);
    return 0;
  }
  zbfuzz::check_loaded_scene(scene);
  zbfuzz::check_rasterized(zb::rasterize_scene(scene, zb::Viewport{24, 16}), scene.triangle_count());
  return 0;
}
