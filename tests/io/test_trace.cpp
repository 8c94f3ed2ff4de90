// Trace files: round trip, replay, and every kind of damage rejected with a located error.
#include <gtest/gtest.h>

#include <random>

#include "support/layers.h"
#include "rop/rop.h"
#include "io/trace.h"
#include "pipeline/passes.h"
#include "scene/builtin_scenes.h"

namespace {

zb::Trace small_trace() {
  const zb::RasterizedScene rs = zbtest::layer_scene(
      {{9000, {40, 60, 200, 255}}, {1000, {230, 30, 30, 128}}}, {255, 255, 255, 255});
  return zb::make_trace(rs, *zb::find_plan("three-pass"));
}

TEST(Trace, StatePackingRoundTripsEveryValidWord) {
  int valid = 0;
  for (uint32_t bits = 0; bits < (1u << zb::kStateBits); ++bits) {
    zb::RopState s;
    if (!zb::unpack_state(uint16_t(bits), s)) continue;
    ++valid;
    EXPECT_EQ(zb::pack_state(s), bits);
  }
  // Blend codes 0..6 of the 3-bit field are valid (6 is layers): 7 of 8.
  EXPECT_EQ(valid, 7 << (zb::kStateBits - 3));
  zb::RopState s;
  EXPECT_FALSE(zb::unpack_state(uint16_t(6u << 5 | 1u << 5), s));  // blend code 7
  EXPECT_TRUE(zb::unpack_state(uint16_t(6u << 5 | 3u << 13), s));
  EXPECT_EQ(s.blend, zb::BlendMode::kLayers);
  EXPECT_EQ(s.layers, 4);
}

// Version 4 files (13-bit state, no layers) still read; layers in one are refused.
TEST(Trace, VersionFourReadsWithoutLayers) {
  std::string bytes = zb::serialize_trace(small_trace());
  bytes[8] = 4;  // the version word, little-endian
  const zb::Trace back = zb::parse_trace(bytes, "v4");
  EXPECT_EQ(back.passes.size(), 3u);
  const std::string current = zb::serialize_trace(back);
  EXPECT_EQ(current[8], 5);
  EXPECT_EQ(current.substr(12), bytes.substr(12));
  zb::Trace layers = small_trace();
  layers.passes[1].state.blend = zb::BlendMode::kLayers;
  std::string v4 = zb::serialize_trace(layers);
  EXPECT_NO_THROW(zb::parse_trace(v4, "v5"));
  v4[8] = 4;
  EXPECT_THROW(zb::parse_trace(v4, "v4"), zb::TraceError);
}

TEST(Trace, RoundTripAndReplayMatchRender) {
  zb::Trace t = small_trace();
  ASSERT_EQ(t.passes.size(), 3u);
  t.wboit = {20, 12, 5};
  EXPECT_EQ(zb::serialized_size(t), zb::serialize_trace(t).size());
  const zb::Trace back = zb::parse_trace(zb::serialize_trace(t), "mem");
  EXPECT_EQ(back.wboit, t.wboit);
  ASSERT_EQ(back.passes.size(), t.passes.size());
  EXPECT_EQ(back.width, t.width);
  EXPECT_EQ(back.clear_color, t.clear_color);
  for (size_t p = 0; p < t.passes.size(); ++p) {
    EXPECT_EQ(back.passes[p].name, t.passes[p].name);
    EXPECT_EQ(zb::pack_state(back.passes[p].state), zb::pack_state(t.passes[p].state));
    ASSERT_EQ(back.passes[p].fragments.size(), t.passes[p].fragments.size());
    for (size_t i = 0; i < t.passes[p].fragments.size(); ++i) {
      const zb::Fragment &a = back.passes[p].fragments[i], &b = t.passes[p].fragments[i];
      EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z && a.color == b.color &&
                  a.front == b.front && a.coverage == b.coverage && a.prim == b.prim);
    }
  }
  zb::GoldenRop from_trace, direct;
  zb::replay_trace(back, from_trace);
  const zb::RasterizedScene rs = zbtest::layer_scene(
      {{9000, {40, 60, 200, 255}}, {1000, {230, 30, 30, 128}}}, {255, 255, 255, 255});
  zb::render(rs, *zb::find_plan("three-pass"), direct);
  EXPECT_EQ(from_trace.framebuffer().color, direct.framebuffer().color);
  EXPECT_EQ(from_trace.framebuffer().depth, direct.framebuffer().depth);
}

