#include "zb_rtl_sc.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "Vzb_rop_sc.h"
#include "Vzb_rop_sc_zb_rop.h"
#include "rtl_params.h"

namespace zb::sc {

static_assert(Vzb_rop_sc_zb_rop::TILE_W == kRtlTileW, "zbsc_vlt's TILE_W disagrees with rtl_params.h");
static_assert(Vzb_rop_sc_zb_rop::DEPTH_BITS == kRtlDepthBits, "DEPTH_BITS disagrees");
static_assert(Vzb_rop_sc_zb_rop::COV_SAMPLES == kRtlCoverageSamples, "COV_SAMPLES disagrees");
static_assert(Vzb_rop_sc_zb_rop::BEAT == kRtlBeat, "BEAT disagrees");
static_assert(Vzb_rop_sc_zb_rop::ACC_BITS == kRtlWboit.acc_bits, "ACC_BITS disagrees");
static_assert(Vzb_rop_sc_zb_rop::REV_BITS == kRtlWboit.rev_bits, "REV_BITS disagrees");
static_assert(Vzb_rop_sc_zb_rop::WEIGHT_BITS == kRtlWboit.weight_bits, "WEIGHT_BITS disagrees");

namespace {

constexpr uint64_t kDrainLimit = 1000;  // as tb/rtlmodel/driver_checks.h: cycles busy_o may stay high

// Bits [lo, lo + width) of a port's value, width at most 32: an integer up to 64 bits, sc_bv
// beyond.
template <class T>
void put_bits(T& v, int lo, int width, uint32_t x) {
  if constexpr (std::is_integral_v<T>) {
    const uint64_t m = ((uint64_t{1} << width) - 1) << lo;
    v = T((uint64_t(v) & ~m) | (uint64_t{x} << lo & m));
  } else {
    v.range(lo + width - 1, lo) = x;
  }
}
template <class T>
uint32_t get_bits(const T& v, int lo, int width) {
  if constexpr (std::is_integral_v<T>) {
    return uint32_t(uint64_t(v) >> lo & ((uint64_t{1} << width) - 1));
  } else {
    return v.range(lo + width - 1, lo).to_uint();
  }
}
// Lane `lane` of `width` bits in a tile port's value.
template <class T>
void put_lane(T& v, int lane, int width, uint32_t x) {
  put_bits(v, lane * width, width, x);
}
template <class T>
uint32_t get_lane(const T& v, int lane, int width) {
  return get_bits(v, lane * width, width);
}
// The accumulation word {r, acc_A, acc_B, acc_G, acc_R} at word `index`.
constexpr int kAccBits = kRtlWboit.acc_bits, kRevBits = kRtlWboit.rev_bits;
constexpr int kAccumW = accum_word_bits(kRtlWboit);
template <class T>
void put_accum(T& v, int index, const AccumWord& w) {
  for (int c = 0; c < 4; ++c)
    put_bits(v, index * kAccumW + c * kAccBits, kAccBits, w.acc[size_t(c)]);
  put_bits(v, index * kAccumW + 4 * kAccBits, kRevBits, w.reveal);
}
template <class T>
AccumWord get_accum(const T& v, int index) {
  AccumWord w;
  for (int c = 0; c < 4; ++c)
    w.acc[size_t(c)] = get_bits(v, index * kAccumW + c * kAccBits, kAccBits);
  w.reveal = get_bits(v, index * kAccumW + 4 * kAccBits, kRevBits);
  return w;
}

// The model's plusargs, set before it exists: none. The bug build reads them ($test$plusargs) and
// so runs its blend defect.
std::unique_ptr<Vzb_rop_sc> make_model() {
  Verilated::commandArgs(0, static_cast<const char**>(nullptr));
  return std::make_unique<Vzb_rop_sc>("zb_rop");
}

}  // namespace

ZbRtlSc::ZbRtlSc(sc_core::sc_module_name name)
    : sc_core::sc_module(name), rtl_(make_model()) {
  Vzb_rop_sc& r = *rtl_;
  r.clk_i(clk_i);
  r.rst_ni(rst_n_);
  r.state_we_i(state_we_);
  r.state_i(state_);
  r.state_layers_i(state_layers_);
  r.tile_x0_i(tile_x0_);
  r.tile_y0_i(tile_y0_);
  r.frag_valid_i(frag_valid_);
  r.frag_ready_o(frag_ready_);
  r.frag_x_i(frag_x_);
  r.frag_y_i(frag_y_);
  r.frag_z_i(frag_z_);
  r.frag_rgba_i(frag_rgba_);
  r.frag_cov_i(frag_cov_);
  r.stall_i(stall_);
  r.tile_req_i(tile_req_);
  r.tile_we_i(tile_we_);
  r.tile_clear_i(tile_clear_);
  r.tile_copy_i(tile_copy_);        // the tile operations: the pass schedule's driver uses none
  r.tile_resolve_i(tile_resolve_);
  r.tile_wboit_i(tile_wboit_);
  r.tile_mlab_i(tile_mlab_);
  r.tile_planes_i(tile_planes_);
  r.tile_addr_i(tile_addr_);
  r.tile_wcolor_i(tile_wcolor_);
  r.tile_wdepth_i(tile_wdepth_);
  r.tile_wcov_i(tile_wcov_);
  r.tile_wpeel_i(tile_wpeel_);
  r.tile_wacc_i(tile_wacc_);
  r.tile_rcolor_o(tile_rcolor_);
  r.tile_rdepth_o(tile_rdepth_);
  r.tile_rcov_o(tile_rcov_);
  r.tile_rpeel_o(tile_rpeel_);
  r.tile_racc_o(tile_racc_);
  r.busy_o(busy_);
  r.cnt_clear_i(cnt_clear_);
  r.cnt_frag_in_o(cnt_frag_in_);
  r.cnt_frag_passed_o(cnt_frag_passed_);
  r.cnt_frag_killed_o(cnt_frag_killed_);
  r.cnt_depth_reads_o(cnt_depth_reads_);
  r.cnt_depth_writes_o(cnt_depth_writes_);
  r.cnt_color_reads_o(cnt_color_reads_);
  r.cnt_color_writes_o(cnt_color_writes_);
  r.cnt_stall_cycles_o(cnt_stall_cycles_);
  r.cnt_cycles_o(cnt_cycles_);
  r.cnt_tile_loads_o(cnt_tile_loads_);
  r.cnt_tile_stores_o(cnt_tile_stores_);
  r.mon_x4_valid_o(mon_x4_valid_);
  r.mon_x4_addr_o(mon_x4_addr_);
  r.mon_dwe_o(mon_dwe_);
  r.mon_wdepth_o(mon_wdepth_);
  r.mon_vwe_o(mon_vwe_);
  r.mon_wcov_o(mon_wcov_);
  r.mon_x11_valid_o(mon_x11_valid_);
  r.mon_x11_addr_o(mon_x11_addr_);
  r.mon_cwe_o(mon_cwe_);
  r.mon_wcolor_o(mon_wcolor_);
  r.mon_awe_o(mon_awe_);
  r.mon_wacc_o(mon_wacc_);
  r.mon_lwe_o(mon_lwe_);
  r.mon_wlayers_o(mon_wlayers_);
  SC_HAS_PROCESS(ZbRtlSc);
  SC_THREAD(run);
}

ZbRtlSc::~ZbRtlSc() = default;

// Inputs change at the falling edge and zb_rop samples them at the rising one; outputs read at
// a falling edge are those of the last rising edge.
void ZbRtlSc::run() {
  rst_n_.write(false);
  for (int i = 0; i < 3; ++i) cycle();
  rst_n_.write(true);
  cycle();
  // The tile memory's words are unknown after reset: one read of every beat puts them at the
  // planes' epoch, as a fast clear needs (zb_plane).
  tile_req_.write(true);
  for (int a = 0; a < kRtlTileW * kRtlTileH / kRtlBeat; ++a) {
    tile_addr_.write(uint32_t(a));
    cycle();
  }
  tile_req_.write(false);
  cycle();
  for (;;) {
    const PassCommand c = cmd_i.read();
    switch (c.kind) {
      case PassCommand::Kind::kBeginFrame:
        if (c.coverage_samples != kRtlCoverageSamples || c.depth_bits != kRtlDepthBits ||
            c.wboit != kRtlWboit)
          throw std::invalid_argument("zb_rtl_sc: the Verilated zb_rop has " +
                                      std::to_string(kRtlDepthBits) + " depth bits, " +
                                      std::to_string(kRtlCoverageSamples) + " coverage samples "
                                      "and the build's ACC_BITS, REV_BITS and WEIGHT_BITS");
        fb_ = Framebuffer(c.width, c.height, c.depth_bits, c.clear, c.coverage_samples, c.wboit);
        tiles_ = TileStates(c.width, c.height, kRtlTileW, c.depth_bits, c.clear, c.wboit);
        break;
      case PassCommand::Kind::kBeginPass:
        state_value_ = c.state;
        frags_.resize(c.fragments);
        for (Fragment& f : frags_) f = frag_i.read();
        break;
      case PassCommand::Kind::kEndPass: stats_o.write(run_pass()); break;
      case PassCommand::Kind::kFrameOp:
        if (c.op.kind == FrameOpKind::kResolveLayers && !resolved_.empty()) {
          fb_.color = resolved_;  // the stores' resolve, kept until now (run_tile)
          resolved_.clear();
        }
        apply_frame_op(fb_, c.op);
        tiles_.frame_op(c.op);
        break;
    }
  }
}

PassStats ZbRtlSc::run_pass() {
  // The command may arrive at a rising edge, in a delta before or after zb_rop samples it:
  // inputs change only at falling edges, so every write lands at a known edge.
  wait(clk_i.negedge_event());
  ++cycles_;
  const uint64_t start = cycles_;
  const sc_core::sc_time start_time = sc_core::sc_time_stamp();
  bin_by_tile(frags_.data(), frags_.size(), fb_.width, fb_.height, kRtlTileW, kRtlTileH, bins_);
  prepare_stores(fb_, state_value_);
  if (planes_written(state_value_) & kPlaneLayers) resolved_ = fb_.color;
  PassStats stats;
  for (size_t t = 0; t + 1 < bins_.first.size(); ++t)
    if (bins_.first[t] != bins_.first[t + 1])
      run_tile(t, int(t % size_t(bins_.columns)) * kRtlTileW, int(t / size_t(bins_.columns)) * kRtlTileH,
               bins_.first[t], bins_.first[t + 1], stats);
  busy_cycles_ += cycles_ - start;
  busy_time_ += sc_core::sc_time_stamp() - start_time;
  return stats;
}

// One tile as RtlRop::run_tile (no back-pressure): the setup cycle (state, counter clear, fast
// clear), the load beats, a fragment offered every clock (held while frag_ready_o is low), the
// drain while busy_o, the counters, the store beats.
void ZbRtlSc::run_tile(size_t tile, int x0, int y0, uint32_t b, uint32_t e, PassStats& stats) {
  const TileSweep sweep(fb_.width, fb_.height, x0, y0);
  const TileIo io = tiles_.plan(tile, state_value_);
  const uint64_t load_begin = cycles_;
  auto put_beat = [this](const BeatWords& w) {
    Bits<kRtlBeat * 32> color{};
    Bits<kRtlBeat * kRtlDepthBits> depth{}, peel{};
    Bits<kRtlBeat * kCovW> cov{};
    Bits<kRtlBeat * kAccumW> acc{};
    for (int l = 0; l < kRtlBeat; ++l) {
      put_lane(color, l, 32, w[0][size_t(l)]);
      put_lane(depth, l, kRtlDepthBits, w[1][size_t(l)]);
      put_lane(cov, l, kCovW, w[2][size_t(l)]);
      put_lane(peel, l, kRtlDepthBits, w[3][size_t(l)]);
      put_accum(acc, l, w.accum[size_t(l)]);
    }
    tile_wcolor_.write(color);
    tile_wdepth_.write(depth);
    tile_wcov_.write(cov);
    tile_wpeel_.write(peel);
    tile_wacc_.write(acc);
  };
  put_beat(clear_beat(io));
  tile_clear_.write(io.clear != 0);
  tile_planes_.write(port_planes(io.clear));
  tile_mlab_.write((io.clear & kPlaneLayers) != 0);
  tile_x0_.write(uint32_t(x0));
  tile_y0_.write(uint32_t(y0));
  state_.write(port_state(pack_state(state_value_)));
  state_layers_.write(port_state_layers(pack_state(state_value_)));
  state_we_.write(true);
  cnt_clear_.write(true);
  cycle();
  state_we_.write(false);
  cnt_clear_.write(false);
  tile_clear_.write(false);
  tile_mlab_.write(false);
  if (io.load) {
    tile_req_.write(true);
    tile_we_.write(true);
    tile_planes_.write(port_planes(io.load));
    for (int k = 0; k < sweep.beats(); ++k) {
      tile_addr_.write(uint32_t(k));
      put_beat(sweep.load(fb_, k));
      cycle();
    }
    tile_req_.write(false);
    tile_we_.write(false);
  }
  tile_planes_.write(0);
  // frag_ready_o falls with tile_clear_i and tile_req_i: let their change reach it (the signal
  // update, then the model's evaluation) before the first offer reads it.
  wait(sc_core::SC_ZERO_TIME);
  wait(sc_core::SC_ZERO_TIME);

  const uint64_t stream_begin = cycles_;
  uint64_t refused = 0;
  for (uint32_t k = b; k < e;) {
    const Fragment& f = frags_[bins_.order[k]];
    frag_valid_.write(true);
    frag_x_.write(f.x);
    frag_y_.write(f.y);
    frag_z_.write(f.z);
    frag_rgba_.write(pack_rgba(f.color));
    frag_cov_.write(f.coverage);
    // frag_ready_o depends on flops, stall_i and the tile port only (all low now): its value
    // since the last rising edge is the one the next edge sees.
    const bool accepted = frag_ready_.read();
    cycle();
    if (accepted) {
      ++k;
      refused = 0;
    } else if (++refused > kDrainLimit) {
      throw std::runtime_error("zb_rtl_sc: frag_ready_o low for " + std::to_string(kDrainLimit) +
                               " cycles (tile " + std::to_string(x0) + "," + std::to_string(y0) +
                               ")");
    }
  }
  frag_valid_.write(false);
  const uint64_t last = cycles_;
  while (busy_.read()) {
    if (cycles_ - last > kDrainLimit)
      throw std::runtime_error("zb_rtl_sc: busy_o still high " + std::to_string(kDrainLimit) +
                               " cycles after the last fragment");
    cycle();
  }
  const uint64_t stream_end = cycles_;
  stats.fragments_in += cnt_frag_in_.read();
  stats.fragments_passed += cnt_frag_passed_.read();
  stats.depth_reads += cnt_depth_reads_.read();
  stats.depth_writes += cnt_depth_writes_.read();
  stats.color_reads += cnt_color_reads_.read();
  stats.color_writes += cnt_color_writes_.read();
  stats.cycles += stream_end - stream_begin;
  if (uint64_t{cnt_frag_killed_.read()} != uint64_t{cnt_frag_in_.read()} - cnt_frag_passed_.read())
    throw std::runtime_error("zb_rtl_sc: cnt_frag_killed_o != cnt_frag_in_o - cnt_frag_passed_o");

  // The layers never leave the tile: a layers pass's store reads the colour resolved with them
  // (tile_mlab_i), kept apart until the resolve operation so that the frame after the pass is
  // the golden model's (colour as it was, the layers pending).
  const bool layers = (io.store & kPlaneLayers) != 0;
  if (io.store) {
    tile_req_.write(true);
    tile_mlab_.write(layers);
    for (int k = 0; k < sweep.beats(); ++k) {
      tile_addr_.write(uint32_t(k));
      cycle();
      BeatWords w{};
      for (int l = 0; l < kRtlBeat; ++l) {
        w[0][size_t(l)] = get_lane(tile_rcolor_.read(), l, 32);
        w[1][size_t(l)] = get_lane(tile_rdepth_.read(), l, kRtlDepthBits);
        w[2][size_t(l)] = get_lane(tile_rcov_.read(), l, kCovW);
        w.accum[size_t(l)] = get_accum(tile_racc_.read(), l);
      }
      if (layers) {
        for (int l = 0; l < kRtlBeat; ++l)
          if (const int64_t i = sweep.pixel(fb_, k, l); i >= 0)
            resolved_[size_t(i)] = unpack_rgba(w[0][size_t(l)]);
      }
      sweep.store(w, port_planes(io.store), fb_, k);
    }
    tile_req_.write(false);
    tile_mlab_.write(false);
  }
  tiles_.stored(tile, io.store);
  io_cycles_ += (stream_begin - load_begin) + (cycles_ - stream_end);
}

}  // namespace zb::sc
