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
                                                  "accumulation", "layers"};

constexpr int kDepthPlane = 1, kPeelPlane = 3;  // kPlaneDepth's and kPlanePeel's numbers

enum class Op : uint8_t { kIdle, kClear, kLoad, kRead };

// One cycle's operation on the port.
struct Step {
  Op op = Op::kIdle;
  int beat = 0;
  uint8_t planes = 0;             // a clear's or a load's
  bool copy = false;              // a read's copy to peel; a clear's renamed copy (a swap)
  bool resolve = false, count_clear = false;
  bool wboit = false;             // a read's resolve of the accumulation
  BeatWords data;                 // a load's beat; a clear's values in lane 0; a resolve's bg
};

std::string step_text(uint64_t n, const Step& s) {
  std::string planes;
  for (int p = 0; p < kTilePlanes; ++p)
    if (s.planes >> p & 1) planes += std::string(planes.empty() ? "" : "+") + kPlaneNames[p];
  switch (s.op) {
    case Op::kClear:
      return fmt::format("op {}: {}fast clear of {}", n, s.copy ? "renamed copy and " : "", planes);
    case Op::kLoad: return fmt::format("op {}: load of beat {} into {}", n, s.beat, planes);
    case Op::kRead:
      return fmt::format("op {}: read of beat {}{}{}{}", n, s.beat, s.copy ? " with copy" : "",
                         s.resolve ? fmt::format(" resolved under 0x{:08x}", s.data[0][0]) : "",
                         s.wboit ? " resolved from the accumulation" : "");
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
  void copy(int beat) { beats_[size_t(beat)][kPeelPlane] = beats_[size_t(beat)][kDepthPlane]; }
  void copy_all() {
    for (int b = 0; b < kBeats; ++b) copy(b);
  }
  // What a read of `beat` shows, resolved under `bg` or from the accumulation when asked.
  BeatWords read(const Step& s) const {
    BeatWords w = beats_[size_t(s.beat)];
    const Rgba8 b = unpack_rgba(s.data[0][0]);
    for (size_t l = 0; l < size_t(kRtlBeat); ++l) {
      const Rgba8 v = unpack_rgba(w[0][l]);
      if (s.resolve)
        w[0][l] = pack_rgba({resolve_under(v.r, b.r, v.a), resolve_under(v.g, b.g, v.a),
                             resolve_under(v.b, b.b, v.a), resolve_under(v.a, b.a, v.a)});
      if (s.wboit)
        w[0][l] = pack_rgba(resolve_wboit(v, w.accum[l].acc, w.accum[l].reveal,
                                          wboit_reveal_one(kRtlWboit.rev_bits)));
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

// What the contract allows next (docs/rtl.md "Port timing"): a fast clear steps a written
// bank's epoch, so no word may then carry the generation it steps to, or it would read as
// current with an old value: with one bit every word at the epoch (loaded, or read back since the
// last clear) or none written since the last clear; the depth banks' kRtlDepthGenBits bits take
// more clears (docs/rtl.md "Renamed copies"). Kept per bank: the depth and peel planes are two
// banks whose roles a renamed copy trades. A read writes back every bank's beat two edges later
// (W2) at the epoch of its read (the peel bank does not take part in a read that copies), so a
// read is a write: a clear that steps the epoch in between leaves it fresh, one that does not
// (the bank all fresh) leaves it current; a load of the bank in that cycle takes the write port
// instead. Words of a beat share their generation here: no pipeline writes.
class Rules {
 public:
  Rules() {
    for (size_t b = 0; b < banks_.size(); ++b) {
      banks_[b].gen.assign(kBeats, 0);  // reset's sweep: every word at epoch 0
      banks_[b].generations = b == kDepthPlane || b == kPeelPlane ? 1 << kRtlDepthGenBits : 2;
    }
  }
  // Whether plane p may be fast-cleared in this cycle (its bank after a renamed copy in it).
  bool may_clear(int p, bool swap = false) const {
    const Bank& q = banks_[bank(p, swap)];
    const int next = (q.epoch + 1) % q.generations;
    return q.all_fresh || std::none_of(q.gen.begin(), q.gen.end(), [&](int g) { return g == next; });
  }
  // Whether that clear steps an epoch with words of other generations left: one bit refuses it.
  bool deep(int p, bool swap = false) const {
    const Bank& q = banks_[bank(p, swap)];
    return !q.all_fresh && std::any_of(q.gen.begin(), q.gen.end(), [&](int g) { return g != q.epoch; });
  }
  // The cycle's operation, after its edge; `copied` the beat last cycle's read copied (or -1).
  void step(const Step& s, int copied) {
    const bool swap = s.op == Op::kClear && s.copy;
    if (swap) std::swap(role_[kDepthPlane], role_[kPeelPlane]);
    const size_t peel = role_[kPeelPlane];
    for (int p = 0; p < kTilePlanes; ++p) {
      const size_t b = role_[size_t(p)];
      Bank& q = banks_[b];
      const bool clear = s.op == Op::kClear && (s.planes >> p & 1);
      const bool copy_in = b == peel && copied >= 0;
      const bool load = (s.op == Op::kLoad && (s.planes >> p & 1)) || copy_in;
      const int load_beat = copy_in ? copied : s.beat;
      const bool step_epoch = clear && !q.all_fresh;
      const bool wb2 = q.wb[1] >= 0 && !load;
      if (wb2) q.gen[size_t(q.wb[1])] = q.wb_epoch[1];
      const bool wb2_current = wb2 && q.wb_epoch[1] == q.epoch;
      if (step_epoch) q.epoch = (q.epoch + 1) % q.generations;
      if (clear)
        q.all_fresh = true;
      else if (q.wb[0] >= 0 || load || wb2_current)
        q.all_fresh = false;  // W1 of a read, a load, or W2 at the epoch
      if (load) q.gen[size_t(load_beat)] = q.epoch;
      q.wb[1] = q.wb[0];
      q.wb_epoch[1] = q.wb_epoch[0];
      q.wb[0] = s.op == Op::kRead && !(s.copy && b == peel) && !copy_in ? s.beat : -1;
      q.wb_epoch[0] = q.epoch;
    }
  }

 private:
  struct Bank {
    int generations = 2, epoch = 0;
    bool all_fresh = false;
    std::vector<int> gen;                 // per beat: its words' generation
    std::array<int, 2> wb{-1, -1};        // beats read one and two cycles ago
    std::array<int, 2> wb_epoch{0, 0};    // the epoch their write-back carries
  };
  size_t bank(int p, bool swap) const {
    if (swap && p == kDepthPlane) return role_[kPeelPlane];
    if (swap && p == kPeelPlane) return role_[kDepthPlane];
    return role_[size_t(p)];
  }
  std::array<Bank, kTilePlanes> banks_;
  std::array<size_t, kTilePlanes> role_ = {0, 1, 2, 3, 4, 5};  // plane p's bank
};

class Stress {
 public:
  Stress(const RtlOptions& o, uint64_t seed)
      : sim_(o.trace_path, o, o.coverage), t_(*sim_.top), rng_(seed) {}

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
    for (AccumWord& a : w.accum)
      if (chance(0.75)) a = near_accum();
    return w;
  }
  // An accumulation word of any magnitude. The resolve's divider takes each quotient bit from
  // a compare of its remainder with acc_A, and its min from acc against acc_A: full-width random
  // words bring either pair near each other almost never. So acc_A of a random width, and each
  // channel at most acc_A (as the blend makes them), within 2 of it, or of acc_A's width.
  AccumWord near_accum() {
    const uint32_t mask = lanes::kAcc >= 32 ? ~0u : (1u << lanes::kAcc) - 1;
    AccumWord a;
    const uint32_t acc_a = bits(1 + unsigned(pick(int(lanes::kAcc))));
    const unsigned width = 32 - unsigned(__builtin_clz(acc_a | 1));
    a.acc[3] = acc_a;
    for (int c = 0; c < 3; ++c) {
      const int kind = pick(3);
      a.acc[size_t(c)] = kind == 0   ? uint32_t(uint64_t(acc_a) * bits(8) / 255)
                         : kind == 1 ? (acc_a + uint32_t(pick(5)) - 2) & mask
                                     : bits(width);
    }
    a.reveal = chance(0.5) ? bits(lanes::kRev) : bits(1 + unsigned(pick(int(lanes::kRev))));
    return a;
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  int pick(int n) { return int(rng_() % uint64_t(n)); }

  // The next operation: one at random, or the next of a sweep under way.
  Step next() {
    if (sweep_.empty() && chance(last_.op == Op::kClear ? 0.05 : 0.004)) plan_sweep();
    if (sweep_.empty()) return random_step();
    Step s = sweep_.front();
    sweep_.pop_front();
    return s;
  }

  // A sweep as the driver makes them: every beat loaded (peel and other planes), or read with a
  // copy (and resolves under changing backgrounds); right after a clear (more often there: a
  // copy or resolve the cycle after a clear), half the time right after a load or a read (a
  // store's: the copy or resolve then starts at the read's next cycle), else after an idle
  // cycle (a load of the beat just read, or of peel after a copy, is not allowed).
  void plan_sweep() {
    const bool load = chance(0.5);
    if ((load && last_.op == Op::kRead) || (last_.op != Op::kClear && chance(0.5)))
      sweep_.push_back(Step{});
    const uint8_t planes = uint8_t(kPlanePeel | pick(32));
    const int resolve = pick(3);  // none, under the background, from the accumulation
    for (int b = 0; b < kBeats; ++b) {
      Step s;
      s.op = load ? Op::kLoad : Op::kRead;
      s.beat = b;
      s.planes = planes;
      s.data = random_beat();
      s.copy = !load;
      s.resolve = !load && resolve == 1;
      s.wboit = !load && resolve == 2;
      s.count_clear = chance(0.002);
      sweep_.push_back(s);
    }
  }

  // A random operation the contract allows after the last one: a fast clear of a plane only as
  // Rules allows it, never two in a row (WriteBackBeforeClear); a renamed copy (a clear of depth
  // with tile_copy_i) the same, clearing no peel; no load of the beat read in the cycle before
  // (LoadAfterReadOfBeat); no fast clear and no load of peel in the cycle after a read that
  // copies (its peel write then takes the port).
  Step random_step() {
    Step s;
    const int kind = pick(10);
    s.op = kind < 2 ? Op::kClear : kind < 5 ? Op::kLoad : kind < 9 ? Op::kRead : Op::kIdle;
    // Beats near the last one: a read, load or clear next to an operation on the same beat.
    s.beat = chance(0.5) ? (last_.beat + pick(3) + kBeats - 1) % kBeats : pick(kBeats);
    s.planes = uint8_t(1 + pick(31));
    s.data = random_beat();
    s.resolve = s.op == Op::kRead && chance(0.3);
    s.wboit = s.op == Op::kRead && !s.resolve && chance(0.3);
    s.copy = s.op == Op::kRead ? chance(0.1) : s.op == Op::kClear && chance(0.3);
    if (s.op == Op::kClear && s.copy) s.planes = uint8_t((s.planes | kPlaneDepth) & ~kPlanePeel);
    s.count_clear = chance(0.05);
    if (s.op == Op::kClear && (last_.op == Op::kClear || last_.copy)) s.op = Op::kIdle;
    if (s.op == Op::kClear && s.copy && !rules_.may_clear(kDepthPlane, true)) s.copy = false;
    if (s.op == Op::kClear)
      for (int p = 0; p < kTilePlanes; ++p)
        if (!rules_.may_clear(p, s.copy)) s.planes &= uint8_t(~(1u << p));
    if (s.op == Op::kLoad && last_.op == Op::kRead && s.beat == last_.beat)
      s.beat = (s.beat + 1) % kBeats;
    if (s.op == Op::kLoad && last_.op == Op::kRead && last_.copy) s.planes &= uint8_t(~kPlanePeel);
    if ((s.op == Op::kClear || s.op == Op::kLoad) && s.planes == 0) s.op = Op::kIdle;
    if (s.op == Op::kIdle) s.copy = false;
    return s;
  }

  void apply(const Step& s) {
    VModel& t = t_;
    sim_.idle_inputs();
    t.tile_copy_i = 0;
    t.tile_resolve_i = 0;
    t.tile_wboit_i = 0;
    t.tile_mlab_i = 0;
    if (s.op != Op::kIdle) {
      put_beat(t, s.data);
      t.tile_planes_i = s.planes;
      t.tile_addr_i = uint32_t(s.beat);
      t.tile_clear_i = s.op == Op::kClear;
      t.tile_req_i = s.op == Op::kLoad || s.op == Op::kRead;
      t.tile_we_i = s.op == Op::kLoad;
      t.tile_copy_i = s.copy;
      t.tile_resolve_i = s.resolve;
      t.tile_wboit_i = s.wboit;
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
    if (s.op == Op::kClear) {
      out_.renames += s.copy;
      for (int p : {kDepthPlane, kPeelPlane})
        out_.deep_clears += (s.planes >> p & 1) && rules_.deep(p, s.copy);
    }
    const bool copied = last_.op == Op::kRead && last_.copy;
    if (copied) model_.copy(last_.beat);
    if (s.op == Op::kRead) check_read(s, n, model_.read(s));
    rules_.step(s, copied ? last_.beat : -1);
    if (s.op == Op::kClear && s.copy) model_.copy_all();
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
        // A read that copies shows no peel beat (the peel bank waits for the copy's write), nor
        // does one in the cycle after it (the peel bank takes that write instead).
        if (p == kPeelPlane && (r.copy || (last_.op == Op::kRead && last_.copy))) continue;
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
