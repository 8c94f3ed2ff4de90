// Where the lock-step monitor (retire_monitor.h) gets its events from one model: the retire
// port after every edge of a tile's stream, drain and store, and each stored beat. With an FST
// the events pass through the waveform's probe (waves.h) on their way to the run's sink.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "port_lanes.h"
#include "retire_monitor.h"
#include "tile_bins.h"
#include "waves.h"

namespace zb {

class MonitorFeed {
 public:
  // `sink`: the run's, or null; `probe`: the traced model's probe inputs, or null. With neither
  // there is no monitor and every call below passes.
  MonitorFeed(RetireSink* sink, WaveProbe* probe);

  bool on() const { return monitor_ != nullptr; }
  void begin_tile(int x0, int y0, const Streamed* f, size_t n);
  // After a rising edge: `tile_cycle` since the tile's setup cycle, `accepted` fragments of its
  // stream so far. False once the sink asked to stop.
  template <class Model>
  bool observe(const Model& t, uint64_t tile_cycle, size_t accepted) {
    return !monitor_ || monitor_->observe(retire_port(t), tile_cycle, accepted);
  }
  bool end_tile(uint64_t tile_cycle) { return !monitor_ || monitor_->end_tile(tile_cycle); }
  bool store(const StoreBeat& b) { return !monitor_ || monitor_->store(b); }
  // Each fragment's X4 cycle by stream position; only when on().
  const std::vector<uint64_t>& x4_cycles() const { return monitor_->x4_cycles(); }

 private:
  template <class Model>
  static RetirePort retire_port(const Model& t) {
    RetirePort p;
    p.x4_valid = t.mon_x4_valid_o;
    p.x4_addr = t.mon_x4_addr_o;
    p.dwe = t.mon_dwe_o;
    p.wdepth = t.mon_wdepth_o;
    p.vwe = t.mon_vwe_o;
    p.wcov = t.mon_wcov_o;
    p.x11_valid = t.mon_x11_valid_o;
    p.x11_addr = t.mon_x11_addr_o;
    p.cwe = t.mon_cwe_o;
    p.wcolor = t.mon_wcolor_o;
    p.awe = t.mon_awe_o;
    lanes::Reader wacc(t.mon_wacc_o);
    p.wacc = lanes::get_accum(wacc);
    p.lwe = t.mon_lwe_o;
    if (p.lwe) {
      lanes::Reader wlayers(t.mon_wlayers_o);
      p.wlayers = lanes::get_layers(wlayers);
    }
    return p;
  }

  std::unique_ptr<ProbeSink> probe_sink_;  // with a probe: the transactions shown in the FST
  std::unique_ptr<RetireMonitor> monitor_;
  std::vector<uint32_t> addr_, index_;     // the monitor's view of the tile's stream
};

}  // namespace zb
