#include "tile_driver.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "driver_checks.h"
#include "port_lanes.h"
#include "rop_model.h"

namespace zb {
namespace {

uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

struct XorShift {
  uint64_t s;
  explicit XorShift(uint64_t seed) : s(splitmix64(seed) | 1) {}
  uint64_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
  }
};

// A draw below it has probability p: stall_i, and (independently) a valid gap, in a cycle.
uint64_t backpressure_threshold(double p) {
  return p <= 0 ? 0 : p >= 1 ? std::numeric_limits<uint64_t>::max()
                             : uint64_t(p * 18446744073709551616.0);
}

// One run of run_tile. Inputs the port leaves unread in a cycle (state_i without state_we_i; the
// tile port's fields without tile_req_i or tile_clear_i; a fragment's without frag_valid_i) take
// random values from a generator of their own, so RTL that reads one where it must not
// mismatches.
class TileRunner {
 public:
  TileRunner(Sim& s, const TileJob& job)
      : s_(s), t_(*s.top), job_(job), sweep_(job.src->width, job.src->height, job.x0, job.y0),
        idle_((job.steps.empty() ? 0 : job.steps[0].seed) ^ 0x1d1e5eedull) {
    while ((1u << beat_aw_) < unsigned(sweep_.beats())) ++beat_aw_;
  }

  TileResult run() {
    TileRun& r = out_.run;
    r.x0 = job_.x0;
    r.y0 = job_.y0;
    r.load_begin = s_.cycle;
    for (size_t i = 0; i < job_.steps.size(); ++i) step(i);
    r.io.store = job_.store;
    const uint64_t beats = uint64_t(sweep_.beats());
    uint64_t reads = job_.store ? beats : 0, loads = 0;
    if (!job_.steps.empty() && job_.steps.back().io.load) loads += beats;
    if (job_.preload_after) {
      load(job_.preload_after);
      loads += beats;
      r.load_beats += beats;
      r.io.load |= job_.preload_after;
    }
    if (job_.copy_after) {
      read_all(true);
      reads += beats;
    } else if (job_.sweep_after) {
      read_all(false);
      reads += beats;
    }
    if (job_.swap_after || job_.clear_after.clear) {  // the closing setup cycle
      TileIo io = job_.clear_after;
      if (job_.swap_after) {
        io.clear |= kPlaneDepth;
        io.clear_value[1] = job_.swap_after_depth;
      }
      clear(io, job_.swap_after);
    }
    store();
    r.store_beats = t_.cnt_tile_stores_o;
    // The tile counters were cleared at the last step's setup: its loads, then the reads (a
    // copy or sweep and the store may pass the counter's width, TileCntW: it saturates).
    audit_beats(counted(t_.cnt_tile_loads_o, r.store_beats), std::min(loads, 2 * beats - 1),
                std::min(reads, 2 * beats - 1));
    r.store_end = s_.cycle;
    if (!stored_.empty() && out_.go) reread();
    return out_;
  }

 private:
  // The tile counters' beats, for audit_beats.
  TileRun counted(uint64_t loads, uint64_t stores) const {
    TileRun c;
    c.x0 = job_.x0;
    c.y0 = job_.y0;
    c.load_beats = loads;
    c.store_beats = stores;
    return c;
  }
  uint32_t bits(unsigned w) { return uint32_t(idle_.next() & ((uint64_t{1} << w) - 1)); }
  void refuses(const char* why) const {
    check_refuses(t_.frag_ready_o, job_.x0, job_.y0, s_.cycle, why);
  }
  // An edge of the stream, drain or store, then the retire port's writes at the next.
  void tick_watched(size_t accepted) {
    s_.tick();
    out_.go = s_.feed.observe(t_, s_.cycle - out_.run.load_begin, accepted) && out_.go;
  }

  void idle_tile_port() {
    t_.tile_we_i = bits(1);
    t_.tile_planes_i = bits(kPortPlanes);
    t_.tile_addr_i = bits(beat_aw_);
    BeatWords w;
    scramble(w, 0, [this](unsigned b) { return bits(b); });
    put_beat(t_, w);
  }
  void idle_fragment() {
    t_.frag_x_i = bits(16);
    t_.frag_y_i = bits(16);
    t_.frag_z_i = bits(lanes::kDepth);
    t_.frag_rgba_i = bits(32);
    t_.frag_cov_i = bits(lanes::kCov);
  }

  void step(size_t i);
  void read_all(bool copy);
  void setup();
  void clear(const TileIo& io, bool swap);
  void load(uint8_t planes);
  void stream();
  void drain();
  void count(TileRun& r);
  void store();
  void reread();

