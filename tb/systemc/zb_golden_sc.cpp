#include "zb_golden_sc.h"

#include <algorithm>
#include <stdexcept>

#include "rtl_params.h"
#include "rtl_timing.h"

namespace zb::sc {

ZbGoldenSc::ZbGoldenSc(sc_core::sc_module_name name) : sc_core::sc_module(name) {
  SC_HAS_PROCESS(ZbGoldenSc);
  SC_THREAD(run);
}

void ZbGoldenSc::wait_cycles(uint64_t n) {
  for (uint64_t i = 0; i < n; ++i) wait(clk_i.posedge_event());
}

void ZbGoldenSc::run() {
  for (;;) {
    const PassCommand c = cmd_i.read();
    switch (c.kind) {
      case PassCommand::Kind::kBeginFrame:
        rop_.begin_frame(c.width, c.height, c.depth_bits, c.clear, c.coverage_samples, c.wboit);
        tiles_ = TileStates(c.width, c.height, kRtlTileW, c.depth_bits, c.clear);
        break;
      case PassCommand::Kind::kBeginPass:
        rop_.begin_pass(c.state);
        state_ = c.state;
        frags_.resize(c.fragments);
        for (Fragment& f : frags_) f = frag_i.read();
        break;
      case PassCommand::Kind::kEndPass: stats_o.write(run_pass()); break;
      case PassCommand::Kind::kFrameOp:
        rop_.frame_op(c.op);
        tiles_.frame_op(c.op);
        break;
    }
  }
}

// Per touched tile: its setup and load beats, its fragments in the order zb_rop issues them
// (tb/rtlmodel/rtl_timing.h: the issue window keeps pass order per pixel, so the result is
// render()'s), each at its issue cycle, the drain, its store beats (tb/rtlmodel/tile_io.h).
PassStats ZbGoldenSc::run_pass() {
  wait(clk_i.posedge_event());  // a pass starts on a clock edge, as zb_rop's would
  const sc_core::sc_time start = sc_core::sc_time_stamp();
  const Framebuffer& fb = rop_.framebuffer();
  bin_by_tile(frags_.data(), frags_.size(), fb.width, fb.height, kRtlTileW, kRtlTileH, bins_);
  uint64_t stream_cycles = 0;
  for (size_t t = 0; t + 1 < bins_.first.size(); ++t) {
    const uint32_t b = bins_.first[t], e = bins_.first[t + 1];
    if (b == e) continue;
    const uint64_t beats = tile_beats(kRtlTileW, kRtlTileH, kRtlBeat);
    const TileIo io = tiles_.plan(t, state_);
    tiles_.stored(t, io.store);
    const uint64_t load = kRtlTileSetup + (io.load ? beats : 0), store = io.store ? beats : 0;
    wait_cycles(load);
    io_cycles_ += load + store;
    issue_.resize(e - b);
    const uint64_t cycles = schedule_.run_tile(bins_, t, frags_.data(), fb.width, issue_.data());
    order_.resize(e - b);
    for (uint32_t k = 0; k < order_.size(); ++k) order_[k] = k;
    std::sort(order_.begin(), order_.end(),
              [&](uint32_t a, uint32_t c) { return issue_[a] < issue_[c]; });
    uint64_t now = 0;
    for (const uint32_t k : order_) {
      wait_cycles(issue_[k] - now);
      now = issue_[k];
      rop_.draw(&frags_[bins_.order[b + k]], 1);
    }
    wait_cycles(cycles - now + store);
    stream_cycles += cycles;
    busy_cycles_ += load + store;
  }
  PassStats s = rop_.end_pass();
  s.cycles = stream_cycles;
  busy_cycles_ += stream_cycles;
  busy_time_ += sc_core::sc_time_stamp() - start;
  return s;
}

}  // namespace zb::sc
