// Scene files: Wavefront OBJ (+MTL) through tinyobjloader, glTF 2.0 (.gltf, .glb) through
// tinygltf, and the camera: fitted to the scene's bounds, or set by the user (docs/scenes.md).
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "scene.h"

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

// A user camera: `eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z]`, each field at most once, in any order.
struct CameraSpec {
  glm::vec3 eye{0.0f};
  glm::vec3 at{0.0f};
  float fov_y_deg = 45.0f;
  std::optional<glm::vec3> up;  // default: +y, or -z when looking straight up or down
};

// Parses the text of --camera strictly; throws std::invalid_argument naming the bad field (also
// for an `up` that is zero or parallel to the view direction).
CameraSpec parse_camera_spec(const std::string& text);

// The default camera: looks along -z at the centre of the bounding sphere of all world-space
// vertices (centre and half diagonal of the axis-aligned box), from the distance at which the
// sphere fills the 45-degree vertical field of view (r / sin(22.5 deg)); near and far are the
// sphere's extent along the view direction widened by 1% of the radius each side, near lowered
// where the float projection would overflow (docs/scenes.md).
void fit_camera(Scene& scene);

// Puts the camera at `spec` (up: spec.up, else +y, or -z when looking straight up or down), with
// near and far fitted to the range of the vertices' distances along the view direction
// (docs/scenes.md). Throws std::invalid_argument when eye equals at, `up` is zero or parallel to
// the view direction, or the whole scene lies behind the eye.
void aim_camera(Scene& scene, const CameraSpec& spec);

}  // namespace zb
