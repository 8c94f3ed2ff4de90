#include "pixel_history.h"

#include <stdexcept>

#include <fmt/core.h>

#include "geometry/frame_geometry.h"
#include "metrics/color_difference.h"

namespace zb {

PixelValue PixelValue::of(const Framebuffer& fb, size_t i) {
  PixelValue v;
  v.color = fb.color[i];
  v.depth = fb.depth[i];
  v.coverage = fb.coverage[i];
  v.peel = fb.peel[i];
  v.acc = fb.accum_at(i);
  v.reveal = fb.reveal_at(i);
  v.layers = fb.layers_at(i);
  return v;
}

void HistoryRecorder::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                                  int coverage_samples, const WboitFormat& wboit) {
  golden_.begin_frame(width, height, depth_bits, clear_color, coverage_samples, wboit);
  frame_ = FrameHistory{};
  frame_.width = width;
  frame_.height = height;
  frame_.depth_bits = depth_bits;
  frame_.coverage_samples = coverage_samples;
  frame_.wboit = wboit;
  frame_.arithmetic = golden_.arithmetic();
  slot_.assign(size_t(width) * size_t(height), -1);
  const Framebuffer& fb = golden_.framebuffer();
  for (const auto& [x, y] : asked_) {
    if (x < 0 || y < 0 || x >= width || y >= height)
      throw std::invalid_argument(fmt::format("pixel ({}, {}) is outside the {}x{} frame", x, y,
                                              width, height));
    const size_t i = fb.index(x, y);
    if (slot_[i] >= 0) throw std::invalid_argument(fmt::format("pixel ({}, {}) asked twice", x, y));
    slot_[i] = int32_t(frame_.pixels.size());
    PixelHistory h;
    h.x = x;
    h.y = y;
    h.first = PixelValue::of(fb, i);
    frame_.pixels.push_back(std::move(h));
  }
}

void HistoryRecorder::begin_pass(const RopState& state) {
  golden_.begin_pass(state);
  state_ = state;
  stream_index_ = 0;
  frame_.passes.push_back(PassRecord{label_, state, false});
  label_.clear();
}

void HistoryRecorder::draw(const Fragment* fragments, size_t count) {
  const Framebuffer& fb = golden_.framebuffer();
  for (size_t k = 0; k < count; ++k, ++stream_index_) {
    const Fragment& f = fragments[k];
    const size_t i = fb.index(f.x, f.y);
    const int32_t slot = i < slot_.size() ? slot_[i] : -1;
    if (slot < 0) continue;  // another pixel's: the datapath is per pixel
    HistoryEvent e;
    e.pass = frame_.passes.size() - 1;
    e.before = PixelValue::of(fb, i);
    FragmentRecord& r = e.fragment;
    r.index = stream_index_;
    r.fragment = f;
    if (state_.blend != BlendMode::kCoverage) {
      r.depth_tested = state_.depth_test;
      r.depth_passed = !r.depth_tested || depth_test(state_.depth_func, f.z, e.before.depth);
      r.peel_tested = state_.peel_test;
      r.peel_passed = !r.peel_tested || f.z > e.before.peel;
    }
    r.blended = e.before.color;
    if (r.depth_passed && r.peel_passed && state_.blend != BlendMode::kCoverage &&
        state_.blend != BlendMode::kAccumulate)
      r.blended = blend(state_.blend, f.color, e.before.color);
    r.writes = golden_.process(f);
    if (r.writes.color && state_.blend == BlendMode::kCoverage) r.blended = r.writes.rgba;
    e.after = PixelValue::of(fb, i);
    frame_.pixels[size_t(slot)].events.push_back(e);
  }
}

void HistoryRecorder::frame_op(const FrameOp& op) {
  std::vector<PixelValue> before;
  const Framebuffer& fb = golden_.framebuffer();
  for (const PixelHistory& h : frame_.pixels) before.push_back(PixelValue::of(fb, fb.index(h.x, h.y)));
  golden_.frame_op(op);
  for (size_t p = 0; p < frame_.pixels.size(); ++p) {
    PixelHistory& h = frame_.pixels[p];
    HistoryEvent e;
    e.kind = HistoryEvent::Kind::kFrameOp;
    e.pass = frame_.passes.size();
    e.op = op;
    e.before = before[p];
    e.after = PixelValue::of(fb, fb.index(h.x, h.y));
    h.events.push_back(e);
  }
}