void expect_rejected(const std::string& bytes, const char* needle) {
  try {
    zb::parse_trace(bytes, "t.zbt");
    ADD_FAILURE() << "accepted a damaged trace; wanted '" << needle << "'";
  } catch (const zb::TraceError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("trace 't.zbt': byte "), std::string::npos) << e.what();
  }
}

// A scene's plan serialised straight from the feeder: the same bytes as its Trace's, within
// trace_bound, never a byte past the capacity it is given.
TEST(Trace, SceneStreamIsTheTraceSerialised) {
  int coverage_passes = 0, edge_passes = 0;
  for (const char* scene : {"cad", "parts"}) {
    const zb::RasterizedScene rs =
        zb::rasterize_scene(*zb::builtin_scene(scene), zb::Viewport{64, 48});
    for (const zb::PassPlan& plan : zb::pass_plans()) {
      const zb::Trace t = zb::make_trace(rs, plan);
      const std::string want = zb::serialize_trace(t);
      const size_t bound = zb::trace_bound(rs, plan);
      ASSERT_LE(want.size(), bound) << scene << " " << plan.name;
      std::vector<uint8_t> buf(bound + 16, 0xcd);
      const zb::TraceCounts c = zb::serialize_trace(rs, plan, buf.data(), bound);
      ASSERT_EQ(c.bytes, want.size()) << scene << " " << plan.name;
      EXPECT_EQ(std::string(buf.begin(), buf.begin() + std::ptrdiff_t(c.bytes)), want)
          << scene << " " << plan.name;
      EXPECT_EQ(c.passes, t.passes.size());
      uint64_t fragments = 0;
      for (const zb::TracePass& p : t.passes) {
        fragments += p.fragments.size();
        coverage_passes += zb::is_coverage_pass(p.state) && !p.fragments.empty();
      }
      for (const zb::PassState& p : plan.passes) edge_passes += p.filter == zb::PrimFilter::kEdges;
      EXPECT_EQ(c.fragments, fragments);
      // One byte short: refused, nothing written past it.
      if (want.size() > 64) {
        std::vector<uint8_t> small(want.size() + 16, 0xcd);
        EXPECT_THROW(zb::serialize_trace(rs, plan, small.data(), want.size() - 1), std::logic_error);
        EXPECT_TRUE(std::all_of(small.begin() + std::ptrdiff_t(want.size() - 1), small.end(),
                                [](uint8_t b) { return b == 0xcd; }))
            << scene << " " << plan.name;
      }
    }
  }
  EXPECT_GT(coverage_passes, 0);  // the bound's box case was exercised
  EXPECT_GT(edge_passes, 0);
}

// Fragments block by block: the same fragments in order, each block at most
// kTraceReadRecords, between `pass` and `pass_end`; a damaged fragment stops the scan at its byte
// with the blocks before it delivered.
TEST(Trace, BlocksGiveThePassWhole) {
  zb::Trace t;
  t.width = t.height = 128;
  std::mt19937 rng(7);
  zb::TracePass pass{"big", {}, zb::RopState{}, {}};
  for (size_t i = 0; i < 2 * zb::kTraceReadRecords + 123; ++i)
    pass.fragments.push_back({uint16_t(rng() % 128), uint16_t(rng() % 128), uint32_t(rng() % 65536),
                              {uint8_t(rng()), 0, 0, 255}});
  t.passes.push_back(pass);
  t.passes.push_back({"none", {}, zb::RopState{}, {}});
  std::string bytes = zb::serialize_trace(t);
  std::vector<zb::Fragment> got;
  std::vector<std::string> calls;
  zb::TraceScan scan;
  scan.pass = [&](const zb::TracePass& p, uint64_t) {
    EXPECT_TRUE(p.fragments.empty());
    calls.push_back("pass " + p.name);
  };
  scan.fragments = [&](const zb::Fragment* f, size_t n) {
    EXPECT_LE(n, zb::kTraceReadRecords);
    got.insert(got.end(), f, f + n);
    calls.push_back("block");
  };
  scan.pass_end = [&] { calls.push_back("end"); };
  zb::scan_trace(bytes, "mem", scan);
  EXPECT_EQ(calls, (std::vector<std::string>{"pass big", "block", "block", "block", "end",
                                              "pass none", "end"}));
  ASSERT_EQ(got.size(), pass.fragments.size());
  for (size_t i = 0; i < got.size(); ++i)
    ASSERT_TRUE(got[i].x == pass.fragments[i].x && got[i].y == pass.fragments[i].y &&
                got[i].z == pass.fragments[i].z && got[i].color == pass.fragments[i].color)
        << i;
  // Fragment 2 * kTraceReadRecords + 5 (in the third block) moved outside the frame.
  const size_t first = 8 + 4 * 5 + 3 + 4 + 4 + 4 + 3 + 4 + 2 + 8;  // header, pass "big" head
  const size_t bad = first + (2 * zb::kTraceReadRecords + 5) * zb::kTraceFragmentBytes;
  bytes[bad] = char(0xff), bytes[bad + 1] = char(0xff);
  got.clear();
  calls.clear();
  try {
    zb::scan_trace(bytes, "mem", scan);
    FAIL() << "the damaged fragment was taken";
  } catch (const zb::TraceError& e) {
    EXPECT_EQ(e.byte, bad) << e.what();
  }
  EXPECT_EQ(got.size(), 2 * zb::kTraceReadRecords);
  EXPECT_EQ(calls, (std::vector<std::string>{"pass big", "block", "block"}));
}

