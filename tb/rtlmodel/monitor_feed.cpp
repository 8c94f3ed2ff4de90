#include "monitor_feed.h"

namespace zb {

MonitorFeed::MonitorFeed(RetireSink* sink, WaveProbe* probe) {
  if (probe) {
    probe_sink_ = std::make_unique<ProbeSink>(sink, *probe);
    monitor_ = std::make_unique<RetireMonitor>(*probe_sink_);
  } else if (sink) {
    monitor_ = std::make_unique<RetireMonitor>(*sink);
  }
}

void MonitorFeed::begin_tile(int x0, int y0, const Streamed* f, size_t n) {
  if (!monitor_) return;
  addr_.resize(n);
  index_.resize(n);
  for (size_t j = 0; j < n; ++j) {
    addr_[j] = uint32_t(f[j].y - y0) * kRtlTileW + uint32_t(f[j].x - x0);
    index_[j] = f[j].index;
  }
  monitor_->begin_tile(x0, y0, addr_.data(), index_.data(), n);
}

}  // namespace zb
