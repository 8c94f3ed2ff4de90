// zblend conformance check: a DUT's planes (OUT/<test>/got.<plane>.hex) against a suite's
// expected signatures (docs/conformance.md "Checking signatures").
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace zb::conformance {

struct TestResult {
  std::string name;
  bool pass = false;
  bool skipped = false;  // needs a plane the DUT does not have: neither passed nor failed
  // "pass  NAME", "skip  NAME: why", or "FAIL  NAME: the first problem [each plane's state]"
  std::string line;
  int first_x = -1, first_y = -1;  // a failed test's first differing pixel, if a word differs
};

// The names of SUITE's tests, in its order. Throws ConformanceError on a malformed manifest.
std::vector<std::string> suite_test_names(const std::string& suite);

// Checks every test of SUITE (or those in `only`, in the suite's order) and reports each result
// to `report` as it is decided. Without `dut_accum` (a DUT with no accumulation plane) a test
// that needs the plane is skipped and no test's got.accum.hex is read. A malformed suite (manifest, or expect files that do not match
// their signature_sha256) or a name in `only` that is not a test throws ConformanceError; a got
// file that is missing or malformed fails its test.
std::vector<TestResult> check_suite(const std::string& suite, const std::string& out,
                                    const std::vector<std::string>& only, bool dut_accum,
                                    const std::function<void(const TestResult&)>& report);

}  // namespace zb::conformance
