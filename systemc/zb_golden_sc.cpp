#include "zb_golden_sc.h"

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
        rop_.begin_frame(c.width, c.height, c.depth_bits, c.clear, c.coverage_samples);
        pixel_issue_.assign(size_t(c.width) * size_t(c.height), 0);
        pixel_tile_.assign(pixel_issue_.size(), 0);
        tile_stamp_ = 0;
        break;
      case PassCommand::Kind::kBeginPass:
        rop_.begin_pass(c.state);
        frags_.resize(c.fragments);
        for (Fragment& f : frags_) f = frag_i.read();
        break;
      case PassCommand::Kind::kEndPass: stats_o.write(run_pass()); break;
      case PassCommand::Kind::kFrameOp: rop_.frame_op(c.op); break;
    }
  }
}

// The fragments in the RTL driver's order (tile by tile, pass order within a tile: a pixel
// sees them in pass order, so the result is render()'s), each after the clock cycles zb_rop's
// interlock gives it (rtlmodel/rtl_timing.h), then the drain. Tile load and store are not timed.
PassStats ZbGoldenSc::run_pass() {
  wait(clk_i.posedge_event());  // a pass starts on a clock edge, as zb_rop's would
  const sc_core::sc_time start = sc_core::sc_time_stamp();
  const Framebuffer& fb = rop_.framebuffer();
  bin_by_tile(frags_.data(), frags_.size(), fb.width, fb.height, kRtlTileW, kRtlTileH, bins_);
  uint64_t stream_cycles = 0;
  for (size_t t = 0; t + 1 < bins_.first.size(); ++t) {
    const uint32_t b = bins_.first[t], e = bins_.first[t + 1];
    if (b == e) continue;
    ++tile_stamp_;
    uint64_t now = 0, issue = 0;
    for (uint32_t k = b; k < e; ++k) {
      const Fragment& f = frags_[bins_.order[k]];
      const size_t p = fb.index(f.x, f.y);
      issue = rtl_issue_cycle(k == b, issue, pixel_tile_[p] == tile_stamp_, pixel_issue_[p]);
      pixel_tile_[p] = tile_stamp_;
      pixel_issue_[p] = issue;
      wait_cycles(issue - now);
      now = issue;
      rop_.draw(&f, 1);
    }
    wait_cycles(kRtlDrain);
    stream_cycles += issue + kRtlDrain;
  }
  PassStats s = rop_.end_pass();
  s.cycles = stream_cycles;
  busy_cycles_ += stream_cycles;
  busy_time_ += sc_core::sc_time_stamp() - start;
  return s;
}

}  // namespace zb::sc