FrameHistory HistoryRecorder::take() {
  const Framebuffer& fb = golden_.framebuffer();
  for (PixelHistory& h : frame_.pixels) h.final_value = PixelValue::of(fb, fb.index(h.x, h.y));
  return std::move(frame_);
}

bool same_stage_writes(const RetireRecord& r, const PixelWrites& g) {
  return same_stage_writes(r.x11, r.writes, g);
}

namespace {

// The planes where two values differ, "colour, depth".
std::string planes_differing(const PixelValue& a, const PixelValue& b) {
  std::string s;
  auto add = [&](bool differs, const char* name) {
    if (differs) s += (s.empty() ? "" : ", ") + std::string(name);
  };
  add(a.color != b.color, "colour");
  add(a.depth != b.depth, "depth");
  add(a.coverage != b.coverage, "coverage");
  add(a.peel != b.peel, "peel");
  add(a.acc != b.acc, "accumulation");
  add(a.reveal != b.reveal, "revealage");
  add(a.layers != b.layers, "layers");
  return s;
}

}  // namespace

std::optional<std::string> replay_error(const PixelHistory& h, const FrameHistory& f) {
  PixelValue v = h.first;
  for (size_t k = 0; k < h.events.size(); ++k) {
    const HistoryEvent& e = h.events[k];
    if (e.before != v)
      return fmt::format("pixel ({}, {}) event {}: its value before ({}) is not the replay's",
                         h.x, h.y, k, planes_differing(e.before, v));
    if (e.kind == HistoryEvent::Kind::kFragment) {
      const PixelWrites& w = e.fragment.writes;
      if (w.depth) v.depth = w.z;
      if (w.coverage) v.coverage = w.cov;
      if (w.color) v.color = w.rgba;
      if (w.accum) {
        v.acc = w.acc;
        v.reveal = w.reveal;
      }
      if (w.layers) v.layers = w.lay;
    } else {
      // The frame operation itself, on a one-pixel frame holding the value so far.
      Framebuffer one(1, 1, f.depth_bits, v.color, f.coverage_samples, f.wboit);
      one.depth[0] = v.depth;
      one.coverage[0] = v.coverage;
      one.peel[0] = v.peel;
      one.touch_accum();
      one.accum[0] = v.acc;
      one.reveal[0] = v.reveal;
      one.touch_layers();
      one.layers[0] = v.layers;
      apply_frame_op(one, e.op);
      v = PixelValue::of(one, 0);
    }
    if (e.after != v)
      return fmt::format("pixel ({}, {}) event {}: the replay's value after it differs from the "
                         "frame's ({})", h.x, h.y, k, planes_differing(e.after, v));
  }
  if (h.final_value != v)
    return fmt::format("pixel ({}, {}): the replay ends at a value other than the frame's ({})",
                       h.x, h.y, planes_differing(h.final_value, v));
  return std::nullopt;
}

namespace {

FrameHistory checked(FrameHistory f) {
  for (const PixelHistory& h : f.pixels)
    if (const auto error = replay_error(h, f))
      throw std::logic_error("pixel history does not add up: " + *error);
  return f;
}

}  // namespace

FrameHistory record_history(const RasterizedScene& rs, const PassPlan& plan,
                            const std::vector<std::pair<int, int>>& pixels) {
  HistoryRecorder recorder(pixels);
  render(rs, plan, recorder);
  FrameHistory f = recorder.take();
  if (f.passes.size() != plan.passes.size())
    throw std::logic_error("pixel history: the plan's passes and the recorded ones differ");
  f.from_scene = true;
  for (size_t p = 0; p < f.passes.size(); ++p)
    f.passes[p].edges = plan.passes[p].filter == PrimFilter::kEdges;
  const std::vector<ReferencePixel> ref = reference_pixels(rs, pixels);
  std::optional<LineVisibility> lines;
  if (plan_draws_edges(plan)) lines = line_visibility(rs);
  for (size_t k = 0; k < f.pixels.size(); ++k) {
    PixelHistory& h = f.pixels[k];
    h.reference = ref[k];
    h.delta_e = delta_e2000(h.final_value.color, ref[k].color);
    if (lines) h.line_reference = lines->at(h.x, h.y);
  }
  return checked(std::move(f));
}

FrameHistory record_history(const Trace& trace, const std::vector<std::pair<int, int>>& pixels,
                            const Arithmetic& arithmetic) {
  HistoryRecorder recorder(pixels, arithmetic);
  replay_trace(trace, recorder);
  return checked(recorder.take());
}

}  // namespace zb
