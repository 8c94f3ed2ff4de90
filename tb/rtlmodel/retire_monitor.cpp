#include "retire_monitor.h"

#include "rtl_params.h"

namespace zb {

const char* to_string(RetireStage s) { return s == RetireStage::kX4 ? "X4" : "X11"; }

void RetireMonitor::begin_tile(int x0, int y0, const uint32_t* addr, const uint32_t* index,
                               size_t n) {
  constexpr size_t words = size_t(kRtlTileW) * kRtlTileH;
  go_ = true;
  x0_ = x0;
  y0_ = y0;
  addr_ = addr;
  index_ = index;
  n_ = n;
  next_.assign(n, kNone);
  x4_cycle_.assign(n, kNoCycle);
  for (auto& h : head_) h.assign(words, kNone);
  tail_.assign(words, kNone);
  for (size_t k = 0; k < n; ++k) {
    const uint32_t a = addr[k];
    if (tail_[a] == kNone) {
      head_[0][a] = head_[1][a] = uint32_t(k);
    } else {
      next_[tail_[a]] = uint32_t(k);
    }
    tail_[a] = uint32_t(k);
  }
}

Retire RetireMonitor::at(RetireStage stage, uint32_t addr, uint64_t cycle) const {
  Retire r;
  r.stage = stage;
  r.x = x0_ + int(addr % kRtlTileW);
  r.y = y0_ + int(addr / kRtlTileW);
  r.tile_x0 = x0_;
  r.tile_y0 = y0_;
  r.tile_cycle = cycle;
  return r;
}

bool RetireMonitor::take(RetireStage stage, uint32_t addr, uint64_t cycle, size_t accepted,
                         const PixelWrites& w) {
  Retire r = at(stage, addr, cycle);
  r.writes = w;
  uint32_t& head = head_[stage == RetireStage::kX11][addr];
  if (head == kNone || head >= accepted) {
    r.kind = Retire::Kind::kExtra;
  } else {
    r.fragment = index_[head];
    if (stage == RetireStage::kX4) x4_cycle_[head] = cycle;
    head = next_[head];
  }
  return sink_.retire(r);
}

// A stage's writes with no fragment in it (valid low) are extra: `accepted` 0 finds none.
bool RetireMonitor::observe(const RetirePort& p, uint64_t tile_cycle, size_t accepted) {
  if (!go_) return false;
  constexpr uint32_t mask = uint32_t(kRtlTileW) * kRtlTileH - 1;
  if (p.x4_valid || p.dwe || p.vwe) {
    PixelWrites w;
    w.depth = p.dwe;
    w.z = p.dwe ? p.wdepth : 0;
    w.coverage = p.vwe;
    w.cov = p.vwe ? uint8_t(p.wcov) : 0;
    go_ = take(RetireStage::kX4, p.x4_addr & mask, tile_cycle, p.x4_valid ? accepted : 0, w) &&
          go_;
  }
  if (p.x11_valid || p.cwe || p.awe || p.lwe) {
    PixelWrites w;
    w.color = p.cwe;
    w.rgba = p.cwe ? unpack_rgba(p.wcolor) : Rgba8{};
    w.accum = p.awe;
    if (p.awe) {
      w.acc = p.wacc.acc;
      w.reveal = p.wacc.reveal;
    }
    w.layers = p.lwe;
    if (p.lwe) w.lay = p.wlayers;
    go_ = take(RetireStage::kX11, p.x11_addr & mask, tile_cycle, p.x11_valid ? accepted : 0, w) &&
          go_;
  }
  return go_;
}

bool RetireMonitor::end_tile(uint64_t tile_cycle) {
  for (int s = 0; s < 2 && go_; ++s) {
    // In stream order: the first missing fragment is reported first.
    for (size_t k = 0; k < n_ && go_; ++k) {
      const uint32_t a = addr_[k];
      if (head_[s][a] != k) continue;
      Retire r = at(s ? RetireStage::kX11 : RetireStage::kX4, a, tile_cycle);
      r.kind = Retire::Kind::kMissing;
      r.fragment = index_[k];
      go_ = sink_.retire(r);
    }
  }
  return go_;
}

}  // namespace zb
