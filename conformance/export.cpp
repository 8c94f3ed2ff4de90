#include "export.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "rop/rop.h"
#include "sha256.h"

namespace zb::conformance {

namespace fs = std::filesystem;

std::vector<std::string> trace_features(const Trace& trace) {
  std::set<std::string> f{fmt::format("depth_bits.{}", trace.depth_bits),
                          fmt::format("coverage_samples.{}", trace.coverage_samples)};
  auto resolves = [&](const std::vector<FrameOp>& ops) {
    for (const FrameOp& op : ops)
      if (op.kind == FrameOpKind::kResolveWboit) f.insert("accum_plane");
  };
  for (const TracePass& p : trace.passes) {
    resolves(p.frame_ops);
    if (p.fragments.empty()) continue;
    const RopState& s = p.state;
    f.insert(fmt::format("blend.{}", to_string(s.blend)));
    if (s.blend == BlendMode::kAccumulate) f.insert("accum_plane");
    if (s.blend == BlendMode::kLayers) f.insert(fmt::format("layers.{}", s.layers));
    const bool coverage = is_coverage_pass(s);
    if (s.depth_test && !coverage) f.insert(fmt::format("depth_func.{}", to_string(s.depth_func)));
    if (s.depth_test && s.depth_write) f.insert("depth_write");
    if ((s.color_mask & kMaskRgba) != kMaskRgba) f.insert("color_mask");
    if (s.peel_test && !coverage) f.insert("peel_test");
  }
  resolves(trace.final_ops);
  return {f.begin(), f.end()};
}

TestVectors make_vectors(const TestSpec& t) {
  const Trace trace = test_trace(t);
  TestVectors v;
  const Stream s = encode_stream(trace);
  v.stream = s.hex;
  v.words = s.words;
  v.fragments = s.fragments;
  v.passes = int(trace.passes.size());
  v.features = trace_features(trace);
  v.stream_sha256 = sha256_hex(v.stream);
  auto resolves = [](const std::vector<FrameOp>& ops) {
    return std::any_of(ops.begin(), ops.end(),
                       [](const FrameOp& op) { return op.kind == FrameOpKind::kResolveWboit; });
  };
  v.needs_accum = resolves(trace.final_ops) ||
                  std::any_of(trace.passes.begin(), trace.passes.end(),
                              [&](const TracePass& p) { return resolves(p.frame_ops); });
  GoldenRop golden;
  replay_trace(trace, golden);
  Sha256 hash;
  for (size_t p = 0; p < std::size(kPlanes); ++p) {
    v.expect[p] = plane_hex(golden.framebuffer(), kPlanes[p]);
    v.expect_sha256[p] = sha256_hex(v.expect[p]);
    hash.update(v.expect[p]);
  }
  v.signature_sha256 = hash.hex();
  return v;
}

namespace {

// Writes `root`/`name`; an error names the file as it will be in the suite.
void write_file(const fs::path& root, const std::string& name, const std::string& bytes) {
  std::ofstream out(root / name, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  out.close();
  if (!out) throw ConformanceError(fmt::format("cannot write {}: {}", name, std::strerror(errno)));
}

// True when `dir` holds a suite this command wrote (so it may be replaced).
bool holds_suite(const fs::path& dir) {
  std::ifstream in(dir / "manifest.json");
  if (!in) return false;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() && j.value("suite", "") == kSuiteName;
}

// A new directory beside `dir`, named after it: the suite is written there, then renamed.
fs::path make_sibling(const fs::path& dir, const char* what) {
  for (int n = 0;; ++n) {
    const fs::path p = dir.parent_path() /
                       fmt::format(".{}.{}-{}-{}", dir.filename().string(), what, ::getpid(), n);
    std::error_code ec;
    if (fs::create_directory(p, ec)) return p;
    if (ec || n > 100)
      throw ConformanceError(fmt::format("cannot create a directory beside {}: {}", dir.string(),
                                         ec ? ec.message() : "too many taken"));
  }
}

nlohmann::json manifest_entry(const TestSpec& t, const TestVectors& v) {
  nlohmann::json e = {{"name", t.name},
                      {"config", t.config.name},
                      {"kind", to_string(t.kind)},
                      {"width", t.width},
                      {"height", t.height},
                      {"passes", v.passes},
                      {"fragments", v.fragments},
                      {"words", v.words},
                      {"needs_accum", v.needs_accum},
                      {"features", v.features},
                      {"signature_sha256", v.signature_sha256}};
  nlohmann::json& files = e["files"] = {{"stream.hex", v.stream_sha256}};
  for (size_t p = 0; p < std::size(kPlanes); ++p)
    files[fmt::format("expect.{}.hex", to_string(kPlanes[p]))] = v.expect_sha256[p];
  e["tier"] = t.seeded ? "random" : t.quick ? "quick" : "full";
  if (t.kind == TestKind::kScene) {
    e["scene"] = t.scene;
    e["method"] = t.method;
  } else if (t.kind == TestKind::kGenerated) {
    e["family"] = to_string(t.family);
  } else {
    e["seed"] = t.seed;
  }
  return e;
}

// Writes every test and the manifest into `tmp`.
ExportSummary write_suite(const fs::path& tmp, const std::vector<TestSpec>& tests) {
  nlohmann::json configs = nlohmann::json::array(), entries = nlohmann::json::array();
  ExportSummary sum;
  for (const TestSpec& t : tests) {
    if (std::none_of(configs.begin(), configs.end(),
                     [&](const nlohmann::json& c) { return c["name"] == t.config.name; }))
      configs.push_back({{"name", t.config.name}, {"depth_bits", t.config.depth_bits},
                         {"coverage_samples", t.config.coverage_samples},
                         {"acc_bits", t.config.wboit.acc_bits},
                         {"rev_bits", t.config.wboit.rev_bits},
                         {"weight_bits", t.config.wboit.weight_bits}});
    const TestVectors v = make_vectors(t);
    fs::create_directory(tmp / t.name);
    write_file(tmp, t.name + "/stream.hex", v.stream);
    sum.bytes += v.stream.size();
    for (size_t p = 0; p < std::size(kPlanes); ++p) {
      write_file(tmp, fmt::format("{}/expect.{}.hex", t.name, to_string(kPlanes[p])), v.expect[p]);
      sum.bytes += v.expect[p].size();
    }
    entries.push_back(manifest_entry(t, v));
    ++sum.tests;
    sum.fragments += v.fragments;
  }
  // nlohmann::json keeps keys sorted: the same bytes every run.
  const nlohmann::json manifest = {{"suite", kSuiteName}, {"version", kSuiteVersion},
                                   {"configs", configs}, {"tests", entries}};
  const std::string text = manifest.dump(2) + "\n";
  write_file(tmp, "manifest.json", text);
  sum.bytes += text.size();
  return sum;
}

}  // namespace

ExportSummary export_suite(const std::string& dir_text, const std::vector<TestSpec>& tests) {
  const fs::path dir = fs::absolute(dir_text).lexically_normal();
  const fs::path target = dir.has_filename() ? dir : dir.parent_path();  // "out/" is "out"
  std::error_code ec;
  const bool exists = fs::exists(target, ec);
  if (exists && !fs::is_empty(target, ec) && !holds_suite(target))
    throw ConformanceError(fmt::format("{}: is not empty and holds no zblend suite (choose a new "
                                       "directory, or empty it)", dir_text));
  fs::create_directories(target.parent_path(), ec);
  if (ec)
    throw ConformanceError(fmt::format("{}: cannot create its parent: {}", dir_text, ec.message()));
  const fs::path tmp = make_sibling(target, "tmp");
  try {
    const ExportSummary sum = write_suite(tmp, tests);
    if (exists) {
      // An empty directory or an earlier suite: moved aside, then removed once the new one is in.
      const fs::path old = make_sibling(target, "old");
      fs::rename(target, old);
      fs::rename(tmp, target);
      fs::remove_all(old);
    } else {
      fs::rename(tmp, target);
    }
    return sum;
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(tmp, ec);
    throw ConformanceError(fmt::format("{}: {}", dir_text, e.what()));
  } catch (const ConformanceError& e) {
    fs::remove_all(tmp, ec);
    throw ConformanceError(fmt::format("{}: {} (nothing was written)", dir_text, e.what()));
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace zb::conformance
