#include "port_stress.h"

#include <algorithm>
#include <array>
#include <deque>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "port_lanes.h"
#include "rop/blend.h"
#include "rop_model.h"

namespace zb {
namespace {

constexpr int kBeats = kRtlTileW * kRtlTileH / kRtlBeat;
constexpr const char* kPlaneNames[kTilePlanes] = {"colour", "depth", "coverage", "peel",
                                                  "accumulation"};

constexpr int kPeelPlane = 3;  // kPlanePeel's number: read-only, one fresh flag

enum class Op : uint8_t { kIdle, kClear, kLoad, kRead };

// One cycle's operation on the port.
struct Step {
  Op op = Op::kIdle;
  int beat = 0;
  uint8_t planes = 0;             // a clear's or a load's
  bool copy = false, resolve = false, count_clear = false;
  BeatWords data;                 // a load's beat; a clear's values in lane 0; a resolve's bg
};

std::string step_text(uint64_t n, const Step& s) {
  std::string planes;
  for (int p = 0; p < kTilePlanes; ++p)
    if (s.planes >> p & 1) planes += std::string(planes.empty() ? "" : "+") + kPlaneNames[p];
  switch (s.op) {
    case Op::kClear: return fmt::format("op {}: fast clear of {}", n, planes);
    case Op::kLoad: return fmt::format("op {}: load of beat {} into {}", n, s.beat, planes);
    case Op::kRead:
      return fmt::format("op {}: read of beat {}{}{}", n, s.beat, s.copy ? " with copy" : "",
                         s.resolve ? fmt::format(" resolved under 0x{:08x}", s.data[0][0]) : "");
    case Op::kIdle: break;
  }
  return fmt::format("op {}: idle", n);
}

// The planes as the contract says they read: a beat's words per plane.
class PlaneModel {
 public:
  PlaneModel() : beats_(kBeats) {}
  void clear(const Step& s) {
    for (BeatWords& b : beats_) set(b, s.planes, s.data, true);
  }
  void load(const Step& s) { set(beats_[size_t(s.beat)], s.planes, s.data, false); }
  void copy(int beat) { beats_[size_t(beat)][kPeelPlane] = beats_[size_t(beat)][1]; }
  // What a read of `beat` shows, resolved under `bg` when asked.
  BeatWords read(int beat, bool resolve, uint32_t bg) const {
    BeatWords w = beats_[size_t(beat)];
    if (resolve)
      for (uint32_t& c : w[0]) {
        const Rgba8 v = unpack_rgba(c), b = unpack_rgba(bg);
        c = pack_rgba({resolve_under(v.r, b.r, v.a), resolve_under(v.g, b.g, v.a),
                       resolve_under(v.b, b.b, v.a), resolve_under(v.a, b.a, v.a)});
      }
    return w;
  }