  Sim& s_;
  VModel& t_;
  const TileJob& job_;
  const TileStep* step_ = nullptr;  // the pass being run
  const TileSweep sweep_;
  XorShift idle_;
  unsigned beat_aw_ = 0;    // zb_rop's BeatAW: tile_addr_i's width
  uint64_t thr_ = 0;        // backpressure_threshold
  uint64_t cleared_ = 0;    // the setup cycle: the counters count from the next one on
  uint64_t refused_ = 0;    // cycles offered and not accepted: cnt_stall_cycles_o's events
  std::vector<BeatWords> stored_;  // for reread_stores
  TileResult out_;
};

// One pass on the resident tile: setup, the loads it needs, its stream and drain, the counters.
// The monitor's tile cycles count from the run's first setup, the pass's stream apart.
void TileRunner::step(size_t i) {
  step_ = &job_.steps[i];
  const TileStep& st = *step_;
  TileRun r;
  r.x0 = job_.x0;
  r.y0 = job_.y0;
  r.io = st.io;
  r.load_begin = out_.run.load_begin;
  if (st.preload) load(st.preload);
  if (st.copy || st.sweep) read_all(st.copy);
  s_.feed.begin_tile(job_.x0, job_.y0, st.stream, st.n);
  setup();
  load(st.io.load);
  idle_tile_port();
  r.stream_begin = s_.cycle;
  if (i == 0) out_.run.stream_begin = r.stream_begin;
  stream();
  drain();
  r.stream_end = out_.run.stream_end = s_.cycle;
  out_.run.stream_cycles += r.stream_end - r.stream_begin;
  out_.go = s_.feed.end_tile(s_.cycle - r.load_begin) && out_.go;
  // After the monitor, so that a wrong write is reported as such first.
  if (job_.check_timing && st.n > 0 && out_.go)
    s_.timing.check(r, st.stream, st.n, thr_ != 0 ? job_.accepted : nullptr,
                    s_.feed.on() ? &s_.feed.x4_cycles() : nullptr);
  count(r);
  TileIo& io = out_.run.io;  // the run's: every plane cleared, with its value, and loaded
  io.clear |= st.io.clear;
  io.load |= st.io.load | st.preload;
  for (size_t p = 0; p < kWordPlanes; ++p)
    if (st.io.clear >> p & 1) io.clear_value[p] = st.io.clear_value[p];
  if (st.io.clear & kPlaneAccum) io.accum_clear = st.io.accum_clear;
  // The counters count from the setup: a load before it (a copy's), the driver's.
  out_.run.load_beats += t_.cnt_tile_loads_o + (st.preload ? uint64_t(sweep_.beats()) : 0);
  if (i + 1 < job_.steps.size())
    audit_beats(counted(t_.cnt_tile_loads_o, 0), st.io.load ? uint64_t(sweep_.beats()) : 0, 0);
}

// A read of every beat, the data unused: with `copy` (tile_copy_i) the depth beats go to the
// peel plane, the last a cycle after its read; else a sweep, which leaves every plane whole at
// its epoch so that a fast clear may follow (zb_plane's FastClearWhole).
void TileRunner::read_all(bool copy) {
  t_.tile_req_i = 1;
  t_.tile_we_i = 0;
  t_.tile_copy_i = copy;
  for (int b = 0; b < sweep_.beats(); ++b) {
    t_.tile_addr_i = b;
    tick_watched(0);
    refuses(copy ? "tile_req_i (a copy)" : "tile_req_i (a sweep)");
  }
  t_.tile_req_i = 0;
  t_.tile_copy_i = 0;
  idle_tile_port();
  if (copy) tick_watched(0);  // the last beat's load into peel
}

// Pass state, counter clear, tile origin and the fast clear of the planes io.clear names.
void TileRunner::setup() {
  t_.tile_x0_i = job_.x0;
  t_.tile_y0_i = job_.y0;
  t_.state_i = port_state(step_->state);
  t_.state_layers_i = port_state_layers(step_->state);
  t_.state_we_i = 1;
  t_.cnt_clear_i = 1;
  cleared_ = s_.cycle;
  clear(step_->io, step_->swap);
  t_.state_we_i = 0;
  t_.state_i = bits(13);  // pass_state_t
  t_.state_layers_i = bits(3);
  t_.cnt_clear_i = 0;
}

// One cycle: the fast clear of the planes io.clear names, with `swap` (tile_copy_i) trading
// depth and peel first (a renamed copy: depth's words become peel's, the other bank is cleared).
void TileRunner::clear(const TileIo& io, bool swap) {
  t_.tile_clear_i = io.clear != 0;
  t_.tile_copy_i = swap;
  t_.tile_planes_i = port_planes(io.clear);
  t_.tile_mlab_i = (io.clear & kPlaneLayers) != 0;  // the layers emptied
  put_beat(t_, clear_beat(io));
  s_.tick();
  if (io.clear) refuses(swap ? "tile_clear_i (a renamed copy)" : "tile_clear_i");
  t_.tile_clear_i = 0;
  t_.tile_copy_i = 0;
  t_.tile_mlab_i = 0;
}

void TileRunner::load(uint8_t planes) {
  if (!planes) return;
  t_.tile_req_i = 1;
  t_.tile_we_i = 1;
  t_.tile_planes_i = planes;
  for (int k = 0; k < sweep_.beats(); ++k) {
    t_.tile_addr_i = k;
    BeatWords w = sweep_.load(*job_.src, k);
    scramble(w, planes, [this](unsigned b) { return bits(b); });  // lanes not loaded
    put_beat(t_, w);
    s_.tick();
    refuses("tile_req_i (a load)");
  }
  t_.tile_req_i = 0;
}

// Offers fragment k every cycle (or, with back-pressure, a random valid gap and stall_i); it is
// accepted at the edge of a cycle with frag_valid_i && frag_ready_o. frag_ready_o also drops
// while the interlock holds fragments (zb_rop's skid register is full). The per-cycle loop
// works on locals: the model's byte-wide ports may alias any member, which would be reloaded
// after every store to them.
void TileRunner::stream() {
  Sim& s = s_;
  VModel& t = t_;
  const Streamed* f = step_->stream;
  const size_t n = step_->n;
  uint64_t* accepted = job_.accepted;
  const int x0 = job_.x0, y0 = job_.y0;
  const uint64_t load_begin = out_.run.load_begin;
  XorShift rng(step_->seed);
  const uint64_t thr = thr_ = backpressure_threshold(job_.backpressure);
  uint64_t waiting = 0;  // consecutive offers (valid, no stall_i) not accepted
  uint64_t refused = 0;
  bool go = out_.go;
  size_t k = 0;
  while (k < n) {
    bool stall = false, valid = true;
    if (thr != 0) {
      stall = rng.next() < thr;
      valid = rng.next() >= thr;
    }
    t.stall_i = stall;
    t.frag_valid_i = valid;
    if (valid) {
      t.frag_x_i = f[k].x;
      t.frag_y_i = f[k].y;
      t.frag_z_i = f[k].z;
      t.frag_rgba_i = f[k].rgba;
      t.frag_cov_i = f[k].cov;
    } else {
      idle_fragment();
    }
    if (s.probe) {  // only a traced model shows the offered fragment
      s.wave.frag_index = valid ? f[k].index : WaveProbe::kNone;
      s.wave.frag_prim = valid ? job_.pass[f[k].index].prim : WaveProbe::kNone;
    }
    // frag_ready_o follows stall_i within the cycle, so a changed stall_i needs an eval;
    // without back-pressure only flops move it, and the last edge's eval already shows it.
    if (thr != 0 || k == 0) t.eval();
    if (stall) check_refuses(t.frag_ready_o, x0, y0, s.cycle, "stall_i");
    refused += valid && !t.frag_ready_o;
    if (valid && t.frag_ready_o) {
      accepted[f[k].index] = s.cycle;
      ++k;
      waiting = 0;
    } else if (valid && !stall && ++waiting > kDrainLimit) {
      fail_not_ready(x0, y0);
    }
    s.tick();
    go = s.feed.observe(t, s.cycle - load_begin, k) && go;
  }
  out_.go = go;
  refused_ = refused;
  t.frag_valid_i = 0;
  t.stall_i = 0;
  s.wave.frag_index = s.wave.frag_prim = WaveProbe::kNone;
}

void TileRunner::drain() {
  const uint64_t last = s_.cycle;
  while (t_.busy_o) {
    idle_fragment();
    if (s_.cycle - last > kDrainLimit) fail_busy(job_.x0, job_.y0);
    tick_watched(step_->n);
  }
}

// The RTL's counters, final once drained, into the pass's and against the driver's view.
void TileRunner::count(TileRun& r) {
  out_.stats.emplace_back();
  PassStats& st = out_.stats.back();
  st.fragments_in += t_.cnt_frag_in_o;
  st.fragments_passed += t_.cnt_frag_passed_o;
  st.depth_reads += t_.cnt_depth_reads_o;
  st.depth_writes += t_.cnt_depth_writes_o;
  st.color_reads += t_.cnt_color_reads_o;
  st.color_writes += t_.cnt_color_writes_o;
  st.cycles += r.stream_end - r.stream_begin;
  r.stall_cycles = t_.cnt_stall_cycles_o;
  r.rtl_cycles = t_.cnt_cycles_o;
  out_.run.stall_cycles += r.stall_cycles;
  out_.run.rtl_cycles += r.rtl_cycles;
  const StreamCounters c{t_.cnt_frag_in_o, t_.cnt_frag_passed_o, t_.cnt_frag_killed_o,
                         r.rtl_cycles, r.stall_cycles};
  audit_stream(r, c, s_.cycle - cleared_ - 1, refused_);
}

void TileRunner::store() {
  const uint8_t planes = job_.store;
  if (!planes) return;
  t_.tile_req_i = 1;
  t_.tile_we_i = 0;
  t_.tile_resolve_i = job_.resolve == StoreResolve::kUnder;
  t_.tile_wboit_i = job_.resolve == StoreResolve::kWboit;
  t_.tile_mlab_i = job_.resolve == StoreResolve::kLayers;
  for (int b = 0; b < sweep_.beats(); ++b) {
    t_.tile_addr_i = b;
    if (job_.resolve == StoreResolve::kUnder) {  // the background in wdata lane 0, the rest unread
      BeatWords w;
      scramble(w, 0, [this](unsigned n) { return bits(n); });
      w[0][0] = job_.background;
      put_beat(t_, w);
    }
    tick_watched(0);
    refuses("tile_req_i (a store)");
    const BeatWords w = read_beat(t_);
    sweep_.store(w, planes, *job_.dst, b);
    if (job_.reread_stores && job_.resolve == StoreResolve::kNone) stored_.push_back(w);
    const uint64_t at = s_.cycle - 1 - out_.run.load_begin;
    out_.go = s_.feed.store(StoreBeat{job_.x0, job_.y0, b, planes, at, &w}) && out_.go;
  }
  t_.tile_req_i = 0;
  t_.tile_resolve_i = 0;
  t_.tile_wboit_i = 0;
  t_.tile_mlab_i = 0;
  idle_tile_port();
}

// After the store, outside the run's cycles: reads the stored planes again, beat by beat (every
// word must be the one the store read, and the port must hold it through a cycle with no read),
// then loads them back. The tile counters, not cleared since the setup, then hold one more tile
// of reads and of loads: past their width (zb_rop's TileCntW, two tiles' beats less one), so
// their saturation shows.
void TileRunner::reread() {
  const uint8_t planes = job_.store;
  const std::vector<BeatWords>& first = stored_;
  t_.tile_we_i = 0;
  // The port shows a read's beat "from cycle t+1 on" (docs/rtl.md "Tile port"): a bank that
  // loads its read register in the cycle with no read shows the next beat's word.
  for (size_t b = 0; b < first.size(); ++b) {
    t_.tile_req_i = 1;
    t_.tile_addr_i = uint32_t(b);
    s_.tick();
    check_reread(out_.run, planes, read_beat(t_), first[b], b,
                 "read again after its store (the store changed the plane)");
    t_.tile_req_i = 0;
    t_.tile_addr_i = uint32_t((b + 1) % first.size());
    s_.tick();
    check_reread(out_.run, planes, read_beat(t_), first[b], b,
                 "a cycle after its read, with no read between (the port must hold the beat)");
  }
  t_.tile_req_i = 1;
  const uint64_t beats = first.size(), most = 2 * beats - 1;  // 2^TileCntW - 1
  t_.tile_we_i = 1;
  t_.tile_planes_i = planes;
  for (size_t b = 0; b < first.size(); ++b) {
    t_.tile_addr_i = uint32_t(b);
    put_beat(t_, first[b]);
    s_.tick();
    // At every beat, not only the last: a count whose hold path rewrites it wrong shows only
    // at some cycles.
    const uint64_t loads = std::min(most, (job_.steps.back().io.load ? beats : 0) + b + 1);
    audit_reload(out_.run, t_.cnt_tile_stores_o, t_.cnt_tile_loads_o, most, loads, b);
  }
  t_.tile_req_i = 0;
  t_.tile_we_i = 0;
}

}  // namespace

TileResult run_tile(Sim& sim, const TileJob& job) { return TileRunner(sim, job).run(); }

uint64_t tile_seed(uint64_t run_seed, uint64_t pass, size_t tile) {
  return splitmix64(run_seed ^ splitmix64(pass * 0x100000001b3ull + tile));
}

}  // namespace zb
