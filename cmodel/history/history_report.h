// A pixel history as people and programs read it: text, and JSON that parses back into the
// history it came from (so a program's copy can be replayed: replay_error).
#pragma once

#include <string>

#include "pixel_history.h"
#include "scene/scene.h"

namespace zb {

// The history of one pixel of `f`, for people: the first value, each pass's state and the
// fragments that reached the pixel in it, each test's outcome, the blend, what was written,
// the frame operations, the final value. With `scene`, each triangle is named by its object and
// material.
std::string history_text(const FrameHistory& f, const PixelHistory& h, const Scene* scene = nullptr);

// Every pixel's history of `f` as one JSON document (docs/history.md "JSON").
std::string history_json(const FrameHistory& f, const std::string& scene_name, const std::string& method,
                         const Scene* scene = nullptr);

// Triangle `prim` of `scene` (scene order): "object 'name' triangle k, material 'm'".
std::string triangle_source(const Scene& scene, uint32_t prim);
// Back again; std::invalid_argument (with where) on a document that is not a history.
FrameHistory parse_history_json(const std::string& text);

}  // namespace zb
