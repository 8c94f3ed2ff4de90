#include "zb_cosim_sc.h"

#include <chrono>

#include <fmt/core.h>

#include "zb_golden_sc.h"
#include "zb_rtl_sc.h"

namespace zb::sc {

ZbCosimSc::ZbCosimSc(sc_core::sc_module_name name,
                     std::vector<std::pair<std::string, Trace>> traces, const ZbGoldenSc& golden,
                     const ZbRtlSc& rtl, sc_core::sc_time clock_period)
    : sc_core::sc_module(name),
      traces_(std::move(traces)),
      golden_(golden),
      rtl_(rtl),
      period_(clock_period) {
  SC_HAS_PROCESS(ZbCosimSc);
  SC_THREAD(run);
}

void ZbCosimSc::run() {
  for (const auto& [name, trace] : traces_) results_.push_back(run_trace(name, trace));
  sc_core::sc_stop();
}

void ZbCosimSc::send(const PassCommand& c) {
  golden_cmd_o.write(c);
  rtl_cmd_o.write(c);
}

// Every plane of both buffers; the first difference is kept, the first of the run reported.
void ZbCosimSc::compare(CosimResult& r, const char* where) {
  const Framebuffer& g = golden_.framebuffer();
  const Framebuffer& t = rtl_.framebuffer();
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const size_t i = g.index(x, y);
      const Rgba8 a = g.color[i], b = t.color[i];
      if (a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a && g.depth[i] == t.depth[i] &&
          g.coverage[i] == t.coverage[i] && g.peel[i] == t.peel[i] && g.accum_at(i) == t.accum_at(i) &&
          g.reveal_at(i) == t.reveal_at(i))
        continue;
      if (r.mismatches++ == 0)
        r.first_mismatch = fmt::format(
            "{}: pixel ({},{}): golden rgba {},{},{},{} depth {} coverage {} peel {} {}; "
            "rtl rgba {},{},{},{} depth {} coverage {} peel {} {}", where, x, y, a.r, a.g, a.b,
            a.a, g.depth[i], g.coverage[i], g.peel[i], accum_text(g.accum_at(i), g.reveal_at(i)), b.r,
            b.g, b.b, b.a, t.depth[i], t.coverage[i], t.peel[i],
            accum_text(t.accum_at(i), t.reveal_at(i)));
    }
}

CosimResult ZbCosimSc::run_trace(const std::string& name, const Trace& t) {
  const auto wall0 = std::chrono::steady_clock::now();
  CosimResult r;
  r.name = name;
  const sc_core::sc_time golden0 = golden_.busy_time(), rtl0 = rtl_.busy_time();
  const uint64_t gtile0 = golden_.tile_io_cycles(), rtile0 = rtl_.tile_io_cycles();
  send(PassCommand::begin_frame(t.width, t.height, t.depth_bits, t.clear_color,
                                t.coverage_samples, t.wboit));
  for (size_t p = 0; p < t.passes.size(); ++p) {
    const TracePass& pass = t.passes[p];
    for (const FrameOp& op : pass.frame_ops) send(PassCommand::frame_op(op));
    send(PassCommand::begin_pass(pass.state, pass.fragments.size()));
    for (const Fragment& f : pass.fragments) {
      golden_frag_o.write(f);
      rtl_frag_o.write(f);
    }
    send(PassCommand::end_pass());
    const PassStats gs = golden_stats_i.read(), rs = rtl_stats_i.read();
    r.fragments += pass.fragments.size();
    ++r.passes;
    r.golden_stream_cycles += gs.cycles;
    r.rtl_stream_cycles += rs.cycles;
    const std::string where = fmt::format("pass {} ({})", p, pass.name);
    if (gs.fragments_in != rs.fragments_in || gs.fragments_passed != rs.fragments_passed ||
        gs.depth_reads != rs.depth_reads || gs.depth_writes != rs.depth_writes ||
        gs.color_reads != rs.color_reads || gs.color_writes != rs.color_writes) {
      if (r.mismatches++ == 0)
        r.first_mismatch = fmt::format(
            "{}: counters differ: golden in {} passed {} depth r/w {}/{} colour r/w {}/{}; "
            "rtl in {} passed {} depth r/w {}/{} colour r/w {}/{}", where, gs.fragments_in,
            gs.fragments_passed, gs.depth_reads, gs.depth_writes, gs.color_reads, gs.color_writes,
            rs.fragments_in, rs.fragments_passed, rs.depth_reads, rs.depth_writes, rs.color_reads,
            rs.color_writes);
    }
    compare(r, where.c_str());
  }
  for (const FrameOp& op : t.final_ops) send(PassCommand::frame_op(op));
  if (!t.final_ops.empty()) {
    wait(period_);  // both modules idle on their command fifo: one clock sees the ops applied
    compare(r, "final frame operations");
  }
  r.golden_tile_cycles = golden_.tile_io_cycles() - gtile0;
  r.rtl_tile_cycles = rtl_.tile_io_cycles() - rtile0;
  r.golden_time = golden_.busy_time() - golden0;
  r.rtl_time = rtl_.busy_time() - rtl0;
  r.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall0)
                  .count();
  return r;
}

}  // namespace zb::sc
