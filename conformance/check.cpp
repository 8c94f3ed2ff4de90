#include "check.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "geometry/geometry.h"
#include "sha256.h"
#include "suite.h"
#include "vectors.h"

namespace zb::conformance {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ManifestTest {
  std::string name;
  int width = 0, height = 0;
  std::string signature_sha256;
  WboitFormat wboit;         // its config's accumulation widths
  bool needs_accum = false;  // its colour is resolved from the accumulation plane
  std::string tier;          // "quick", "full" or "random"
  std::map<std::string, std::string> files;  // file name: SHA-256, in name order
};

// A test name is a directory of the suite: letters, digits, '-', '_' and '.', not first.
bool valid_name(const std::string& s) {
  if (s.empty() || s[0] == '.') return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
}

bool is_sha256(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<ManifestTest> read_manifest(const fs::path& suite) {
  const fs::path path = suite / "manifest.json";
  auto malformed = [&](const std::string& what) {
    return ConformanceError(fmt::format("SUITE {}: {}", path.string(), what));
  };
  std::error_code ec;
  if (!fs::is_directory(suite, ec))
    throw ConformanceError(fmt::format("SUITE {}: not a directory (give the directory 'zblend "
                                       "conformance export' wrote)", suite.string()));
  const std::optional<std::string> text = read_text(path);
  if (!text)
    throw malformed(fmt::format("cannot read: {} (give the directory 'zblend conformance export' "
                                "wrote)", std::strerror(errno)));
  std::vector<ManifestTest> tests;
  try {
    const json j = json::parse(*text);
    if (!j.is_object() || j.value("suite", "") != kSuiteName)
      throw malformed(fmt::format("not a zblend conformance suite (\"suite\" is not \"{}\")", kSuiteName));
    if (j.at("version") != kSuiteVersion)
      throw malformed(fmt::format("version {} is not supported (this zblend reads {})",
                                  j.at("version").dump(), kSuiteVersion));
    std::map<std::string, WboitFormat> configs;
    for (const json& c : j.at("configs")) {
      const WboitFormat f{c.at("acc_bits").get<int>(), c.at("rev_bits").get<int>(),
                          c.at("weight_bits").get<int>()};
      if (!valid_wboit_format(f))
        throw malformed(fmt::format("config '{}': acc_bits {}, rev_bits {}, weight_bits {} are "
                                    "out of range", c.at("name").get<std::string>(), f.acc_bits,
                                    f.rev_bits, f.weight_bits));
      configs[c.at("name").get<std::string>()] = f;
    }
    std::set<std::string> seen;
    for (const json& t : j.at("tests")) {
      ManifestTest m;
      m.name = t.at("name").get<std::string>();
      m.width = t.at("width").get<int>();
      m.height = t.at("height").get<int>();
      m.signature_sha256 = t.at("signature_sha256").get<std::string>();
      m.needs_accum = t.at("needs_accum").get<bool>();
      const std::string config = t.at("config").get<std::string>();
      if (!configs.count(config))
        throw malformed(fmt::format("test '{}': config '{}' is not in \"configs\"", m.name, config));
      m.wboit = configs[config];
      if (!valid_name(m.name)) throw malformed(fmt::format("test name '{}' is not a directory name", m.name));
      if (!seen.insert(m.name).second) throw malformed(fmt::format("test '{}' is listed twice", m.name));
      if (m.width < 1 || m.width > kMaxFrameSize || m.height < 1 || m.height > kMaxFrameSize)
        throw malformed(fmt::format("test '{}': frame {}x{} is out of range", m.name, m.width, m.height));
      if (!is_sha256(m.signature_sha256))
        throw malformed(fmt::format("test '{}': signature_sha256 is not 64 hex digits", m.name));
      m.tier = t.value("tier", "");
      for (const auto& [file, sha] : t.at("files").items()) {
        if (!valid_name(file) || !sha.is_string() || !is_sha256(sha.get<std::string>()))
          throw malformed(fmt::format("test '{}': \"files\": '{}' is not a file name with 64 hex "
                                      "digits", m.name, file));
        m.files[file] = sha.get<std::string>();
      }
      // The files the kit's commands read are hashed, so each must be listed.
      std::vector<std::string> read = {"stream.hex"};
      for (Plane p : kPlanes) read.push_back(fmt::format("expect.{}.hex", to_string(p)));
      for (const std::string& f : read)
        if (!m.files.count(f)) throw malformed(fmt::format("test '{}': \"files\" lacks {}", m.name, f));
      tests.push_back(std::move(m));
    }
  } catch (const json::exception& e) {
    throw malformed(e.what());
  }
  return tests;
}

// Every file of every test held to the manifest's SHA-256 in scripts/conformance.py's order
// and words (load_suite), so that the runner and every command refuse a corrupt suite alike.
void verify_files(const fs::path& suite, const std::vector<ManifestTest>& tests) {
  const char* again = "export it again: zblend conformance export DIR";
  fs::path base = fs::absolute(suite).lexically_normal();  // as os.path.abspath writes it
  if (!base.has_filename()) base = base.parent_path();
  for (const ManifestTest& t : tests)
    for (const auto& [file, want] : t.files) {
      const std::string path = (base / t.name / file).string();
      errno = 0;
      const std::optional<std::string> text = read_text(path);
      if (!text)
        throw ConformanceError(fmt::format("corrupt suite: {}: {} ({})", path,
                                           std::strerror(errno ? errno : EIO), again));
      const std::string got = sha256_hex(*text);
      if (got != want)
        throw ConformanceError(fmt::format("corrupt suite: {}: SHA-256 {}..., the manifest says "
                                           "{}... (truncated or changed; {})", path,
                                           got.substr(0, 16), want.substr(0, 16), again));
    }
}

// A file of hex words, one a line, each kept as `digits` lower-case digits (a word may be wider
// than 64 bits: the accumulation word). `strict` (expect files): exactly `digits` lower-case
// digits a line. Otherwise (a DUT's got files, $writememh's): 1 to `digits` digits of either
// case, surrounding blanks, and blank lines and // comments skipped. Returns an error or "".
std::string parse_words(const std::string& text, int digits, bool strict, const std::string& file,
                        std::vector<std::string>& out) {
  std::istringstream in(text);
  std::string line;
  for (size_t n = 1; std::getline(in, line); ++n) {
    std::string w = line;
    if (!strict) {
      const size_t a = w.find_first_not_of(" \t\r"), b = w.find_last_not_of(" \t\r");
      w = a == std::string::npos ? "" : w.substr(a, b - a + 1);
      if (w.empty() || w.rfind("//", 0) == 0) continue;
    }
    const bool hex = !w.empty() && w.size() <= size_t(digits) &&
                     (!strict || w.size() == size_t(digits)) &&
                     std::all_of(w.begin(), w.end(), [&](char c) {
                       return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') ||
                              (!strict && c >= 'A' && c <= 'F');
                     });
    if (!hex)
      return fmt::format("{} line {}: '{}' is not a hex word of {}{} digits", file, n,
                         w.substr(0, 40), strict ? "" : "at most ", digits);
    std::transform(w.begin(), w.end(), w.begin(),
                   [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); });
    out.push_back(std::string(size_t(digits) - w.size(), '0') + w);
  }
  return "";
}

// One plane of one test: its state for the report line.
struct PlaneCheck {
  std::string state = "ok";  // "ok", "missing", "malformed", "N pixels differ"
  std::string first;         // the first problem, "" when ok
  int x = -1, y = -1;        // its pixel, when a word differs
  size_t within = 0;         // colour words that differ within the tolerance
  int most = 0;              // their largest channel difference
};

// The largest difference between two packed RGBA8 words' channels.
int channel_difference(const std::string& a, const std::string& b) {
  const uint32_t x = uint32_t(std::stoul(a, nullptr, 16)), y = uint32_t(std::stoul(b, nullptr, 16));
  int most = 0;
  for (int sh = 0; sh < 32; sh += 8)
    most = std::max(most, std::abs(int((x >> sh) & 0xffu) - int((y >> sh) & 0xffu)));
  return most;
}

// `tolerance` (colour only): a word whose every channel is within it of the expected one counts
// as `within`, not as differing.
PlaneCheck check_plane(const ManifestTest& t, Plane plane, const std::vector<std::string>& expect,
                       const fs::path& got_path, int tolerance = 0) {
  PlaneCheck c;
  const std::optional<std::string> text = read_text(got_path);
  if (!text) {
    c.state = "missing";
    c.first = fmt::format("missing {}", got_path.string());
    return c;
  }
  std::vector<std::string> got;
  const std::string error =
      parse_words(*text, hex_digits(plane, t.wboit), false, got_path.string(), got);
  if (error.empty() && got.size() != expect.size()) {
    c.state = "malformed";
    c.first = fmt::format("{}: {} words, expected {} ({}x{})", got_path.string(), got.size(),
                          expect.size(), t.width, t.height);
    return c;
  }
  if (!error.empty()) {
    c.state = "malformed";
    c.first = error;
    return c;
  }
  size_t differ = 0;
  for (size_t i = 0; i < expect.size(); ++i) {
    if (got[i] == expect[i]) continue;
    if (tolerance > 0 && plane == Plane::kColor) {
      const int d = channel_difference(got[i], expect[i]);
      if (d <= tolerance) {
        ++c.within;
        c.most = std::max(c.most, d);
        continue;
      }
    }
    if (differ++ == 0) {
      c.x = int(i % size_t(t.width));
      c.y = int(i / size_t(t.width));
      c.first = fmt::format("{} pixel ({}, {}): expected {}, got {}", to_string(plane), c.x, c.y,
                            expect[i], got[i]);
    }
  }
  if (differ) c.state = fmt::format("{} pixel{} differ{}", differ, differ == 1 ? "" : "s", differ == 1 ? "s" : "");
  return c;
}

// The testbench's digest of the planes after each pass (got.passes.hex: "<passes done> <16 hex
// digits>" a line) against the golden model's: "" when every line matches, else the first
// differing pass. A pass another overwrites is seen here, not in the final planes.
std::string check_passes(const fs::path& path, const std::vector<PassDigest>& golden) {
  const std::optional<std::string> text = read_text(path);
  if (!text) return fmt::format("{}: cannot read: {}", path.string(), std::strerror(errno));
  std::istringstream in(*text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    unsigned long long pass = 0, digest = 0;
    char tail = 0;
    if (std::sscanf(line.c_str(), "%llu %16llx%c", &pass, &digest, &tail) != 2 || line.size() < 18)
      return fmt::format("{} line {}: '{}' is not \"<passes> <16 hex digits>\"", path.string(), n,
                         line);
    if (pass < 1 || pass > golden.size())
      return fmt::format("{} line {}: pass {} of a stream of {}", path.string(), n, pass,
                         golden.size());
    if (digest != golden[pass - 1].digest)
      return fmt::format("the planes after pass {} of {} differ from the golden model's (digest "
                         "{:016x}, expected {:016x}; got.passes.hex line {})", pass, golden.size(),
                         digest, golden[pass - 1].digest, n);
  }
  return "";
}

TestResult check_test(const fs::path& suite, const fs::path& out, const ManifestTest& t,
                      bool dut_accum, const CheckRule& rule) {
  const Arithmetic& arithmetic = rule.arithmetic;
  // The expected planes, held to the manifest's hash first: a damaged suite is not a DUT failure.
  std::string expect_text[std::size(kPlanes)];
  Sha256 hash;
  for (size_t p = 0; p < std::size(kPlanes); ++p) {
    const fs::path path = suite / t.name / fmt::format("expect.{}.hex", to_string(kPlanes[p]));
    std::optional<std::string> text = read_text(path);
    if (!text)
      throw ConformanceError(fmt::format("SUITE {}: cannot read: {} (export the suite again)",
                                         path.string(), std::strerror(errno)));
    hash.update(*text);
    expect_text[p] = std::move(*text);
  }
  if (hash.hex() != t.signature_sha256)
    throw ConformanceError(fmt::format("SUITE {}: the expect files of test '{}' do not match its "
                                       "signature_sha256 (export the suite again)",
                                       suite.string(), t.name));
  // The stream (verified above) replayed once, for the digests after each pass (exact: a DUT
  // judged by thresholds is judged on its final planes alone) and, in a declared arithmetic other
  // than zblend's, for the expected planes.
  const fs::path passes_path = out / t.name / "got.passes.hex";
  std::error_code ec;
  const bool digests = !rule.cts && fs::exists(passes_path, ec);
  std::optional<GoldenReplay> replay;
  if (digests || !arithmetic.is_zblend())
    replay = replay_golden(read_stream((suite / t.name / "stream.hex").string()), arithmetic);
  if (!arithmetic.is_zblend())
    for (size_t p = 0; p < std::size(kPlanes); ++p) expect_text[p] = plane_hex(replay->frame, kPlanes[p]);
  TestResult r{t.name, true, false, ""};
  if (t.needs_accum && !dut_accum) {
    r.skipped = true;
    r.line = fmt::format("skip  {}: needs the accumulation plane (a resolve wboit), which the DUT "
                         "does not have", t.name);
    return r;
  }
  std::string first, states;
  size_t within = 0;
  int most = 0;
  for (size_t p = 0; p < std::size(kPlanes); ++p) {
    const Plane plane = kPlanes[p];
    std::vector<std::string> expect;
    const fs::path expect_path = suite / t.name / fmt::format("expect.{}.hex", to_string(plane));
    std::string error =
        parse_words(expect_text[p], hex_digits(plane, t.wboit), true, expect_path.string(), expect);
    if (error.empty() && expect.size() != size_t(t.width) * size_t(t.height))
      error = fmt::format("{}: {} words for a {}x{} frame", expect_path.string(), expect.size(),
                          t.width, t.height);
    if (!error.empty()) throw ConformanceError("SUITE " + error + " (export the suite again)");
    if (plane == Plane::kAccum && !dut_accum) {
      states += fmt::format(", {} not checked (the DUT has none)", to_string(plane));
      continue;
    }
    const PlaneCheck c =
        check_plane(t, plane, expect, out / t.name / fmt::format("got.{}.hex", to_string(plane)),
                    rule.cts ? kCtsColorThreshold : 0);
    within += c.within;
    most = std::max(most, c.most);
    if (first.empty()) {
      first = c.first;
      r.first_x = c.x;
      r.first_y = c.y;
    }
    states += fmt::format("{}{} {}", p ? ", " : "", to_string(plane), c.state);
  }
  const std::string passes = digests ? check_passes(passes_path, replay->digests) : "";
  if (first.empty() && !passes.empty()) first = passes + " (the final planes match: a later pass "
                                                "overwrote what this one did wrong)";
  else if (!passes.empty()) states += "; " + passes;
  r.pass = first.empty();
  r.cts = r.pass && within > 0;
  r.line = !r.pass  ? fmt::format("FAIL  {}: {} [{}]", t.name, first, states)
           : r.cts  ? fmt::format("cts   {}: {} colour pixel{} within the CTS blend threshold ({} a "
                                  "channel; the largest difference {}), not exact",
                                  t.name, within, within == 1 ? "" : "s", kCtsColorThreshold, most)
                    : fmt::format("pass  {}", t.name);
  return r;
}

}  // namespace

