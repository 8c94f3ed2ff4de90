// The camera: fitted to the scene's bounds, or aimed where the user says (docs/scenes.md).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene.h"

namespace zb {

// A user camera: `eye=x,y,z,at=x,y,z,fov=deg[,up=x,y,z]`, each field at most once, in any order.
struct CameraSpec {
  glm::vec3 eye{0.0f};
  glm::vec3 at{0.0f};
  float fov_y_deg = 45.0f;
  std::optional<glm::vec3> up;  // default: +y, or -z when looking straight up or down
};

// Parses a camera text strictly; throws std::invalid_argument naming the bad field (also for an
// `up` that is zero or parallel to the view direction). The message names no option: the
// command line that took the text says which (app/options.cpp).
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
