// Scene files: Wavefront OBJ (+MTL) through tinyobjloader, glTF 2.0 (.gltf, .glb) through
// tinygltf (docs/scenes.md). The camera they get is fit_camera's (scene/camera.h).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace zb {

// A scene file that cannot be used. The message is one line: "FILE: PLACE: what is wrong"
// (PLACE is "line N", a JSON path such as "meshes[0].primitives[1]", an accessor index or a
// byte offset), or "scene 'FILE': no triangles".
struct SceneFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// True when `name` is meant as a file rather than a built-in scene: it contains '/' or ends in
// .obj, .gltf or .glb (any case).
bool is_scene_path(const std::string& name);

// Loads an OBJ, glTF or GLB file. The camera is fitted (fit_camera); the background is white.
Scene load_scene_file(const std::string& path);

// The files a scene names (MTL libraries, glTF buffers and images) are read through this, by
// their name in the scene joined to the scene's directory.
enum class FileRead { kOk, kMissing, kUnreadable };
using SceneFileReader = std::function<FileRead(const std::string& path, std::string& bytes)>;

// The file system: kMissing unless `path` is a regular file.
FileRead read_scene_file(const std::string& path, std::string& bytes);

// load_scene_file on bytes already in memory (fuzzing, tests): `name` stands for the file's path;
// its extension picks the format, its directory resolves the names passed to `read`, and
// messages start with it. Throws SceneFileError and nothing else.
Scene load_scene_bytes(const std::string& name, const std::string& bytes,
                       const SceneFileReader& read = read_scene_file);

}  // namespace zb
