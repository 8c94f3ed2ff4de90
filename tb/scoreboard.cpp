#include "scoreboard.h"

#include <tuple>

#include <fmt/core.h>

#include "rtl_params.h"
#include "tile_io.h"

namespace zb {
namespace {

std::string rgba_text(Rgba8 c) { return fmt::format("rgba({},{},{},{})", c.r, c.g, c.b, c.a); }

// Does the RTL's stage agree with the golden writes? Only the planes the stage writes count.
bool same(RetireStage stage, const PixelWrites& r, const PixelWrites& g) {
  return same_stage_writes(stage == RetireStage::kX11, r, g);
}

// Earlier in one model's time: tiles run in tile order, then by cycle.
auto when(const Divergence& d) {
  return std::make_tuple(d.retire.tile_y0, d.retire.tile_x0, d.retire.tile_cycle,
                         int(d.retire.stage));
}

}  // namespace

std::string describe_writes(RetireStage stage, const PixelWrites& w, int depth_bits) {
  const int zd = (depth_bits + 3) / 4;
  if (stage == RetireStage::kX4)
    return (w.depth ? fmt::format("depth 0x{:0{}x}", w.z, zd) : std::string("no depth")) +
           (w.coverage ? fmt::format(", coverage {}", w.cov) : std::string(", no coverage"));
  return (w.color ? "colour " + rgba_text(w.rgba) : std::string("no colour")) +
         (w.accum ? ", accumulation " + accum_text(w.acc, w.reveal) : std::string()) +
         (w.layers ? ", " + layers_text(w.lay, depth_bits) : std::string());
}

void Scoreboard::begin_pass() {
  expected_.clear();
  rtl_.clear();
  golden_ = nullptr;
  first_.reset();
}

void Scoreboard::arm(const Framebuffer& golden) {
  golden_ = &golden;
  rtl_.assign(expected_.size(), RtlRetired{});
}

bool Scoreboard::diverge(Divergence d) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!first_ || when(d) < when(*first_)) first_ = std::move(d);
  return false;
}

bool Scoreboard::retire(const Retire& r) {
  Divergence d;
  d.retire = r;
  const char* stage = to_string(r.stage);
  switch (r.kind) {
    case Retire::Kind::kExtra:
      d.what = fmt::format("{} retired at a pixel where no accepted fragment waited ({})", stage,
                           describe_writes(r.stage, r.writes, kRtlDepthBits));
      return diverge(std::move(d));
    case Retire::Kind::kMissing:
      d.golden = expected_.at(r.fragment);
      d.what = fmt::format("fragment never retired at {} (the golden model wrote {})", stage,
                           describe_writes(r.stage, d.golden, kRtlDepthBits));
      return diverge(std::move(d));
    case Retire::Kind::kRetired: break;
  }
  const int s = r.stage == RetireStage::kX11;
  RtlRetired& rec = rtl_.at(r.fragment);
  rec.cycle[s] = r.tile_cycle;
  rec.writes[s] = r.writes;
  const PixelWrites& g = expected_.at(r.fragment);
  if (same(r.stage, r.writes, g)) return true;
  d.golden = g;
  d.what = fmt::format("{}: rtl wrote {}; golden {}", stage,
                       describe_writes(r.stage, r.writes, kRtlDepthBits),
                       describe_writes(r.stage, g, kRtlDepthBits));
  return diverge(std::move(d));
}

bool Scoreboard::store(const StoreBeat& b) {
  if (!golden_) return true;
  const TileSweep sweep(golden_->width, golden_->height, b.tile_x0, b.tile_y0);
  const BeatWords want = sweep.load(*golden_, b.beat);
  static constexpr const char* kNames[] = {"colour", "depth", "coverage", "peel"};
  for (int l = 0; l < kRtlBeat; ++l) {
    const int64_t i = sweep.pixel(*golden_, b.beat, l);
    if (i < 0) continue;
    Divergence d;
    d.store = true;
    d.retire.x = int(i % golden_->width);
    d.retire.y = int(i / golden_->width);
    d.retire.tile_x0 = b.tile_x0;
    d.retire.tile_y0 = b.tile_y0;
    d.retire.tile_cycle = b.tile_cycle;
    d.retire.stage = RetireStage::kX11;  // after every retire of the tile
    for (int p = 0; p < kWordPlanes; ++p) {
      if (!(b.planes & (1u << p))) continue;
      const uint32_t got = (*b.words)[size_t(p)][size_t(l)], exp = want[size_t(p)][size_t(l)];
      if (got == exp) continue;
      d.what = p == 0 ? fmt::format("tile store beat {} lane {}: colour rtl {} golden {}", b.beat,
                                    l, rgba_text(unpack_rgba(got)), rgba_text(unpack_rgba(exp)))
                      : fmt::format("tile store beat {} lane {}: {} rtl 0x{:x} golden 0x{:x}",
                                    b.beat, l, kNames[p], got, exp);
      return diverge(std::move(d));
    }
    const AccumWord& got = b.words->accum[size_t(l)];
    if ((b.planes & kPlaneAccum) && got != want.accum[size_t(l)]) {
      d.what = fmt::format("tile store beat {} lane {}: accumulation rtl {} golden {}", b.beat, l,
                           accum_text(got), accum_text(want.accum[size_t(l)]));
      return diverge(std::move(d));
    }
  }
  return true;
}

}  // namespace zb