std::vector<std::string> verified_test_names(const std::string& suite) {
  const std::vector<ManifestTest> tests = read_manifest(suite);
  verify_files(suite, tests);
  std::vector<std::string> names;
  for (const ManifestTest& t : tests) names.push_back(t.name);
  return names;
}

Trace read_test_stream(const std::string& suite, const std::string& test) {
  const std::vector<std::string> names = verified_test_names(suite);
  if (std::find(names.begin(), names.end(), test) == names.end())
    throw ConformanceError(fmt::format("TEST: '{}' is not a test of {} (its manifest.json names "
                                       "them)", test, suite));
  try {
    return read_stream((fs::path(suite) / test / "stream.hex").string());
  } catch (const TraceError& e) {
    throw ConformanceError(e.what());
  }
}

std::optional<RunRecord> read_run(const std::string& out) {
  const fs::path path = fs::path(out) / "results.json";
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  auto malformed = [&](const std::string& what) {
    return ConformanceError(fmt::format("OUT {}: {} (scripts/conformance.py writes it; give "
                                        "--tests or --quick to choose the tests instead)",
                                        path.string(), what));
  };
  const std::optional<std::string> text = read_text(path);
  if (!text) throw malformed(fmt::format("cannot read: {}", std::strerror(errno)));
  RunRecord run;
  try {
    const json j = json::parse(*text);
    run.accum_plane = j.value("accum_plane", true);
    run.arithmetic = j.value("arithmetic", std::string("zblend"));
    for (const json& t : j.at("tests")) {
      const std::string verdict = t.at("verdict").get<std::string>();
      // Simulated: it has got files, or lacks them as a failure (not_supported and not_run
      // tests were never simulated).
      if (verdict == "pass" || verdict == "cts_pass" || verdict == "fail" || verdict == "timeout")
        run.tests.push_back(t.at("name").get<std::string>());
    }
  } catch (const json::exception& e) {
    throw malformed(e.what());
  }
  return run;
}

