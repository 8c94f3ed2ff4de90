// One interface for the two implementations of the datapath: the golden model and the RTL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fragment.h"
#include "framebuffer.h"

namespace zb {

// Counters of one pass, in fragments and pixel accesses.
struct PassStats {
  uint64_t fragments_in = 0;
  uint64_t fragments_passed = 0;  // passed the depth test
  uint64_t color_reads = 0;       // destination reads for blending
  uint64_t color_writes = 0;
  uint64_t depth_reads = 0;
  uint64_t depth_writes = 0;
  uint64_t cycles = 0;            // clock cycles; 0 where the backend has no clock

  uint64_t fragments_killed() const { return fragments_in - fragments_passed; }
  PassStats& operator+=(const PassStats& o);
};

// Applies `op` to `fb` (the host's rule, shared by every backend's host side).
void apply_frame_op(Framebuffer& fb, const FrameOp& op);

// The colour and depth of a rectangle of pixels, from memory: a tile loaded between passes
// (the virtual platform's TILE_LOAD). Row by row, width * height words each; no depth: kept.
// The other planes (coverage, peel, accumulation, layers) are kept.
struct RegionLoad {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  std::vector<Rgba8> color;
  std::vector<uint32_t> depth;
};
// std::invalid_argument for a rectangle outside `fb`'s frame, planes of another size or a depth
// above the frame's depth_max.
void check_region_load(const Framebuffer& fb, const RegionLoad& r);
// Writes `r` into `fb`, checked first (nothing written when it throws).
void apply_region_load(Framebuffer& fb, const RegionLoad& r);
const char* to_string(FrameOpKind k);

class Backend {
 public:
  virtual ~Backend() = default;
  virtual const char* name() const = 0;
  // Starts a frame: buffers of the given size cleared to `clear_color`, the far depth and
  // coverage 0, for a sample pattern of `coverage_samples` (valid_coverage_samples) per pixel;
  // accumulation 0 and revealage 1.0 in the widths of `wboit` (valid_wboit_format).
  virtual void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                           int coverage_samples, const WboitFormat& wboit) = 0;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                   int coverage_samples) {
    begin_frame(width, height, depth_bits, clear_color, coverage_samples, WboitFormat{});
  }
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color) {
    begin_frame(width, height, depth_bits, clear_color, kDefaultCoverageSamples);
  }
  // Names the pass about to begin, for reports; backends may ignore it.
  virtual void label_pass(const std::string& /*name*/) {}
  virtual void begin_pass(const RopState& state) = 0;
  // Sends `count` fragments, in order; a pass may draw many times.
  virtual void draw(const Fragment* fragments, size_t count) = 0;
  void draw(const std::vector<Fragment>& fragments) { draw(fragments.data(), fragments.size()); }
  virtual PassStats end_pass() = 0;
  // A frame operation between passes (never inside one).
  virtual void frame_op(const FrameOp& op) = 0;
  // A region loaded between passes (apply_region_load's rule). Backends without it throw
  // std::logic_error.
  virtual void load_region(const RegionLoad& r);
  // The frame's last call, after its final frame operations: a backend that runs passes later
  // than end_pass (the RTL's tile schedule) runs them here and puts their counters in `stats`
  // (one a pass, end_pass's in order). Others leave `stats` as it is.
  virtual void finish_frame(std::vector<PassStats>& /*stats*/) {}
  virtual const Framebuffer& framebuffer() const = 0;
};

}  // namespace zb