 private:
  // A load takes each lane; a clear lane 0 for every word.
  static void set(BeatWords& b, uint8_t planes, const BeatWords& d, bool clear) {
    for (size_t p = 0; p < kWordPlanes; ++p)
      if (planes >> p & 1)
        for (size_t l = 0; l < size_t(kRtlBeat); ++l) b[p][l] = d[p][clear ? 0 : l];
    if (planes & kPlaneAccum)
      for (size_t l = 0; l < size_t(kRtlBeat); ++l) b.accum[l] = d.accum[clear ? 0 : l];
  }
  std::vector<BeatWords> beats_;
};

// What the contract allows next (docs/rtl.md "Port timing"): a fast clear flips a written
// plane's one-bit epoch, so every word must then be at the epoch (loaded, or read back since its
// last clear) or none written since the last clear; else words two clears old would read as
// current. Kept per plane that the pipeline can write (the peel plane keeps one fresh flag and
// is loaded or copied whole). A read writes back every such plane's beat two edges later (W2),
// at the epoch of its read, so a read is a write: a clear that flips the epoch in between leaves
// it fresh, one that does not (the plane all fresh) leaves it current; a load of the plane in
// that cycle takes the write port instead.
class Rules {
 public:
  Rules() {
    for (Plane& p : planes_) p.current.assign(kBeats, true);  // reset's sweep
  }
  // Whether plane p may be fast-cleared in this cycle.
  bool may_clear(int p) const {
    const Plane& q = planes_[size_t(p)];
    return p == kPeelPlane || q.all_fresh || q.n_current == kBeats;
  }
  // The cycle's operation, after its edge.
  void step(const Step& s) {
    for (int p = 0; p < kTilePlanes; ++p) {
      if (p == kPeelPlane) continue;
      Plane& q = planes_[size_t(p)];
      const bool clear = s.op == Op::kClear && (s.planes >> p & 1);
      const bool load = s.op == Op::kLoad && (s.planes >> p & 1);
      const bool flip = clear && !q.all_fresh;
      // The write-back of the read two cycles ago lands now at the epoch of its read: current
      // unless the epoch flipped since (this edge included), and not when a load of the plane
      // takes the write port.
      const bool wb2 = q.wb[1] >= 0 && !q.flipped[1] && !flip && !load;
      if (wb2) set(q, q.wb[1]);
      if (flip) {
        q.current.assign(kBeats, false);
        q.n_current = 0;
      }
      if (clear)
        q.all_fresh = true;
      else if (q.wb[0] >= 0 || load || wb2)
        q.all_fresh = false;  // W1 of a read, a load, or W2 at the epoch
      if (load) set(q, s.beat);
      q.wb[1] = q.wb[0];
      q.flipped[1] = q.flipped[0] || flip;
      q.wb[0] = s.op == Op::kRead ? s.beat : -1;
      q.flipped[0] = false;
    }
  }

 private:
  struct Plane {
    bool all_fresh = false;
    std::vector<bool> current;
    int n_current = kBeats;
    std::array<int, 2> wb{-1, -1};               // beats read one and two cycles ago
    std::array<bool, 2> flipped{false, false};    // the epoch flipped since that read
  };
  static void set(Plane& q, int beat) {
    if (!q.current[size_t(beat)]) {
      q.current[size_t(beat)] = true;
      ++q.n_current;
    }
  }
  std::array<Plane, kTilePlanes> planes_;
};

class Stress {
 public:
  Stress(const RtlOptions& o, uint64_t seed)
      : sim_(o.trace_path, o), t_(*sim_.top), rng_(seed) {}

  PortStressResult run(uint64_t ops) {
    // Every plane cleared to a known value first (a clear is what makes the words known).
    // and the counters cleared, so that the model counts from 0.
    Step first;
    first.op = Op::kClear;
    first.planes = 0x1f;
    first.data = random_beat();
    first.count_clear = true;
    apply(first);
    for (uint64_t n = 1; n <= ops && out_.mismatch.empty(); ++n) apply(next());
    out_.cycles = sim_.cycle;
    return out_;
  }

