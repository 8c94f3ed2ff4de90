#include "rtl_timing.h"

#include <algorithm>

namespace zb {

namespace {
constexpr uint64_t kPickToIssue = 2;  // picked in cycle c: K in c + 1, M (issue) in c + 2
}  // namespace

IssueSchedule::IssueSchedule(unsigned window, size_t keys)
    : window_(window < 2 ? 2 : window), stamp_(keys, 0), last_(keys, 0), pending_(keys, 0) {
  entries_.reserve(window_);
}

uint64_t IssueSchedule::run(const uint32_t* pixel, size_t n, uint64_t* issue,
                            const uint64_t* accept) {
  if (n == 0) return 0;
  if (++run_ == 0) {  // the stamp wrapped: forget every pixel
    std::fill(stamp_.begin(), stamp_.end(), 0);
    run_ = 1;
  }
  const uint32_t top = *std::max_element(pixel, pixel + n);
  if (top >= stamp_.size()) {
    stamp_.resize(size_t(top) + 1, 0);
    last_.resize(stamp_.size(), 0);
    pending_.resize(stamp_.size(), 0);
  }
  entries_.clear();
  size_t next = 0;      // the fragment in the input register I, from cycle 1
  uint64_t c = 1, last_issue = 0;
  while (next < n || !entries_.empty()) {
    // The pick of cycle c: the oldest entry whose pixel is free. It issues in c + 2 (K, M).
    size_t pick = entries_.size();
    for (size_t e = 0; e < entries_.size(); ++e)
      if (entries_[e].earliest <= c) {
        pick = e;
        break;
      }
    // The next fragment is in I (or moving there from S) from the cycle after its accept.
    const bool room = next < n && entries_.size() < window_;
    const uint64_t ready = room && accept ? accept[next] + 1 : 0;
    const bool take = room && c >= ready;
    const bool picked_one = pick < entries_.size();
    if (picked_one) {
      const Entry picked = entries_[pick];
      entries_.erase(entries_.begin() + std::ptrdiff_t(pick));
      last_issue = c + kPickToIssue;
      if (issue) issue[picked.index] = last_issue;
      last_[picked.pixel] = last_issue;
      if (--pending_[picked.pixel] > 0)
        for (Entry& e : entries_)
          if (e.pixel == picked.pixel) {  // the next one to that pixel, oldest first
            e.earliest = last_issue + kRtlIssueSpan - kPickToIssue;
            break;
          }
    }
    if (take) {
      const uint32_t p = pixel[next];
      if (stamp_[p] != run_) {
        stamp_[p] = run_;
        pending_[p] = 0;
        last_[p] = 0;
      }
      uint64_t earliest = c + 1;  // in the window from the next cycle
      if (pending_[p] > 0)
        earliest = kNever;
      else if (last_[p] != 0)
        earliest = std::max(earliest, last_[p] + kRtlIssueSpan - kPickToIssue);
      ++pending_[p];
      entries_.push_back(Entry{p, uint32_t(next), earliest});
      ++next;
    } else if (!picked_one) {
      // Nothing picked and nothing taken: nothing changes until the first entry frees (the
      // oldest entry of each pixel has a finite `earliest`).
      uint64_t wake = room ? ready : kNever;
      for (const Entry& e : entries_) wake = std::min(wake, e.earliest);
      c = std::max(c + 1, wake);
      continue;
    }
    ++c;
  }
  return last_issue + kRtlDrain;
}

uint64_t IssueSchedule::run_tile(const TileBins& bins, size_t tile, const Fragment* f, int width,
                                 uint64_t* issue) {
  tile_pixels_.clear();
  for (uint32_t k = bins.first[tile]; k < bins.first[tile + 1]; ++k) {
    const Fragment& g = f[bins.order[k]];
    tile_pixels_.push_back(uint32_t(g.y) * uint32_t(width) + g.x);
  }
  return run(tile_pixels_.data(), tile_pixels_.size(), issue);
}

}  // namespace zb