TEST(Trace, EveryTruncationIsRejected) {
  const std::string bytes = zb::serialize_trace(small_trace());
  for (size_t n = 0; n < bytes.size(); ++n) expect_rejected(bytes.substr(0, n), "");
  expect_rejected(bytes + "x", "after the last pass");
}

// Offsets into the header: magic 0, version 8, width 12, height 16, depth bits 20, coverage
// samples 24, accumulation, revealage and weight widths 28, 29, 30, clear colour 31, pass
// count 35.
TEST(Trace, DamagedFieldsNameTheProblem) {
  const std::string good = zb::serialize_trace(small_trace());
  auto patched = [&](size_t at, std::initializer_list<uint8_t> b) {
    std::string s = good;
    for (uint8_t v : b) s[at++] = char(v);
    return s;
  };
  expect_rejected(patched(0, {'X'}), "bad magic");
  expect_rejected(patched(8, {1}), "version 1");
  expect_rejected(patched(12, {0, 0}), "out of range");
  expect_rejected(patched(20, {40}), "depth width 40");
  expect_rejected(patched(24, {3}), "coverage samples 3");
  expect_rejected(patched(24, {32}), "coverage samples 32");
  expect_rejected(patched(28, {7}), "accumulation 7");
  expect_rejected(patched(29, {17}), "revealage 17");
  expect_rejected(patched(30, {17}), "weight 17");
  // First pass: name length at 39, name, frame op count (0 here), then the state word.
  const size_t name_len = uint8_t(good[39]);
  expect_rejected(patched(43 + name_len, {0xff}), "frame ops is more than");
  expect_rejected(patched(47 + name_len, {0xe0, 0x00}), "invalid pass state");  // blend 7
  expect_rejected(patched(49 + name_len, {0xff, 0xff, 0xff, 0xff}), "fragments announced");
  const size_t first_fragment = 57 + name_len;
  expect_rejected(patched(first_fragment, {0xff, 0x00}), "outside the 4x4 frame");
  expect_rejected(patched(first_fragment + 4, {0xff, 0xff, 0xff, 0xff}), "exceeds 24 bits");
  // Flags: bit 0 front, bits 8..15 coverage (at most the header's 16), the rest reserved.
  expect_rejected(patched(first_fragment + 12, {0x00, 17}), "coverage 17 exceeds the 16");
  expect_rejected(patched(first_fragment + 12, {0x80}), "reserved bits");
  expect_rejected(patched(first_fragment + 14, {0x01}), "reserved bits");
}

TEST(Trace, RandomDamageNeverCrashes) {
  const std::string good = zb::serialize_trace(small_trace());
  std::mt19937 rng(7);
  int rejected = 0;
  for (int i = 0; i < 2000; ++i) {
    std::string s = good;
    for (int k = 0; k < 3; ++k) s[rng() % s.size()] = char(rng());
    try {
      zb::parse_trace(s, "fuzz");
    } catch (const zb::TraceError&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
}

TEST(Trace, MissingFile) {
  EXPECT_THROW(zb::read_trace("/nonexistent/x.zbt"), zb::TraceError);
}

}  // namespace
