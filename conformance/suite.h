// The conformance suite: which tests it holds, in which order, and each test's command stream
// as a Trace (docs/conformance.md "The vectors"; the format is conformance_spec.md's, v1).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/trace.h"
#include "streams.h"

namespace zb::conformance {

// The manifest's "suite" and "version" (conformance_spec.md, format v1).
constexpr const char* kSuiteName = "zblend-conformance";
// Version 2: the random and hazard streams draw the accumulate blend (mode 5) too.
// Version 3: the accumulation plane (expect.accum.hex, in every test's signature; its widths in
// FRAME and the manifest's configs) and the wboit tests.
// Version 4: random-wboit, the random stream with resolves (the other tests as in version 3).
// Version 5: each test's "features" and the SHA-256 of each of its files; random-core (and -d16,
// -d32) at the end of their configs' groups, the random stream in the replace and alpha blends
// only, for subset DUTs (the other tests' bytes as in version 4).
// Version 6: the generated tests (generate.h), each aimed at goals of the reach (reach.h), at the
// end of their configs' groups; the tiers (quick chosen by the reach's ranking, full, and the
// seeded random tier); the manifest's "tier" and, for a generated test, "family" (the other
// tests' bytes as in version 5).
// Version 7: mlab-K's layers (blend 6): PASS carries the 16-bit pass state ([15:13] K - 1),
// FRAME_OP kind 5 resolves the layers; the scenes with mlab-2 and mlab-4, the layers family, the
// same-pixel runs of layers, at the end of their configs' groups (the other tests' bytes as in
// version 6).
// Version 8: at 16 and 32 bits, cad with opaque, states, values and same-pixel runs of the replace,
// alpha and additive blends, and the tiles, at the end of those configs' groups, so a DUT of one
// depth width meets every blend it has (the other tests' bytes as in version 7).
constexpr int kSuiteVersion = 8;

// Bad input to the kit (a malformed suite, a path it cannot use, an unknown test): one line.
struct ConformanceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The widths a DUT is built with: one build per config.
struct Config {
  std::string name;  // "d24-c16"
  int depth_bits = 24;
  int coverage_samples = 16;
  WboitFormat wboit;  // the accumulation planes' widths: the defaults in every config
};

enum class TestKind { kScene, kHazard, kRandom, kGenerated };
const char* to_string(TestKind k);  // "scene", "hazard", "random", "generated": the manifest's kind

// A generated test's family (generate.h).
enum class Family {
  kStates, kDepthBits, kValues, kCoverageValues, kAccumValues, kTiles, kSamePixel, kLayers
};
const char* to_string(Family f);  // "states", "depth-bits", ...: the manifest's family

struct TestSpec {
  std::string name;  // the test's directory
  Config config;
  TestKind kind = TestKind::kScene;
  std::string scene, method;  // kScene: a built-in scene and a pass plan
  uint64_t seed = 0;          // kHazard, kRandom
  RandomMix mix = RandomMix::kAll;  // kRandom: which states and frame operations (random_trace)
  Family family = Family::kStates;  // kGenerated: the family, its blend mode and peel setting
  BlendMode blend = BlendMode::kReplace;
  bool peel = false;
  int width = 0, height = 0;
  bool quick = false;         // in the CI-sized subset (export --quick)
  bool seeded = false;        // in the seeded random tier (export --seed N)
};

// Every test, grouped by config (the base config d24-c16 first), in a fixed order; with
// `quick`, the CI-sized subset, the same tests under the same names.
std::vector<TestSpec> suite_tests(bool quick);

// The seeded random tier (export --seed N): new random streams every seed, each reproducible
// from it, in every config, named <stream>-s<N> ("random-s7", "random-core-d16-s7").
std::vector<TestSpec> seeded_tests(uint64_t seed);

// "" in a default build. Otherwise a warning: the hazard tests follow this build's RTL tile and
// sample count (tb::HazardStimulus draws for them), so they differ from a default build's.
std::string build_warning();

// The test's frame, passes, fragments and frame operations (frame operations' values as the
// stream carries them: the background substituted, clear depths clamped to the far depth).
Trace test_trace(const TestSpec& t);

}  // namespace zb::conformance
