// The two loaders behind load_scene_bytes (scene_file.h), each checking its format before the
// library reads it. Internal to the golden model.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "io/scene_file.h"

namespace zb {

// Wavefront OBJ with its MTL libraries (obj_loader.cpp), through tinyobjloader.
Scene load_obj(const std::string& path, const std::string& text, const SceneFileReader& read);
// glTF 2.0, text or binary (gltf_loader.cpp), through tinygltf.
Scene load_gltf(const std::string& path, const std::string& data, bool binary,
                const SceneFileReader& read);

// Textures are not sampled: a warning on `scene` for each material its objects use for which
// textured(m) holds.
void warn_ignored_textures(Scene& scene, const std::function<bool(uint32_t)>& textured);

}  // namespace zb
