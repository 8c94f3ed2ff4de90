// Bytes the golden model holds, and the process's peak resident memory, for the memory
// targets of docs/bench.md.
#pragma once

#include <cstddef>
#include <cstdint>

#include "rop/fragment.h"
#include "scene/scene.h"

namespace zb {

// The golden model's frame buffers at width x height: colour, depth, coverage and peel planes.
uint64_t frame_bytes(int width, int height);

// The scene's meshes (positions, normals, triangles) and materials, as held in memory.
uint64_t scene_bytes(const Scene& scene);

// What the exact reference keeps per fragment: the fragment and its unrounded depth.
constexpr uint64_t kReferenceFragmentBytes = sizeof(Fragment) + sizeof(double);

// The peak resident set of this process so far (getrusage), in bytes.
uint64_t peak_rss_bytes();

}  // namespace zb