 private:
  uint32_t bits(unsigned width) {
    return uint32_t(rng_()) & (width >= 32 ? ~0u : (1u << width) - 1);
  }
  BeatWords random_beat() {
    BeatWords w;
    scramble(w, 0, [&](unsigned width) { return bits(width); });
    return w;
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  int pick(int n) { return int(rng_() % uint64_t(n)); }

  // The next operation: one at random, or the next of a sweep under way.
  Step next() {
    if (sweep_.empty() && chance(0.004)) plan_sweep();
    if (sweep_.empty()) return random_step();
    Step s = sweep_.front();
    sweep_.pop_front();
    return s;
  }

  // The peel plane keeps one fresh flag, not one a word (docs/rtl.md "Tile port"): after its
  // fast clear it is loaded or copied whole, every beat in order, as the driver does. A sweep
  // does that, after an idle cycle: every beat loaded (peel and other planes), or read with a
  // copy (and resolves under changing backgrounds).
  void plan_sweep() {
    sweep_.push_back(Step{});
    const bool load = chance(0.5);
    const uint8_t planes = uint8_t(kPlanePeel | pick(32));
    const bool resolve = chance(0.5);
    for (int b = 0; b < kBeats; ++b) {
      Step s;
      s.op = load ? Op::kLoad : Op::kRead;
      s.beat = b;
      s.planes = planes;
      s.data = random_beat();
      s.copy = !load;
      s.resolve = !load && resolve;
      s.count_clear = chance(0.002);
      sweep_.push_back(s);
    }
  }

  // A random operation the contract allows after the last one: a fast clear of a plane only as
  // Rules allows it, never two in a row (WriteBackBeforeClear); no load of the beat read in the
  // cycle before
  // (LoadAfterReadOfBeat); no load of peel but in a sweep; no fast clear in the cycle after a
  // read that copies (its peel write then takes the clear too).
  Step random_step() {
    Step s;
    const int kind = pick(10);
    s.op = kind < 2 ? Op::kClear : kind < 5 ? Op::kLoad : kind < 9 ? Op::kRead : Op::kIdle;
    // Beats near the last one: a read, load or clear next to an operation on the same beat.
    s.beat = chance(0.5) ? (last_.beat + pick(3) + kBeats - 1) % kBeats : pick(kBeats);
    s.planes = uint8_t(1 + pick(31));
    if (s.op == Op::kLoad) s.planes &= uint8_t(~kPlanePeel);
    s.data = random_beat();
    s.resolve = s.op == Op::kRead && chance(0.3);
    s.count_clear = chance(0.05);
    if (s.op == Op::kClear && (last_.op == Op::kClear || last_.copy)) s.op = Op::kIdle;
    if (s.op == Op::kClear)
      for (int p = 0; p < kTilePlanes; ++p)
        if (!rules_.may_clear(p)) s.planes &= uint8_t(~(1u << p));
    if (s.op == Op::kLoad && last_.op == Op::kRead && s.beat == last_.beat)
      s.beat = (s.beat + 1) % kBeats;
    if ((s.op == Op::kClear || s.op == Op::kLoad) && s.planes == 0) s.op = Op::kIdle;
    return s;
  }

  void apply(const Step& s) {
    VModel& t = t_;
    sim_.idle_inputs();
    t.tile_copy_i = 0;
    t.tile_resolve_i = 0;
    if (s.op != Op::kIdle) {
      put_beat(t, s.data);
      t.tile_planes_i = s.planes;
      t.tile_addr_i = uint32_t(s.beat);
      t.tile_clear_i = s.op == Op::kClear;
      t.tile_req_i = s.op == Op::kLoad || s.op == Op::kRead;
      t.tile_we_i = s.op == Op::kLoad;
      t.tile_copy_i = s.copy;
      t.tile_resolve_i = s.resolve;
    }
    t.cnt_clear_i = s.count_clear;
    sim_.tick();
    ++out_.ops;
    const uint64_t n = out_.ops - 1;
    // The beat's history: its loads and reads, and every fast clear (they touch all beats).
    auto& h = s.op == Op::kClear ? clears_ : beat_history_[size_t(s.beat)];
    if (s.op != Op::kIdle) h.push_back({n, sim_.cycle - 1, s});
    if (h.size() > 8) h.pop_front();
    // The counters after this edge: a clear's cycle counts nothing.
    cycles_ = s.count_clear ? 0 : cycles_ + 1;
    if (s.count_clear) loads_ = stores_ = 0;
    if (!s.count_clear && s.op == Op::kLoad) ++loads_;
    if (!s.count_clear && s.op == Op::kRead) ++stores_;
    // At this edge: the copy of last cycle's read lands in peel, this cycle's read shows its
    // beat (the words as they were before the edge), this cycle's clear or load writes.
    if (last_.copy) model_.copy(last_.beat);
    if (s.op == Op::kRead) check_read(s, n, model_.read(s.beat, s.resolve, s.data[0][0]));
    rules_.step(s);
    if (s.op == Op::kClear) model_.clear(s);
    if (s.op == Op::kLoad) model_.load(s);
    // The tile counters are a beat address and a bit wide, saturating (zb_rop's TileCntW).
    const uint64_t top = 2 * uint64_t(kBeats) - 1;
    check_counter("cnt_tile_loads_o", uint64_t(t.cnt_tile_loads_o), std::min(loads_, top), n);
    check_counter("cnt_tile_stores_o", uint64_t(t.cnt_tile_stores_o), std::min(stores_, top), n);
    check_counter("cnt_cycles_o", uint64_t(t.cnt_cycles_o), cycles_, n);
    last_ = s;
  }

  void check_read(const Step& r, uint64_t n, const BeatWords& expect) {
    if (!out_.mismatch.empty()) return;
    const BeatWords got = read_beat(t_);
    ++out_.reads;
    for (size_t l = 0; l < size_t(kRtlBeat) && out_.mismatch.empty(); ++l) {
      for (size_t p = 0; p < kWordPlanes; ++p) {
        // The cycle after a copy the peel plane takes the copy's write, not this read.
        if (p == kPeelPlane && last_.copy) continue;
        ++out_.words;
        if (got[p][l] != expect[p][l]) {
          fail(r, n, fmt::format("{} lane {}: rtl 0x{:x}, model 0x{:x}", kPlaneNames[p], l,
                                 got[p][l], expect[p][l]));
          return;
        }
      }
      ++out_.words;
      if (got.accum[l] != expect.accum[l])
        fail(r, n, fmt::format("accumulation lane {}: rtl {}, model {}", l,
                               accum_text(got.accum[l]), accum_text(expect.accum[l])));
    }
  }
  void check_counter(const char* name, uint64_t got, uint64_t want, uint64_t n) {
    if (out_.mismatch.empty() && got != want)
      out_.mismatch = fmt::format("after op {} (cycle {}): {} is {}, the model counts {}", n,
                                  sim_.cycle - 1, name, got, want);
  }
  void fail(const Step& r, uint64_t n, const std::string& what) {
    std::string text = fmt::format("{} (cycle {}): {}\n  the beat's last operations and the "
                                   "last fast clears before it:",
                                   step_text(n, r), sim_.cycle - 1, what);
    std::vector<Past> before(clears_.begin(), clears_.end());
    const auto& mine = beat_history_[size_t(r.beat)];
    before.insert(before.end(), mine.begin(), mine.end());
    std::sort(before.begin(), before.end(), [](const Past& a, const Past& b) { return a.op < b.op; });
    // The waveform's save file: a marker at the read that differs and at each of these.
    sim_.view.title = "port stress: " + step_text(n, r) + " differs";
    sim_.view.mismatch = sim_.cycle - 1;
    sim_.view.from = sim_.cycle > 24 ? sim_.cycle - 24 : 0;  // zoomed to the last cycles
    sim_.view.to = sim_.cycle + 2;
    sim_.view.markers.push_back({sim_.cycle - 1, "read that differs"});
    for (const Past& p : before) {
      if (p.op >= n) continue;
      text += "\n    " + step_text(p.op, p.step);
      if (sim_.view.markers.size() < 26)
        sim_.view.markers.push_back({p.cycle, step_text(p.op, p.step)});
    }
    out_.mismatch = text;
  }

  Sim sim_;
  VModel& t_;
  std::mt19937_64 rng_;
  PlaneModel model_;
  Rules rules_;
  Step last_;
  std::deque<Step> sweep_;  // the rest of a sweep under way
  uint64_t loads_ = 0, stores_ = 0, cycles_ = 0;
  struct Past {
    uint64_t op, cycle;
    Step step;
  };
  std::vector<std::deque<Past>> beat_history_ = std::vector<std::deque<Past>>(kBeats);
  std::deque<Past> clears_;
  PortStressResult out_;
};

}  // namespace

PortStressResult run_port_stress(const RtlOptions& o, uint64_t seed, uint64_t ops) {
  Stress s(o, seed);
  return s.run(ops);
}

}  // namespace zb
