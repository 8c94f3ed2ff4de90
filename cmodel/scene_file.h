// Scene files: Wavefront OBJ (+MTL) through tinyobjloader, glTF 2.0 (.gltf, .glb) through
// tinygltf, and the camera: fitted to the scene's bounds, or set by the user (docs/scenes.md).
#pragma once

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

// A user camera: `eye=x,y,z,at=x,y,z,fov=deg`, each field once, in any order.
struct CameraSpec {
  glm::vec3 eye{0.0f};
  glm::vec3 at{0.0f};
  float fov_y_deg = 45.0f;
};

// Parses the text of --camera strictly; throws std::invalid_argument naming the bad field.
CameraSpec parse_camera_spec(const std::string& text);

// The default camera: looks along -z at the centre of the bounding sphere of all world-space
// vertices (centre and half diagonal of the axis-aligned box), from the distance at which the
// sphere fills the 45-degree vertical field of view (r / sin(22.5 deg)); near and far are the
// sphere's extent along the view direction widened by 1% of the radius each side.
void fit_camera(Scene& scene);

// Puts the camera at `spec`, up +y (or -z when looking straight up or down), with near and far
// fitted to the bounding sphere as above. Throws std::invalid_argument when eye equals at or
// the whole scene lies behind the eye.
void aim_camera(Scene& scene, const CameraSpec& spec);

}  // namespace zb
