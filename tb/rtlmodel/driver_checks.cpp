#include "driver_checks.h"

namespace zb {

void fail_ready(int x0, int y0, uint64_t cycle, const char* why) {
  fail("rtl: tile ({},{}) frag_ready_o high at cycle {} with {} (docs/rtl.md \"Port timing\": "
       "the port must refuse fragments then)",
       x0, y0, cycle, why);
}

void fail_not_ready(int x0, int y0) {
  fail("rtl: frag_ready_o low for {} cycles (tile {},{})", kDrainLimit, x0, y0);
}

void fail_busy(int x0, int y0) {
  fail("rtl: busy_o still high {} cycles after the last fragment (tile {},{})", kDrainLimit, x0,
       y0);
}

void ScheduleCheck::check(const TileRun& run, const Streamed* f, size_t n,
                          const uint64_t* accepted, const std::vector<uint64_t>* x4) {
  pixels_.resize(n);
  for (size_t j = 0; j < n; ++j)
    pixels_[j] = uint32_t(f[j].y - run.y0) * kRtlTileW + uint32_t(f[j].x - run.x0);
  issue_.resize(n);
  if (accepted) {
    accepts_.resize(n);
    for (size_t j = 0; j < n; ++j) accepts_[j] = accepted[f[j].index] - run.stream_begin;
  }
  const uint64_t want =
      schedule_.run(pixels_.data(), n, issue_.data(), accepted ? accepts_.data() : nullptr);
  if (x4) {
    const uint64_t from = run.stream_begin - run.load_begin;  // x4 counts from the setup cycle
    const std::vector<uint64_t>& c = *x4;
    for (size_t j = 0; j < n; ++j)
      if (c[j] - issue_[j] != c[0] - issue_[0])
        fail("rtl: fragment #{} (position {} of tile ({},{})'s stream) reached X4 {} cycles "
             "after its issue in the schedule (rtl_timing.h), the tile's first {} "
             "(--no-timing-check to go on)",
             f[j].index, j, run.x0, run.y0, int64_t(c[j] - issue_[j] - from),
             int64_t(c[0] - issue_[0] - from));
  }
  if (run.stream_end - run.stream_begin != want)
    fail("rtl: tile ({},{}) streamed {} fragments in {} cycles, the issue schedule "
         "(rtl_timing.h) says {} (--no-timing-check to go on)",
         run.x0, run.y0, n, run.stream_end - run.stream_begin, want);
}

void audit_stream(const TileRun& run, const StreamCounters& c, uint64_t clocked,
                  uint64_t refused_offers) {
  if (c.killed != c.in - c.passed)
    fail("rtl: cnt_frag_killed_o != cnt_frag_in_o - cnt_frag_passed_o");
  // The driver saw every cycle and every refused offer: the counters must say the same.
  if (c.cycles != clocked || c.stall_cycles != refused_offers)
    fail("rtl: tile ({},{}) counted {} cycles and {} stall cycles, the driver clocked {} and saw "
         "{} offers refused",
         run.x0, run.y0, c.cycles, c.stall_cycles, clocked, refused_offers);
}

void audit_beats(const TileRun& run, uint64_t want_loads, uint64_t want_stores) {
  if (run.load_beats != want_loads || run.store_beats != want_stores)
    fail("rtl: tile ({},{}) counted {} load and {} store beats, the driver moved {} and {}",
         run.x0, run.y0, run.load_beats, run.store_beats, want_loads, want_stores);
}

void check_reread(const TileRun& run, uint8_t planes, const BeatWords& now,
                  const BeatWords& first, size_t b, const char* what) {
  static const char* const kPlane[3] = {"colour", "depth", "coverage"};
  for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
    for (size_t p = 0; p < 3; ++p)
      if ((planes >> p & 1) && now[p][l] != first[p][l])
        fail("rtl: tile ({},{}) {}: {} {:#x} at beat {} lane {}, where its store read {:#x}",
             run.x0, run.y0, what, kPlane[p], now[p][l], b, l, first[p][l]);
    if ((planes & kPlaneAccum) && now.accum[l] != first.accum[l])
      fail("rtl: tile ({},{}) {}: accumulation {} at beat {} lane {}, where its store read {}",
           run.x0, run.y0, what, accum_text(now.accum[l]), b, l, accum_text(first.accum[l]));
  }
}

void audit_reload(const TileRun& run, uint64_t stores, uint64_t loads, uint64_t most,
                  uint64_t want_loads, size_t b) {
  if (stores != most || loads != want_loads)
    fail("rtl: tile ({},{}) counted {} store and {} load beats after its store was read again "
         "and loaded back; two tiles of beats saturate at {}: want {} and {} at load-back beat {}",
         run.x0, run.y0, stores, loads, most, most, want_loads, b);
}

}  // namespace zb
