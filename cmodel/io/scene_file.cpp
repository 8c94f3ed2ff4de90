// Scene files (docs/scenes.md): the file read, its format chosen by extension, the loader's
// scene given a white background and a fitted camera.
#include "scene_file.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "io/internal/loaders.h"
#include "io/internal/text.h"
#include "scene/camera.h"

namespace zb {

using namespace text;
namespace fs = std::filesystem;

FileRead read_scene_file(const std::string& path, std::string& bytes) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return FileRead::kMissing;
  std::ifstream in(path, std::ios::binary);
  if (!in) return FileRead::kUnreadable;
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return FileRead::kUnreadable;
  bytes = ss.str();
  return FileRead::kOk;
}

bool is_scene_path(const std::string& name) {
  const std::string ext = lower_extension(name);
  return name.find('/') != std::string::npos || ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

Scene load_scene_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) fail(path, "open", "is a directory, not a scene file");
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
    fail(path, "name", fmt::format("unsupported file type '{}' (expected .obj, .gltf or .glb)", ext));
  std::string bytes;
  const FileRead r = read_scene_file(path, bytes);
  if (r == FileRead::kMissing) fail(path, "open", fs::exists(path, ec) ? "not a regular file" : "no such file");
  if (r != FileRead::kOk) fail(path, "open", "cannot read the file");
  return load_scene_bytes(path, bytes, read_scene_file);
}

Scene load_scene_bytes(const std::string& name, const std::string& bytes, const SceneFileReader& read) {
  const std::string ext = lower_extension(name);
  Scene scene;
  if (ext == ".obj") {
    scene = load_obj(name, bytes, read);
  } else if (ext == ".gltf" || ext == ".glb") {
    scene = load_gltf(name, bytes, ext == ".glb", read);
  } else {
    fail(name, "name", fmt::format("unsupported file type '{}' (expected .obj, .gltf or .glb)", ext));
  }
  if (scene.triangle_count() == 0) throw SceneFileError(printable(fmt::format("scene '{}': no triangles", name)));
  scene.background = {255, 255, 255, 255};
  fit_camera(scene);
  return scene;
}

void warn_ignored_textures(Scene& scene, const std::function<bool(uint32_t)>& textured) {
  std::set<uint32_t> used;
  for (const Object& obj : scene.objects) used.insert(obj.material);
  for (uint32_t m : used)
    if (textured(m))
      scene.warnings.push_back(fmt::format("material '{}': texture ignored, its base colour is used",
                                           printable(scene.materials[m].name)));
}

}  // namespace zb
