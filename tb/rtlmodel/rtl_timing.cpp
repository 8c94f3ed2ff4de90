#include "rtl_timing.h"

#include <algorithm>
#include <stdexcept>

namespace zb {

namespace {
constexpr uint64_t kPickToIssue = 2;  // picked in cycle c: K in c + 1, M (issue) in c + 2
}  // namespace

IssueSchedule::IssueSchedule(unsigned window, size_t keys)
    : window_(window < 2 ? 2 : window), stamp_(keys, 0), last_(keys, 0), pending_(keys, 0) {
  entries_.reserve(window_);
}

template <class Ready, class Issued>
uint64_t IssueSchedule::schedule(const uint32_t* pixel, size_t n, Ready&& ready,
                                 Issued&& issued) {
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
  size_t next = 0;      // the fragment in the input register I
  uint64_t c = 1, last_issue = 0;
  while (next < n || !entries_.empty()) {
    // The pick of cycle c: the oldest entry whose pixel is free. It issues in c + 2 (K, M).
    size_t pick = entries_.size();
    for (size_t e = 0; e < entries_.size(); ++e)
      if (entries_[e].earliest <= c) {
        pick = e;
        break;
      }
    const bool room = next < n && entries_.size() < window_;
    const uint64_t from = room ? ready(next) : kNever;
    const bool take = room && c >= from;
    const bool picked_one = pick < entries_.size();
    if (picked_one) {
      const Entry picked = entries_[pick];
      entries_.erase(entries_.begin() + std::ptrdiff_t(pick));
      last_issue = c + kPickToIssue;
      issued(picked.index, last_issue);
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
      // oldest entry of each pixel has a finite `earliest`) or the next fragment arrives.
      uint64_t wake = from;
      for (const Entry& e : entries_) wake = std::min(wake, e.earliest);
      if (wake == kNever) throw std::logic_error("IssueSchedule: a fragment waits for nothing");
      c = std::max(c + 1, wake);
      continue;
    }
    ++c;
  }
  return last_issue;
}

uint64_t IssueSchedule::run(const uint32_t* pixel, size_t n, uint64_t* issue,
                            const uint64_t* accept) {
  if (n == 0) return 0;
  // Fragment k is in I from the cycle after its accept (from cycle 1 without back-pressure).
  auto ready = [accept](size_t k) { return accept ? accept[k] + 1 : 0; };
  auto issued = [issue](size_t k, uint64_t c) {
    if (issue) issue[k] = c;
  };
  return schedule(pixel, n, ready, issued) + kRtlDrain;
}

OverlapCycles IssueSchedule::run_two_buffers(const std::vector<TileStream>& tiles) {
  OverlapCycles out;
  if (tiles.empty()) return out;
  const size_t count = tiles.size();
  std::vector<uint32_t> keys;
  std::vector<uint32_t> tile_of;     // per fragment of the pass
  std::vector<size_t> first(count + 1, 0), left(count);
  for (size_t t = 0; t < count; ++t) {
    if (tiles[t].n == 0) throw std::invalid_argument("run_two_buffers: a tile with no fragment");
    keys.insert(keys.end(), tiles[t].pixel, tiles[t].pixel + tiles[t].n);
    tile_of.insert(tile_of.end(), tiles[t].n, uint32_t(t));
    first[t + 1] = first[t] + tiles[t].n;
    left[t] = tiles[t].n;
  }
  std::vector<uint64_t> drain(count, kNever), load_end(count, kNever), store_end(count, kNever),
      last(count, 0);
  // The port's operations in order: load 0, then load k and store k - 1 for each k >= 1, then
  // the last store. Each starts when the port is free and its inputs are known: a store at its
  // tile's drain, a load of tile k >= 2 at the end of the store of tile k - 2, its buffer's.
  struct Op {
    bool store;
    size_t tile;
  };
  std::vector<Op> ops{{false, 0}};
  for (size_t k = 1; k < count; ++k) {
    ops.push_back({false, k});
    ops.push_back({true, k - 1});
  }
  ops.push_back({true, count - 1});
  uint64_t port = 0;  // the port is free from this cycle
  size_t op = 0;      // the next operation
  auto advance = [&] {
    for (; op < ops.size(); ++op) {
      const size_t t = ops[op].tile;
      if (ops[op].store) {
        if (drain[t] == kNever) return;
        port = std::max(port, drain[t]) + tiles[t].store_cycles;
        store_end[t] = port;
      } else {
        const uint64_t after = t >= 2 ? store_end[t - 2] : 0;
        if (after == kNever) return;
        port = std::max(port, after) + tiles[t].load_cycles;
        load_end[t] = port;
      }
    }
  };
  advance();
  // Tile t's fragments are offered from the cycle its load ends and taken from the next; the
  // rest follow in order.
  auto ready = [&](size_t k) -> uint64_t {
    const size_t t = tile_of[k];
    if (k != first[t]) return 0;
    return load_end[t] == kNever ? kNever : load_end[t] + 1;
  };
  auto issued = [&](size_t k, uint64_t c) {
    const size_t t = tile_of[k];
    last[t] = std::max(last[t], c);
    if (--left[t] == 0) {
      drain[t] = last[t] + kRtlDrain;
      advance();
    }
  };
  schedule(keys.data(), keys.size(), ready, issued);  // the last tile's drain ran every op
  out.stream = drain[count - 1] - load_end[0];
  out.total = port;
  return out;
}

uint64_t two_buffer_group(const std::vector<ResidentRun>& runs) {
  const size_t n = runs.size();
  std::vector<uint64_t> load_end(n), store_end(n);
  uint64_t port = 0, pipe = 0;  // free from these cycles
  auto load = [&](size_t k) {
    port = std::max(port, k >= 2 ? store_end[k - 2] : 0) + runs[k].load;
    load_end[k] = port;
  };
  auto work_and_store = [&](size_t k) {
    pipe = std::max(pipe, load_end[k]) + runs[k].work;
    port = std::max(port, pipe) + runs[k].store;
    store_end[k] = port;
  };
  if (n == 0) return 0;
  load(0);
  for (size_t k = 1; k < n; ++k) {
    load(k);  // runs k - 1's work meanwhile; its store follows on the port
    work_and_store(k - 1);
  }
  work_and_store(n - 1);
  return port;
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
