// zblend conformance export: writes a suite (docs/conformance.md "The vectors"): per test its
// command stream and its expected planes from the golden model, and the manifest.
#pragma once

#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "suite.h"
#include "vectors.h"

namespace zb::conformance {

// One test's files, in memory.
struct TestVectors {
  std::string stream;  // stream.hex
  std::string expect[std::size(kPlanes)];  // expect.<plane>.hex, in kPlanes order
  uint64_t words = 0, fragments = 0;
  int passes = 0;
  std::string signature_sha256;  // of the expect files, concatenated in kPlanes order
  // A resolve wboit makes its colour from the accumulation plane: a DUT without one cannot run
  // it (the manifest's needs_accum; docs/conformance.md "Skipped tests").
  bool needs_accum = false;
  // What a DUT must support to run it, sorted (the manifest's "features"; docs/conformance.md
  // "Features and profiles").
  std::vector<std::string> features;
  std::string stream_sha256, expect_sha256[std::size(kPlanes)];  // each file's, for "files"
};

// The features `trace` asks of a DUT: only passes with fragments count (a pass without any loads
// no tile, so the DUT never sees its state).
std::vector<std::string> trace_features(const Trace& trace);

// The test's stream, and its planes after replay_trace onto GoldenRop.
TestVectors make_vectors(const TestSpec& t);

// What an export wrote.
struct ExportSummary {
  size_t tests = 0;
  uint64_t fragments = 0, bytes = 0;
};

// Writes `tests` as a suite in `dir`: into a temporary sibling, renamed to `dir` at the end, so a
// failure leaves no partial suite. `dir` must not exist, or be empty, or hold an earlier suite
// (its manifest says so), which is replaced. Throws ConformanceError, one line.
ExportSummary export_suite(const std::string& dir, const std::vector<TestSpec>& tests);

}  // namespace zb::conformance