std::vector<TestResult> check_suite(const std::string& suite, const std::string& out,
                                    const Selection& only, bool dut_accum,
                                    const std::function<void(const TestResult&)>& report,
                                    const CheckRule& rule) {
  const std::vector<ManifestTest> tests = read_manifest(suite);
  verify_files(suite, tests);
  const std::vector<std::string>& names = only.names;
  for (const std::string& name : names)
    if (std::none_of(tests.begin(), tests.end(), [&](const ManifestTest& t) {
          return t.name == name && (!only.quick || t.tier == "quick");
        }))
      throw ConformanceError(fmt::format("{}: '{}' is not a test of {}{} (its manifest.json "
                                         "lists them)", only.from, name, suite,
                                         only.quick ? "'s quick tier" : ""));
  std::vector<TestResult> results;
  for (const ManifestTest& t : tests) {
    if (!names.empty() && std::find(names.begin(), names.end(), t.name) == names.end()) continue;
    if (only.quick && t.tier != "quick") continue;
    results.push_back(check_test(suite, out, t, dut_accum, rule));
    if (report) report(results.back());
  }
  if (only.quick && results.empty())
    throw ConformanceError(fmt::format("--quick: {} has no test of the quick tier (its "
                                       "manifest.json's \"tier\")", suite));
  return results;
}

}  // namespace zb::conformance
