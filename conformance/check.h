// zblend conformance check: a DUT's planes (OUT/<test>/got.<plane>.hex) against a suite's
// expected signatures (docs/conformance.md "Checking signatures").
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/trace.h"
#include "rop/arithmetic.h"

namespace zb::conformance {

struct TestResult {
  std::string name;
  bool pass = false;
  bool skipped = false;  // needs a plane the DUT does not have: neither passed nor failed
  // "pass  NAME", "skip  NAME: why", or "FAIL  NAME: the first problem [each plane's state]"
  std::string line;
  int first_x = -1, first_y = -1;  // a failed test's first differing pixel, if a word differs
  bool cts = false;  // passed by the CTS threshold only, not exactly ("cts   NAME: ..."); pass too
};

// Every command that reads a suite first holds each file of each test to the manifest's SHA-256
// ("files"), as scripts/conformance.py does and in its words ("corrupt suite: PATH: SHA-256
// ..."): a corrupt suite is bad input, never a DUT's failure, nor a stream explained that the
// DUT never ran.

// The names of SUITE's tests, in its order, once every file is verified. Throws
// ConformanceError on a malformed manifest or a corrupt suite.
std::vector<std::string> verified_test_names(const std::string& suite);

// TEST's stream of SUITE, once every file is verified. Throws ConformanceError on a corrupt suite,
// a name that is not a test ("TEST: ..."), or a stream that does not decode.
Trace read_test_stream(const std::string& suite, const std::string& test);

// What a run of scripts/conformance.py left in OUT/results.json: the tests it simulated (verdict
// pass, fail or timeout), in its order, and whether the DUT had the accumulation plane.
struct RunRecord {
  std::vector<std::string> tests;
  bool accum_plane = true;
  std::string arithmetic = "zblend";  // the profile's declared arithmetic (its name)
};
// nullopt when OUT has no results.json. Throws ConformanceError on one it cannot read.
std::optional<RunRecord> read_run(const std::string& out);

// Which tests to check: `names` (none: every test), and of those only the quick tier.
struct Selection {
  std::vector<std::string> names;
  std::string from = "--tests";  // where the names came from, for the error naming a stray one
  bool quick = false;
};

// How a DUT's planes are held to the golden model's: exactly, in its declared arithmetic; or, for
// a DUT that cannot say how it rounds, by the verdict the Khronos CTS's blend tests give: each
// colour channel within 2^(8 - bits) * 5 / 2 + 2 of zblend's (4 for RGBA8), every other plane
// exact, and reported apart from exact passes (docs/conformance.md "The CTS verdict").
struct CheckRule {
  Arithmetic arithmetic;
  bool cts = false;
};
constexpr int kCtsColorThreshold = (1 << (8 - 8)) * 5 / 2 + 2;

// Checks the selected tests of SUITE, in the suite's order, and reports each result to `report`
// as it is decided. Without `dut_accum` (a DUT with no accumulation plane) a test that needs the
// plane is skipped and no test's got.accum.hex is read. A malformed or corrupt suite (manifest,
// files against their SHA-256, expect files against their signature_sha256), a selected name
// that is not a test or an empty quick tier throws ConformanceError; a got file that is missing
// or malformed fails its test. Under a declared arithmetic other than zblend's (docs/datapath.md
// "Declared arithmetic") the expected planes are the test's stream replayed on the golden model
// in that arithmetic, not the expect files (which are still held to their hashes).
std::vector<TestResult> check_suite(const std::string& suite, const std::string& out,
                                    const Selection& only, bool dut_accum,
                                    const std::function<void(const TestResult&)>& report,
                                    const CheckRule& rule = {});

}  // namespace zb::conformance
