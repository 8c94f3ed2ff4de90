// The Verilated zb_rop (verilator --sc) as a SystemC module with the golden one's ports
// (zb_golden_sc.h): a thread drives the tile protocol of tb/rtlmodel/tile_driver.cpp on its signals.
#pragma once

#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include <systemc>

#include "rop/fixed.h"
#include "rop/framebuffer.h"
#include "rtl_params.h"
#include "tile_bins.h"
#include "tile_io.h"
#include "zb_sc_types.h"

class Vzb_rop_sc;

namespace zb::sc {

class ZbRtlSc : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i;
  sc_core::sc_fifo_in<PassCommand> cmd_i;
  sc_core::sc_fifo_in<Fragment> frag_i;
  sc_core::sc_fifo_out<PassStats> stats_o;

  explicit ZbRtlSc(sc_core::sc_module_name name);
  ~ZbRtlSc() override;

  const Framebuffer& framebuffer() const { return fb_; }
  // Clock cycles spent in passes: tile loads, state writes, streaming, drains, tile stores; and
  // the simulated time they took, from the pass's first falling edge to its PassStats.
  uint64_t busy_cycles() const { return busy_cycles_; }
  sc_core::sc_time busy_time() const { return busy_time_; }
  uint64_t tile_io_cycles() const { return io_cycles_; }

 private:
  void run();
  PassStats run_pass();
  void run_tile(size_t tile, int x0, int y0, uint32_t b, uint32_t e, PassStats& stats);
  void cycle() {
    wait(clk_i.negedge_event());
    ++cycles_;
  }

  template <class T>
  using Sig = sc_core::sc_signal<T>;
  // A port of W bits as Verilator --sc declares it.
  template <int W>
  using Bits = std::conditional_t<W <= 32, uint32_t,
                                  std::conditional_t<W <= 64, uint64_t, sc_dt::sc_bv<W>>>;
  static constexpr int kCovW = coverage_bits(kRtlCoverageSamples);
  static constexpr int kAccumW = accum_word_bits(kRtlWboit);
  static constexpr int kLayersW = kRtlLayers > 0 ? kRtlLayers * (kRtlDepthBits + 32) : 1;
  Sig<bool> rst_n_, state_we_, frag_valid_, frag_ready_, stall_, tile_req_, tile_we_, tile_clear_,
      tile_copy_, tile_resolve_, tile_wboit_, tile_mlab_,
      busy_, cnt_clear_;
  Sig<uint32_t> state_, state_layers_, tile_x0_, tile_y0_, frag_x_, frag_y_, frag_z_, frag_rgba_, frag_cov_,
      tile_planes_, tile_addr_, cnt_frag_in_, cnt_frag_passed_, cnt_frag_killed_,
      cnt_depth_reads_, cnt_depth_writes_, cnt_color_reads_, cnt_color_writes_,
      cnt_stall_cycles_, cnt_cycles_, cnt_tile_loads_, cnt_tile_stores_;
  Sig<Bits<kRtlBeat * 32>> tile_wcolor_, tile_rcolor_;
  Sig<Bits<kRtlBeat * kRtlDepthBits>> tile_wdepth_, tile_rdepth_, tile_wpeel_, tile_rpeel_;
  Sig<Bits<kRtlBeat * kCovW>> tile_wcov_, tile_rcov_;
  Sig<Bits<kRtlBeat * kAccumW>> tile_wacc_, tile_racc_;
  // The retire port: bound because SystemC needs every port bound; the lock-step monitor is the
  // C++ testbench's (tb/).
  Sig<bool> mon_x4_valid_, mon_dwe_, mon_vwe_, mon_x11_valid_, mon_cwe_, mon_awe_;
  Sig<uint32_t> mon_x4_addr_, mon_wdepth_, mon_wcov_, mon_x11_addr_, mon_wcolor_;
  Sig<Bits<kAccumW>> mon_wacc_;
  Sig<bool> mon_lwe_;
  Sig<Bits<kLayersW>> mon_wlayers_;
  std::unique_ptr<Vzb_rop_sc> rtl_;

  Framebuffer fb_;
  std::vector<Rgba8> resolved_;  // a layers pass's colour as its stores resolved it
  TileStates tiles_;
  RopState state_value_;
  std::vector<Fragment> frags_;
  TileBins bins_;
  uint64_t cycles_ = 0;  // falling edges since the start
  uint64_t busy_cycles_ = 0, io_cycles_ = 0;
  sc_core::sc_time busy_time_;
};

}  // namespace zb::sc
