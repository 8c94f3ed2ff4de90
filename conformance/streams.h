// The suite's synthetic streams: the testbench's hazard stimulus and a random stream of its own,
// each as a Trace for a given sample count (and, for the random one, depth width).
#pragma once

#include <cstdint>

#include "io/trace.h"

namespace zb::conformance {

// tb::HazardStimulus(seed) on one RTL tile (kRtlTileW x kRtlTileH, 64 x 64 in a default build),
// 24-bit depth: `passes` passes of `per_pass` fragments, runs on 1 to 4 pixels in
// read-modify-write states. Its coverage counts, drawn for kRtlCoverageSamples, are scaled to
// `coverage_samples` (coverage_for_samples).
Trace hazard_trace(uint64_t seed, int coverage_samples, int passes, size_t per_pass);

// A count of `from` samples as a count of `to`: proportional, rounded to nearest, with the edge
// cases kept: 0 stays 0, `from` becomes `to`, and a partial count stays partial (1 to to - 1)
// when `to` allows one.
uint8_t coverage_for_samples(int count, int from, int to);

// A random stream on a width x height frame: every valid pass state, frame operations between
// passes, and fragments at the fields' edge values (depth 0, the far depth and one below it,
// depths repeated across the stream; alpha 0, 1, 254, 255; coverage 0, 1, N - 1, N), a share
// of them in runs on 1 to 4 pixels. Drawn from tb::Rng(seed). With `wboit`, half the passes
// accumulate and a resolve (frame operation 4) follows a fifth of them, among the clears; the
// draws without it are those of suite version 2 on. With kCore, only what every ROP has: the
// replace and alpha blends, no peel test (every depth function, depth write and colour mask
// still drawn), for a DUT of a subset profile.
enum class RandomMix { kAll, kWboit, kCore };
Trace random_trace(uint64_t seed, int width, int height, int depth_bits, int coverage_samples,
                   int passes, size_t per_pass, RandomMix mix = RandomMix::kAll);

}  // namespace zb::conformance
