// A pixel's history (docs/history.md): every fragment that reached the pixel, in order, with
// the pass state, the tests' outcomes, the blend's inputs and what was written; the frame
// operations between passes; the pixel's first and final value on every plane. Recorded by a
// backend that wraps the golden model, only for the pixels asked, and checked by replaying it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/trace.h"
#include "pipeline/render.h"
#include "reference/line_reference.h"
#include "reference/reference.h"
#include "rop/rop.h"

namespace zb {

// One pixel on every plane (colour, depth, coverage, peel, accumulation and revealage).
struct PixelValue {
  Rgba8 color;
  uint32_t depth = 0;
  uint8_t coverage = 0;
  uint32_t peel = 0;
  std::array<uint32_t, 4> acc{};
  uint32_t reveal = 0;
  PixelLayers layers;  // mlab-K's, between a layers pass and its resolve
  static PixelValue of(const Framebuffer& fb, size_t i);
  friend bool operator==(const PixelValue& a, const PixelValue& b) {
    return a.color == b.color && a.depth == b.depth && a.coverage == b.coverage &&
           a.peel == b.peel && a.acc == b.acc && a.reveal == b.reveal && a.layers == b.layers;
  }
  friend bool operator!=(const PixelValue& a, const PixelValue& b) { return !(a == b); }
};

// What the datapath did with one fragment at the pixel.
struct FragmentRecord {
  size_t index = 0;        // in its pass's fragment stream (every pixel's fragments counted)
  Fragment fragment;
  bool depth_tested = false, depth_passed = true;  // the depth test, against before.depth
  bool peel_tested = false, peel_passed = true;    // the peel test: z > before.peel
  Rgba8 blended;           // the blend's output before the colour mask (a colour write's)
  PixelWrites writes;      // what it wrote (the golden model's write log)
};

struct HistoryEvent {
  enum class Kind : uint8_t { kFragment, kFrameOp } kind = Kind::kFragment;
  size_t pass = 0;         // its pass; a frame operation's: the pass it comes before (the
                           // plan's pass count: after the last)
  FragmentRecord fragment; // kFragment
  FrameOp op;              // kFrameOp
  PixelValue before, after;
};

struct PassRecord {
  std::string name;
  RopState state;
  bool edges = false;      // draws the scene's edges (Fragment::prim an edge), not triangles
};

// The RTL's retire of a fragment at the pixel (zblend pixel --backend rtl): its stage (X4 writes
// depth and coverage, X11 colour or the accumulation), the cycles since reset it was accepted
// and its write landed, and what the RTL wrote. An extra retire has no fragment; a missing one
// never wrote.
struct RetireRecord {
  bool x11 = false;
  bool extra = false, missing = false;
  size_t pass = 0;
  uint32_t index = 0;       // the fragment's in its pass
  uint32_t stream = 0;      // in the RTL run's stream (its group's passes in order)
  uint64_t accepted = 0, cycle = 0;
  PixelWrites writes;
};

// Whether an RTL retire's writes are the golden model's for its stage.
bool same_stage_writes(const RetireRecord& r, const PixelWrites& golden);

struct PixelHistory {
  int x = 0, y = 0;
  PixelValue first;        // at the frame's start
  std::vector<HistoryEvent> events;
  PixelValue final_value;  // the framebuffer's at the frame's end
  // A scene's: the exact reference there (its sorted layers, its colour) and the method's
  // CIEDE2000 against it.
  std::optional<ReferencePixel> reference;
  double delta_e = 0;
  // A scene's under a method that draws edges: the exact line reference there (its fair one;
  // the shaded CIEDE2000 means nothing for it).
  std::optional<EdgePixel> line_reference;
  std::vector<RetireRecord> rtl;  // with the RTL beside: its retires at the pixel, in order
  bool rtl_ran = false;
  PixelValue rtl_final;           // and the RTL's frame there at the end
};

struct FrameHistory {
  int width = 0, height = 0, depth_bits = 0, coverage_samples = 0;
  bool from_scene = false;           // Fragment::prim names a scene's triangle or edge
  WboitFormat wboit;
  Arithmetic arithmetic;  // the blend arithmetic replayed in (a DUT's declared one; rop/arithmetic.h)
  std::vector<PassRecord> passes;
  std::vector<PixelHistory> pixels;  // in the order asked
};

// The golden model, recording the histories of `pixels` (each inside the frame, distinct).
// Fragments at other pixels are counted in the stream and dropped: the datapath and the frame
// operations are per pixel, so the asked pixels end as in a full render, at the cost of their
// own fragments. framebuffer() holds the asked pixels only; a render without histories does not
// come here.
class HistoryRecorder final : public Backend {
 public:
  explicit HistoryRecorder(std::vector<std::pair<int, int>> pixels, const Arithmetic& arith = {})
      : asked_(std::move(pixels)) {
    golden_.set_arithmetic(arith);
  }
  const char* name() const override { return "golden"; }
  using Backend::begin_frame;
  void begin_frame(int width, int height, int depth_bits, Rgba8 clear_color, int coverage_samples,
                   const WboitFormat& wboit) override;
  void label_pass(const std::string& name) override { label_ = name; }
  void begin_pass(const RopState& state) override;
  using Backend::draw;
  void draw(const Fragment* fragments, size_t count) override;
  PassStats end_pass() override { return golden_.end_pass(); }
  void frame_op(const FrameOp& op) override;
  const Framebuffer& framebuffer() const override { return golden_.framebuffer(); }

  // The frame's histories, their final values taken from the framebuffer now.
  FrameHistory take();

 private:
  GoldenRop golden_;
  std::vector<std::pair<int, int>> asked_;
  std::vector<int32_t> slot_;  // per frame pixel: its history's index, or -1
  FrameHistory frame_;
  std::string label_;
  RopState state_;
  size_t stream_index_ = 0;
};

// Replays `h` from its first value: each fragment's writes and each frame operation's result in
// turn, checking each event's `before` against the value so far and the end against
// final_value. Returns the first disagreement, or nothing when the history adds up.
std::optional<std::string> replay_error(const PixelHistory& h, const FrameHistory& f);

// Renders `plan` on the golden model recording `pixels`' histories, each checked by
// replay_error (a history that does not add up is std::logic_error: an internal error), with
// the exact reference at each pixel.
FrameHistory record_history(const RasterizedScene& rs, const PassPlan& plan,
                            const std::vector<std::pair<int, int>>& pixels);
// The same for a trace's replay (a .zbt file, a conformance test's stream), in `arithmetic` (a
// DUT's declared one: the conformance path).
FrameHistory record_history(const Trace& trace, const std::vector<std::pair<int, int>>& pixels,
                            const Arithmetic& arithmetic = {});


}  // namespace zb
