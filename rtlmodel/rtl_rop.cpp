#include "rtl_rop.h"

#include <atomic>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <stdexcept>
#include <string>

#include <verilated.h>
#include <verilated_fst_c.h>
#if defined(VM_COVERAGE) && VM_COVERAGE
#include <cstdio>
#include <verilated_cov.h>

#include "code_coverage.h"
#endif

#include <fmt/core.h>

#include "parallel/parallel.h"
#include "rtl_timing.h"
#include "tile_bins.h"
#include "waves.h"

#ifdef ZB_RTL_BUG
#include "Vzb_rop_bug.h"
#include "Vzb_rop_bug_probe.h"
#include "Vzb_rop_bug_zb_rop.h"
using VModel = Vzb_rop_bug;
using VParams = Vzb_rop_bug_zb_rop;
using VProbe = Vzb_rop_bug_probe;
#elif defined(ZB_RTL_FAST)
#include "Vzb_rop_fast.h"
#include "Vzb_rop_fast_probe.h"
#include "Vzb_rop_fast_zb_rop.h"
using VModel = Vzb_rop_fast;
using VParams = Vzb_rop_fast_zb_rop;
using VProbe = Vzb_rop_fast_probe;
#elif defined(ZB_RTL_MUT)
#include "Vzb_rop_mut.h"
#include "Vzb_rop_mut_probe.h"
#include "Vzb_rop_mut_zb_rop.h"
using VModel = Vzb_rop_mut;
using VParams = Vzb_rop_mut_zb_rop;
using VProbe = Vzb_rop_mut_probe;
#else
#include "Vzb_rop.h"
#include "Vzb_rop_probe.h"
#include "Vzb_rop_zb_rop.h"
using VModel = Vzb_rop;
using VParams = Vzb_rop_zb_rop;
using VProbe = Vzb_rop_probe;
#endif

#if defined(__SANITIZE_ADDRESS__)
// Verilator 5.006's Verilated::catName keeps a thread_local buffer it never frees, so every
// thread that builds an RTL model (the lab's workers) loses it when it ends: not ours to fix.
// Here, beside the model, it holds for every program that links the RTL.
extern "C" const char* __lsan_default_suppressions() { return "leak:Verilated::catName\n"; }
#endif

namespace zb {
namespace {

// Verilator 5.006 keeps the context a thread set last in a plain static pointer
// (Verilated::lastContextp), which a VerilatedContext's constructor, a model's (its symbol
// table's) and every Verilated::threadContextp call write. Models on several threads
// (tile-parallel models, the lab's scenes) are made, unmade and given their contexts under this
// one lock, so they do not race on it.
std::mutex context_mutex;

void use_context(VerilatedContext* ctx) {
  const std::lock_guard<std::mutex> lock(context_mutex);
  Verilated::threadContextp(ctx);
}

}  // namespace

static_assert(VParams::TILE_W == kRtlTileW, "tb mirror of TILE_W disagrees with the RTL");
static_assert(VParams::TILE_H == kRtlTileH, "tb mirror of TILE_H disagrees with the RTL");
static_assert(VParams::DEPTH_BITS == kRtlDepthBits, "tb mirror of DEPTH_BITS disagrees");
static_assert(VParams::COV_SAMPLES == kRtlCoverageSamples, "tb mirror of COV_SAMPLES disagrees");
static_assert(VParams::CNT_W == 32, "the driver reads 32-bit counters");
static_assert(VParams::BEAT == kRtlBeat, "tb mirror of BEAT disagrees with the RTL");
static_assert(VParams::ACC_BITS == kRtlWboit.acc_bits, "tb mirror of ACC_BITS disagrees");
static_assert(VParams::REV_BITS == kRtlWboit.rev_bits, "tb mirror of REV_BITS disagrees");
static_assert(VParams::WEIGHT_BITS == kRtlWboit.weight_bits, "tb mirror of WEIGHT_BITS disagrees");

namespace {

constexpr uint64_t kDrainLimit = 1000;  // cycles busy_o (or frag_ready_o low) may last

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

// The accumulation word {r, acc_A, acc_B, acc_G, acc_R}, acc_R lowest.
constexpr unsigned kAccBits = unsigned(kRtlWboit.acc_bits), kRevBits = unsigned(kRtlWboit.rev_bits);

// The tile port's lane widths per word plane (kPlane* order: colour pack_rgba, depth,
// coverage count, peel depth).
constexpr unsigned kColorBits = 32, kDepthBits = kRtlDepthBits,
                   kCovBits = coverage_bits(kRtlCoverageSamples);
constexpr unsigned kLaneBits[kWordPlanes] = {kColorBits, kDepthBits, kCovBits, kDepthBits};

// A port's lanes one after another from bit 0 up, each value `width` (at most 32) bits: the
// tile port's buses are lanes side by side, so a beat moves a 32-bit word at a time instead of
// a masked read-modify-write per field.
template <class Port>
class PortWriter {
 public:
  explicit PortWriter(Port& port) : port_(port) {}
  void put(uint32_t v, unsigned width) {
    acc_ |= uint64_t(v & mask(width)) << fill_;
    fill_ += width;
    if (fill_ >= 32) flush_word();
  }
  ~PortWriter() {
    if constexpr (std::is_integral_v<Port>) {  // at most 64 bits: next_ < 2 while fill_ > 0
      port_ = Port(fill_ > 0 ? word_ | acc_ << (32 * next_) : word_);
    } else {
      if (fill_ > 0) port_[next_] = uint32_t(acc_);
    }
  }

 private:
  static uint32_t mask(unsigned w) { return w >= 32 ? ~0u : (1u << w) - 1; }
  void flush_word() {
    if constexpr (std::is_integral_v<Port>) {
      word_ |= (acc_ & 0xffffffffu) << (32 * next_);
    } else {
      port_[next_] = uint32_t(acc_);
    }
    ++next_;
    acc_ >>= 32;
    fill_ -= 32;
  }
  Port& port_;
  uint64_t acc_ = 0, word_ = 0;
  unsigned fill_ = 0, next_ = 0;
};

template <class Port>
class PortReader {
 public:
  explicit PortReader(const Port& port) : port_(port) {}
  uint32_t get(unsigned width) {
    if (fill_ < width) {
      acc_ |= uint64_t(word(next_++)) << fill_;
      fill_ += 32;
    }
    const uint32_t v = uint32_t(acc_) & (width >= 32 ? ~0u : (1u << width) - 1);
    acc_ >>= width;
    fill_ -= width;
    return v;
  }

 private:
  uint32_t word(unsigned i) const {
    if constexpr (std::is_integral_v<Port>) {
      return i < 2 ? uint32_t(uint64_t(port_) >> (32 * i)) : 0;
    } else {
      return port_[i];
    }
  }
  const Port& port_;
  uint64_t acc_ = 0;
  unsigned fill_ = 0, next_ = 0;
};

// The next accumulation word of a port.
template <class Port>
AccumWord get_accum(PortReader<Port>& r) {
  AccumWord w;
  for (uint32_t& c : w.acc) c = r.get(kAccBits);
  w.reveal = r.get(kRevBits);
  return w;
}
template <class Port>
void put_accum(PortWriter<Port>& p, const AccumWord& w) {
  for (uint32_t c : w.acc) p.put(c, kAccBits);
  p.put(w.reveal, kRevBits);
}

// The beat the tile port read at the last edge (colour, depth, coverage, accumulation; peel is
// never stored).
template <class Model>
BeatWords read_beat(const Model& t) {
  BeatWords w{};
  PortReader color(t.tile_rcolor_o), depth(t.tile_rdepth_o), cov(t.tile_rcov_o),
      acc(t.tile_racc_o);
  for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
    w[0][l] = color.get(kColorBits);
    w[1][l] = depth.get(kDepthBits);
    w[2][l] = cov.get(kCovBits);
    w.accum[l] = get_accum(acc);
  }
  return w;
}

// A beat onto the tile port's write lanes (colour, depth, coverage, peel, accumulation).
template <class Model>
void put_beat(Model& t, const BeatWords& w) {
  PortWriter color(t.tile_wcolor_i), depth(t.tile_wdepth_i), cov(t.tile_wcov_i),
      peel(t.tile_wpeel_i), acc(t.tile_wacc_i);
  for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
    color.put(w[0][l], kColorBits);
    depth.put(w[1][l], kDepthBits);
    cov.put(w[2][l], kCovBits);
    peel.put(w[3][l], kDepthBits);
    put_accum(acc, w.accum[l]);
  }
}

// Random bits for every lane of `w`'s planes not in `keep` (kPlane* mask): lanes the RTL must
// not read.
template <class Bits>
void scramble(BeatWords& w, uint8_t keep, Bits&& bits) {
  for (size_t pl = 0; pl < kWordPlanes; ++pl)
    if (!(keep >> pl & 1))
      for (auto& v : w[pl]) v = bits(kLaneBits[pl]);
  if (!(keep & kPlaneAccum))
    for (AccumWord& a : w.accum) {
      for (uint32_t& c : a.acc) c = bits(kAccBits);
      a.reveal = bits(kRevBits);
    }
}

// A fragment as streamed: the datapath's fields and its index in the pass.
struct Streamed {
  uint16_t x, y;
  uint32_t z, rgba, index;
  uint8_t cov;
};

// One Verilated model with its context, clock and optional FST. The FST opens at the first
// cycle it holds (dump_from), so its time starts there; beside zb_rop it holds the testbench's
// probe (waves.h), and its GTKWave save file is written when it closes.
struct Sim {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<VModel> top;
  std::unique_ptr<VerilatedFstC> fst;
  std::string fst_path;
  std::unique_ptr<VProbe> probe;
  WaveProbe wave;                           // the probe's inputs for the coming cycle
  WaveView view;                            // the save file's
  CoverageTotals* coverage = nullptr;
  std::unique_ptr<ProbeSink> probe_sink;    // with an FST: the monitor's transactions shown
  std::unique_ptr<RetireMonitor> monitor;   // with RtlOptions::retire_sink or an FST
  std::vector<uint32_t> tile_addr, tile_index;  // the monitor's view of the tile's stream
  IssueSchedule schedule{kRtlWindow, size_t(kRtlTileW) * kRtlTileH};  // the cycles' check
  std::vector<uint32_t> pixels;                 // its view of the tile's stream
  std::vector<uint64_t> issue;                  // and its issue cycles
  std::vector<uint64_t> accepts;                // its accept cycles, under back-pressure
  uint64_t cycle = 0;
  uint64_t dump_from, dump_to;

  // `path`: an FST of cycles [from, to] when set.
  Sim(const std::string& path, const RtlOptions& o, CoverageTotals* totals = nullptr,
      uint64_t from = 0, uint64_t to = std::numeric_limits<uint64_t>::max())
      : fst_path(path), coverage(totals), dump_from(from), dump_to(to) {
    std::unique_lock<std::mutex> lock(context_mutex);
    ctx = std::make_unique<VerilatedContext>();
    // The model's threads: Verilator's default (every core) would start an idle thread pool
    // beside each of the tile-parallel models.
    ctx->threads(kVerilatorThreads);
    if (!path.empty()) {
      probe_sink = std::make_unique<ProbeSink>(o.retire_sink, wave);
      monitor = std::make_unique<RetireMonitor>(*probe_sink);
    } else if (o.retire_sink) {
      monitor = std::make_unique<RetireMonitor>(*o.retire_sink);
    }
    std::vector<const char*> argv{"zb_rop"};
    for (const std::string& a : o.plusargs) argv.push_back(a.c_str());
    ctx->commandArgs(int(argv.size()), argv.data());
    ctx->assertOn(o.assertions);
    ctx->fatalOnError(true);
    if (!path.empty()) ctx->traceEverOn(true);  // before the model exists
    top = std::make_unique<VModel>(ctx.get(), "zb_rop");
    if (!path.empty()) {
      const std::filesystem::path p(path);
      if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
      probe = std::make_unique<VProbe>(ctx.get(), "tb");
    }
    lock.unlock();
    if (!path.empty()) {
      fst = std::make_unique<VerilatedFstC>();
      top->trace(fst.get(), 99);
      probe->trace(fst.get(), 99);
    }
    top->clk_i = 0;
    top->rst_ni = 0;
    idle_inputs();
    top->eval();
    tick();
    tick();
    top->rst_ni = 1;
    tick();
    // The tile memory's words are unknown after reset: one read of every beat puts them at the
    // planes' epoch, as a fast clear needs (zb_plane).
    top->tile_req_i = 1;
    for (int a = 0; a < kRtlTileW * kRtlTileH / kRtlBeat; ++a) {
      top->tile_addr_i = a;
      tick();
    }
    top->tile_req_i = 0;
    tick();
  }
  ~Sim() {
    // Verilator 5.006 erases a model's scopes through the thread's current context: make it
    // this model's, or destroying a model after another context came and went deadlocks.
    use_context(ctx.get());
    top->final();
    add_coverage();
    if (fst && fst->isOpen()) {
      fst->close();
      try {
        write_save_file(fst_path, view);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "zblend: %s\n", e.what());
      }
    }
    fst.reset();
    const std::lock_guard<std::mutex> lock(context_mutex);
    Verilated::threadContextp(ctx.get());
    probe.reset();
    top.reset();
  }
  Sim(const Sim&) = delete;
  Sim& operator=(const Sim&) = delete;

  // The context's coverage points die with the model: their counts go to the run's totals now.
  void add_coverage() noexcept {
#if defined(VM_COVERAGE) && VM_COVERAGE
    if (!coverage) return;
    try {
      ctx->coveragep()->write(coverage->scratch_path().c_str());
      coverage->add_file(coverage->scratch_path());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "zblend_tb: %s\n", e.what());
    }
#endif
  }

  void idle_inputs() {
    top->state_we_i = 0;
    top->frag_valid_i = 0;
    top->stall_i = 0;
    top->tile_req_i = 0;
    top->tile_we_i = 0;
    top->tile_clear_i = 0;
    top->tile_planes_i = 0;
    top->cnt_clear_i = 0;
  }

  // One clock: falling edge with the inputs as set, then the rising edge that samples them.
  // Time 2c is cycle c's falling edge, 2c+1 its rising edge. The inputs must be evaluated
  // before the rising edge: Verilator's assertions read the values of the last evaluation,
  // so inputs set after the falling edge's evaluation would reach them a cycle late.
  // The waveform's time: 10 ns a cycle (waves.h).
  void tick() {
    const bool dump = fst && cycle - dump_from <= dump_to - dump_from;
    if (dump && !fst->isOpen()) {
      fst->open(fst_path.c_str());
      if (!fst->isOpen()) throw std::runtime_error("cannot write waveform " + fst_path);
    }
    if (dump) show_probe();
    top->clk_i = 0;
    ctx->time(wave_fall_ps(cycle));
    top->eval();
    if (dump) fst->dump(wave_fall_ps(cycle));
    top->clk_i = 1;
    ctx->time(wave_rise_ps(cycle));
    top->eval();
    if (dump) fst->dump(wave_rise_ps(cycle));
    wave.next_cycle();
    ++cycle;
  }

  void show_probe() {
    VProbe& p = *probe;
    p.pass_no = wave.pass_no;
    p.frag_index = wave.frag_index;
    p.frag_prim = wave.frag_prim;
    p.x4_retire = wave.x4_retire;
    p.x4_index = wave.x4_index;
    p.x4_golden_dwe = wave.x4_dwe;
    p.x4_golden_depth = wave.x4_depth;
    p.x4_golden_vwe = wave.x4_vwe;
    p.x4_golden_cov = wave.x4_cov;
    p.x11_retire = wave.x11_retire;
    p.x11_index = wave.x11_index;
    p.x11_golden_cwe = wave.x11_cwe;
    p.x11_golden_color = wave.x11_color;
    p.x11_golden_awe = wave.x11_awe;
    for (unsigned c = 0; c < 4; ++c) p.x11_golden_acc[c] = wave.x11_acc[c];
    p.x11_golden_reveal = wave.x11_reveal;
    p.mismatch = wave.mismatch || cycle == view.mismatch;
    p.eval();
  }
};

}  // namespace

struct RtlRop::Impl {
  RtlOptions opt;
  Sim sim;
  std::vector<std::unique_ptr<Sim>> helpers;  // the other models of a tile-parallel run
  Framebuffer fb;
  RopState state;
  std::vector<Fragment> frags;      // the current (or last ended) pass
  std::vector<uint64_t> accepted;   // accept cycle per fragment
  std::vector<Streamed> binned;     // frags in tile order, stable
  std::vector<uint32_t> tile_first; // per tile, start in `binned`; one extra at the end
  std::vector<TileRun> runs;
  TileStates tiles;                 // the frame's planes per tile: cleared or stored
  uint64_t pass_no = 0;
  bool in_pass = false;
  uint64_t io_cycles = 0, stalls = 0;
  uint64_t cycles = 0;              // one model's cycles since reset: reset, sweep, every tile

  explicit Impl(RtlOptions o)
      : opt(std::move(o)), sim(opt.trace_path, opt, opt.coverage), cycles(sim.cycle) {}

  int models() const { return opt.trace_path.empty() ? std::max(1, opt.threads) : 1; }

  int tiles_x() const { return (fb.width + kRtlTileW - 1) / kRtlTileW; }

  uint64_t tile_seed(uint64_t pass, size_t tile) const {
    return splitmix64(opt.seed ^ splitmix64(pass * 0x100000001b3ull + tile));
  }

  // Runs tile (x0, y0) of a pass: the setup cycle (pass state, counter clear, fast clear of the
  // planes `io` clears), the load beats of the planes it loads from `src`, `n` fragments, the
  // drain, the store beats; the stored planes go to `dst`. Returns false when the retire sink
  // asked to stop.
  bool run_tile(Sim& s, const Framebuffer& src, Framebuffer& dst, int x0, int y0,
                const TileIo& io, const Streamed* f, size_t n, uint64_t seed,
                uint64_t* accept_out, TileRun& run, PassStats& stats) const {
    VModel& t = *s.top;
    const TileSweep sweep(src.width, src.height, x0, y0);
    // Inputs the port leaves unread in a cycle (state_i without state_we_i; the tile port's
    // fields without tile_req_i or tile_clear_i; a fragment's without frag_valid_i) take random
    // values from a generator of their own, so RTL that reads one where it must not mismatches.
    XorShift idle(seed ^ 0x1d1e5eedull);
    auto bits = [&idle](unsigned w) { return uint32_t(idle.next() & ((uint64_t{1} << w) - 1)); };
    unsigned beat_aw = 0;  // zb_rop's BeatAW: tile_addr_i's width
    while ((1u << beat_aw) < unsigned(sweep.beats())) ++beat_aw;
    auto idle_tile_port = [&] {
      t.tile_we_i = bits(1);
      t.tile_planes_i = bits(kTilePlanes);
      t.tile_addr_i = bits(beat_aw);
      BeatWords w;
      scramble(w, 0, bits);
      put_beat(t, w);
    };
    auto idle_fragment = [&] {
      t.frag_x_i = bits(16);
      t.frag_y_i = bits(16);
      t.frag_z_i = bits(kDepthBits);
      t.frag_rgba_i = bits(32);
      t.frag_cov_i = bits(kCovBits);
    };
    // frag_ready_o must be low in a cycle with stall_i, tile_req_i or tile_clear_i (docs/rtl.md
    // "Port timing"); the driver offers no fragment then, so only this check sees a port that
    // would take one. Read after an edge whose inputs are still applied.
    auto refuses = [&](const char* why) {
      if (t.frag_ready_o)
        throw std::runtime_error(fmt::format(
            "rtl: tile ({},{}) frag_ready_o high at cycle {} with {} (docs/rtl.md \"Port "
            "timing\": the port must refuse fragments then)",
            x0, y0, s.cycle, why));
    };
    run.x0 = x0;
    run.y0 = y0;
    run.io = io;
    run.load_begin = s.cycle;
    bool go = true;
    size_t k = 0;  // fragments accepted
    if (s.monitor) {
      s.tile_addr.resize(n);
      s.tile_index.resize(n);
      for (size_t j = 0; j < n; ++j) {
        s.tile_addr[j] = uint32_t(f[j].y - y0) * kRtlTileW + uint32_t(f[j].x - x0);
        s.tile_index[j] = f[j].index;
      }
      s.monitor->begin_tile(x0, y0, s.tile_addr.data(), s.tile_index.data(), n);
    }
    // After each edge of the stream, drain and store: the retire port's writes at the next.
    auto watch = [&] {
      if (!s.monitor) return;
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
      PortReader wacc(t.mon_wacc_o);
      p.wacc = get_accum(wacc);
      go = s.monitor->observe(p, s.cycle - run.load_begin, k) && go;
    };
    t.tile_x0_i = x0;
    t.tile_y0_i = y0;
    t.state_i = pack_state(state);
    t.state_we_i = 1;
    t.cnt_clear_i = 1;
    const uint64_t cleared = s.cycle;  // the counters count from the next cycle on
    t.tile_clear_i = io.clear != 0;
    t.tile_planes_i = io.clear;
    put_beat(t, clear_beat(io));
    s.tick();
    if (io.clear) refuses("tile_clear_i");
    t.state_we_i = 0;
    t.state_i = bits(13);  // pass_state_t
    t.cnt_clear_i = 0;
    t.tile_clear_i = 0;
    if (io.load) {
      t.tile_req_i = 1;
      t.tile_we_i = 1;
      t.tile_planes_i = io.load;
      for (int k = 0; k < sweep.beats(); ++k) {
        t.tile_addr_i = k;
        BeatWords w = sweep.load(src, k);
        scramble(w, io.load, bits);  // the planes not loaded: unread lanes
        put_beat(t, w);
        s.tick();
        refuses("tile_req_i (a load)");
      }
      t.tile_req_i = 0;
    }
    idle_tile_port();

    run.stream_begin = s.cycle;
    XorShift rng(seed);
    const double p = opt.backpressure;
    const uint64_t thr = p <= 0 ? 0 : p >= 1 ? std::numeric_limits<uint64_t>::max()
                                              : uint64_t(p * 18446744073709551616.0);
    // Offer fragment k every cycle (or, with back-pressure, a random valid gap and stall_i);
    // it is accepted at the edge of a cycle with frag_valid_i && frag_ready_o. frag_ready_o
    // also drops while the interlock holds fragments (zb_rop's skid register is full).
    uint64_t refused = 0;  // consecutive offers (valid, no stall_i) not accepted
    uint64_t waits = 0;    // cycles offered and not accepted: cnt_stall_cycles_o's events
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
        s.wave.frag_prim = valid ? frags[f[k].index].prim : WaveProbe::kNone;
      }
      // frag_ready_o follows stall_i within the cycle, so a changed stall_i needs an eval;
      // without back-pressure only flops move it, and the last edge's eval already shows it.
      if (thr != 0 || k == 0) t.eval();
      if (stall) refuses("stall_i");
      waits += valid && !t.frag_ready_o;
      if (valid && t.frag_ready_o) {
        accept_out[f[k].index] = s.cycle;
        ++k;
        refused = 0;
      } else if (valid && !stall && ++refused > kDrainLimit) {
        throw std::runtime_error("rtl: frag_ready_o low for " + std::to_string(kDrainLimit) +
                                 " cycles (tile " + std::to_string(x0) + "," +
                                 std::to_string(y0) + ")");
      }
      s.tick();
      watch();
    }
    t.frag_valid_i = 0;
    t.stall_i = 0;
    s.wave.frag_index = s.wave.frag_prim = WaveProbe::kNone;
    const uint64_t last = s.cycle;
    while (t.busy_o) {
      idle_fragment();
      if (s.cycle - last > kDrainLimit)
        throw std::runtime_error("rtl: busy_o still high " + std::to_string(kDrainLimit) +
                                 " cycles after the last fragment (tile " +
                                 std::to_string(x0) + "," + std::to_string(y0) + ")");
      s.tick();
      watch();
    }
    run.stream_end = s.cycle;
    if (s.monitor) go = s.monitor->end_tile(s.cycle - run.load_begin) && go;
    // The stream's cycles are the issue schedule's, exactly (a slower or faster RTL is a
    // defect too: the cost model says what it must take); under back-pressure, the schedule
    // of the accepts the RTL made. After the monitor, so that a wrong write is reported as
    // such first.
    if (opt.check_timing && n > 0 && go) {
      s.pixels.resize(n);
      for (size_t j = 0; j < n; ++j)
        s.pixels[j] = uint32_t(f[j].y - y0) * kRtlTileW + uint32_t(f[j].x - x0);
      s.issue.resize(n);
      if (thr != 0) {
        s.accepts.resize(n);
        for (size_t j = 0; j < n; ++j) s.accepts[j] = accept_out[f[j].index] - run.stream_begin;
      }
      const uint64_t want = s.schedule.run(s.pixels.data(), n, s.issue.data(),
                                           thr != 0 ? s.accepts.data() : nullptr);
      // With the monitor, each fragment's too: X4 a fixed number of cycles after its issue.
      if (s.monitor) {
        const auto& x4 = s.monitor->x4_cycles();
        const uint64_t from = run.stream_begin - run.load_begin;
        for (size_t j = 0; j < n; ++j)
          if (x4[j] - s.issue[j] != x4[0] - s.issue[0])
            throw std::runtime_error(fmt::format(
                "rtl: fragment #{} (position {} of tile ({},{})'s stream) reached X4 {} cycles "
                "after its issue in the schedule (rtl_timing.h), the tile's first {} "
                "(--no-timing-check to go on)",
                f[j].index, j, x0, y0, int64_t(x4[j] - s.issue[j] - from),
                int64_t(x4[0] - s.issue[0] - from)));
      }
      if (run.stream_end - run.stream_begin != want)
        throw std::runtime_error("rtl: tile (" + std::to_string(x0) + "," + std::to_string(y0) +
                                 ") streamed " + std::to_string(n) + " fragments in " +
                                 std::to_string(run.stream_end - run.stream_begin) +
                                 " cycles, the issue schedule (rtl_timing.h) says " +
                                 std::to_string(want) + " (--no-timing-check to go on)");
    }
    stats.fragments_in += t.cnt_frag_in_o;
    stats.fragments_passed += t.cnt_frag_passed_o;
    stats.depth_reads += t.cnt_depth_reads_o;
    stats.depth_writes += t.cnt_depth_writes_o;
    stats.color_reads += t.cnt_color_reads_o;
    stats.color_writes += t.cnt_color_writes_o;
    stats.cycles += run.stream_end - run.stream_begin;
    run.stall_cycles = t.cnt_stall_cycles_o;
    run.rtl_cycles = t.cnt_cycles_o;
    if (uint64_t{t.cnt_frag_killed_o} != uint64_t{t.cnt_frag_in_o} - t.cnt_frag_passed_o)
      throw std::runtime_error("rtl: cnt_frag_killed_o != cnt_frag_in_o - cnt_frag_passed_o");
    // The driver saw every cycle and every refused offer: the counters must say the same.
    if (run.rtl_cycles != s.cycle - cleared - 1 || run.stall_cycles != waits)
      throw std::runtime_error(
          "rtl: tile (" + std::to_string(x0) + "," + std::to_string(y0) + ") counted " +
          std::to_string(run.rtl_cycles) + " cycles and " + std::to_string(run.stall_cycles) +
          " stall cycles, the driver clocked " + std::to_string(s.cycle - cleared - 1) +
          " and saw " + std::to_string(waits) + " offers refused");

    std::vector<BeatWords> stored;  // for reread_stores
    if (io.store) {
      t.tile_req_i = 1;
      t.tile_we_i = 0;
      for (int b = 0; b < sweep.beats(); ++b) {
        t.tile_addr_i = b;
        s.tick();
        watch();
        refuses("tile_req_i (a store)");
        const BeatWords w = read_beat(t);
        sweep.store(w, io.store, dst, b);
        if (opt.reread_stores) stored.push_back(w);
        if (s.monitor)
          go = s.monitor->store(StoreBeat{x0, y0, b, io.store, s.cycle - 1 - run.load_begin, &w}) &&
               go;
      }
      t.tile_req_i = 0;
      idle_tile_port();
    }
    run.load_beats = t.cnt_tile_loads_o;
    run.store_beats = t.cnt_tile_stores_o;
    const uint64_t beats = uint64_t(sweep.beats());
    if (run.load_beats != (io.load ? beats : 0) || run.store_beats != (io.store ? beats : 0))
      throw std::runtime_error("rtl: tile (" + std::to_string(x0) + "," + std::to_string(y0) +
                               ") counted " + std::to_string(run.load_beats) + " load and " +
                               std::to_string(run.store_beats) + " store beats, the driver moved " +
                               std::to_string(io.load ? beats : 0) + " and " +
                               std::to_string(io.store ? beats : 0));
    run.store_end = s.cycle;
    if (!stored.empty() && go) reread(s, x0, y0, io.store, io.load != 0, stored);
    return go;
  }

  // After a store: reads the planes `planes` of the tile again, beat by beat (every word must
  // be the one the store read, and the port must hold it through a cycle with no read), then
  // loads those words back (the planes read the same after).
  // Outside the run's cycles (store_end is taken before). The tile counters, not cleared since
  // the setup, then hold one more tile of reads and of loads: past their width (zb_rop's
  // TileCntW, two tiles' beats less one), so their saturation shows.
  static void reread(Sim& s, int x0, int y0, uint8_t planes, bool loaded,
                     const std::vector<BeatWords>& first) {
    VModel& t = *s.top;
    t.tile_we_i = 0;
    static const char* const kPlane[3] = {"colour", "depth", "coverage"};
    // The port's words against beat b's first read; `what` names the read.
    auto same = [&](size_t b, const char* what) {
      const BeatWords w = read_beat(t);
      for (unsigned l = 0; l < unsigned(kRtlBeat); ++l) {
        for (size_t p = 0; p < 3; ++p)
          if ((planes >> p & 1) && w[p][l] != first[b][p][l])
            throw std::runtime_error(fmt::format(
                "rtl: tile ({},{}) {}: {} {:#x} at beat {} lane {}, where its store read {:#x}",
                x0, y0, what, kPlane[p], w[p][l], b, l, first[b][p][l]));
        if ((planes & kPlaneAccum) && w.accum[l] != first[b].accum[l])
          throw std::runtime_error(fmt::format(
              "rtl: tile ({},{}) {}: accumulation {} at beat {} lane {}, where its store read {}",
              x0, y0, what, accum_text(w.accum[l]), b, l, accum_text(first[b].accum[l])));
      }
    };
    // Each beat read again, then a cycle with no read at the next beat's address: the port
    // shows a read's beat "from cycle t+1 on" (docs/rtl.md "Tile port"), so it must still show
    // it, and a bank that loads its read register anyway shows the other word.
    for (size_t b = 0; b < first.size(); ++b) {
      t.tile_req_i = 1;
      t.tile_addr_i = uint32_t(b);
      s.tick();
      same(b, "read again after its store (the store changed the plane)");
      t.tile_req_i = 0;
      t.tile_addr_i = uint32_t((b + 1) % first.size());
      s.tick();
      same(b, "a cycle after its read, with no read between (the port must hold the beat)");
    }
    t.tile_req_i = 1;
    const uint64_t beats = first.size(), most = 2 * beats - 1;  // 2^TileCntW - 1
    t.tile_we_i = 1;
    t.tile_planes_i = planes;
    for (size_t b = 0; b < first.size(); ++b) {
      t.tile_addr_i = uint32_t(b);
      put_beat(t, first[b]);
      s.tick();
      // Both counts at every beat, not only at the end: the store count, saturated at the last
      // read, must hold there; the load count climbs one a beat to its saturation. A count
      // whose hold path rewrites it wrong shows only at some cycles.
      const uint64_t loads = std::min(most, (loaded ? beats : 0) + b + 1);
      if (t.cnt_tile_stores_o != most || t.cnt_tile_loads_o != loads)
        throw std::runtime_error(fmt::format(
            "rtl: tile ({},{}) counted {} store and {} load beats after its store was read "
            "again and loaded back; two tiles of beats saturate at {}: want {} and {} at "
            "load-back beat {}",
            x0, y0, t.cnt_tile_stores_o, t.cnt_tile_loads_o, most, most, loads, b));
    }
    t.tile_req_i = 0;
    t.tile_we_i = 0;
  }

  // Bins `frags` into tiles, stably (tile_bins.h).
  void bin() {
    TileBins bins;
    bin_by_tile(frags.data(), frags.size(), fb.width, fb.height, kRtlTileW, kRtlTileH, bins);
    tile_first = std::move(bins.first);
    binned.resize(frags.size());
    for (size_t k = 0; k < bins.order.size(); ++k) {
      const Fragment& f = frags[bins.order[k]];
      binned[k] = Streamed{f.x, f.y, f.z, pack_rgba(f.color), bins.order[k], f.coverage};
    }
  }
};

const char* RtlRop::build() {
#if defined(ZB_RTL_FAST)
  return "speed build, no assertions";
#elif defined(ZB_RTL_MUT)
  return "mutant netlist, no assertions";
#elif defined(ZB_RTL_BUG)
  return "assertion build with injected defects";
#else
  return "assertion build";
#endif
}

RtlRop::RtlRop(RtlOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
RtlRop::~RtlRop() = default;

void RtlRop::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                         int coverage_samples, const WboitFormat& wboit) {
  if (wboit != kRtlWboit)
    throw std::invalid_argument(fmt::format(
        "rtl backend: accumulation {} bits, revealage {} bits, weight {} bits; the Verilated "
        "zb_rop has ACC_BITS {}, REV_BITS {}, WEIGHT_BITS {} (CMake ZBLEND_RTL_ACC_BITS, "
        "_REV_BITS, _WEIGHT_BITS)",
        wboit.acc_bits, wboit.rev_bits, wboit.weight_bits, kRtlWboit.acc_bits,
        kRtlWboit.rev_bits, kRtlWboit.weight_bits));
  if (coverage_samples != kRtlCoverageSamples)
    throw std::invalid_argument("rtl backend: coverage samples " +
                                std::to_string(coverage_samples) + ", the Verilated zb_rop has " +
                                std::to_string(kRtlCoverageSamples));
  if (depth_bits != kRtlDepthBits)
    throw std::invalid_argument("rtl backend: depth bits " + std::to_string(depth_bits) +
                                ", the Verilated zb_rop has " + std::to_string(kRtlDepthBits));
  if (width < 1 || height < 1 || width > 65535 || height > 65535)
    throw std::invalid_argument("rtl backend: frame size " + std::to_string(width) + "x" +
                                std::to_string(height) + " outside 1..65535");
  impl_->fb = Framebuffer(width, height, depth_bits, clear_color, coverage_samples, wboit);
  impl_->tiles = TileStates(width, height, kRtlTileW, depth_bits, clear_color, wboit);
  impl_->in_pass = false;
}

void RtlRop::begin_pass(const RopState& state) {
  if (impl_->fb.width == 0) throw std::logic_error("rtl backend: begin_pass before begin_frame");
  impl_->state = state;
  impl_->frags.clear();
  impl_->in_pass = true;
}

void RtlRop::draw(const Fragment* fragments, size_t count) {
  Impl& m = *impl_;
  if (!m.in_pass) throw std::logic_error("rtl backend: draw outside a pass");
  for (size_t i = 0; i < count; ++i)
    if (fragments[i].x >= m.fb.width || fragments[i].y >= m.fb.height)
      throw std::invalid_argument("rtl backend: fragment (" + std::to_string(fragments[i].x) +
                                  "," + std::to_string(fragments[i].y) + ") outside the frame");
  for (size_t i = 0; i < count; ++i)
    if (fragments[i].coverage > kRtlCoverageSamples)
      throw std::invalid_argument("rtl backend: fragment coverage " +
                                  std::to_string(fragments[i].coverage) + " exceeds " +
                                  std::to_string(kRtlCoverageSamples) + " samples");
  m.frags.insert(m.frags.end(), fragments, fragments + count);
}

PassStats RtlRop::end_pass() {
  Impl& m = *impl_;
  if (!m.in_pass) throw std::logic_error("rtl backend: end_pass outside a pass");
  m.in_pass = false;
  m.bin();
  m.accepted.assign(m.frags.size(), 0);
  std::vector<size_t> touched;  // tiles with fragments, in tile order
  std::vector<TileIo> ios;
  for (size_t tile = 0; tile + 1 < m.tile_first.size(); ++tile) {
    if (m.tile_first[tile] == m.tile_first[tile + 1]) continue;
    touched.push_back(tile);
    ios.push_back(m.tiles.plan(tile, m.state));
  }
  m.runs.assign(touched.size(), TileRun{});
  std::vector<PassStats> tile_stats(touched.size());
  const int tx = m.tiles_x();
  auto run = [&](Sim& s, size_t j) {
    const size_t tile = touched[j];
    s.wave.pass_no = uint32_t(m.pass_no);
    const uint32_t b = m.tile_first[tile], e = m.tile_first[tile + 1];
    return m.run_tile(s, m.fb, m.fb, int(tile % tx) * kRtlTileW, int(tile / tx) * kRtlTileH,
                      ios[j], m.binned.data() + b, e - b, m.tile_seed(m.pass_no, tile),
                      m.accepted.data(), m.runs[j], tile_stats[j]);
  };
  prepare_stores(m.fb, m.state);  // here, not in a tile's store: the tiles run concurrently
  // Each model takes the next tile; the tiles touch disjoint pixels of fb and of accepted.
  // One model runs on this thread, in tile order. A stop (the retire sink's) lets the running
  // tiles finish, so the tiles that ran are the first `ran`, whole.
  const int n = int(std::min<size_t>(size_t(m.models()), touched.size()));
  while (m.helpers.size() + 1 < size_t(n))
    m.helpers.push_back(std::make_unique<Sim>(std::string(), m.opt, m.opt.coverage));
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false}, stopped{false};
  run_workers(n, [&](int w) {
    Sim& s = w == 0 ? m.sim : *m.helpers[size_t(w - 1)];
    use_context(s.ctx.get());
    try {
      for (size_t j; !failed && !stopped && (j = next++) < touched.size();)
        if (!run(s, j)) stopped = true;
    } catch (...) {
      failed = true;
      throw;
    }
  });
  use_context(m.sim.ctx.get());
  const size_t ran = std::min(next.load(), touched.size());
  m.runs.resize(ran);
  // One model's cycles: the tiles back to back in tile order, from where the last pass ended.
  PassStats stats;
  for (size_t j = 0; j < ran; ++j) {
    TileRun& r = m.runs[j];
    const uint64_t from = r.load_begin;
    auto rebase = [&](uint64_t c) { return c - from + m.cycles; };
    for (uint32_t k = m.tile_first[touched[j]]; k < m.tile_first[touched[j] + 1]; ++k)
      m.accepted[m.binned[k].index] = rebase(m.accepted[m.binned[k].index]);
    r.load_begin = rebase(r.load_begin);
    r.stream_begin = rebase(r.stream_begin);
    r.stream_end = rebase(r.stream_end);
    r.store_end = rebase(r.store_end);
    m.cycles = r.store_end;
    stats += tile_stats[j];
    m.tiles.stored(touched[j], ios[j].store);
    m.io_cycles += (r.stream_begin - r.load_begin) + (r.store_end - r.stream_end);
    m.stalls += r.stall_cycles;
  }
  ++m.pass_no;
  if (stopped) throw RtlStopped();
  return stats;
}

// The host's frame operation on the driver's frame copy; the next pass loads it into the
// tile memory (colour, depth, coverage, peel and accumulation planes).
void RtlRop::frame_op(const FrameOp& op) {
  if (impl_->fb.width == 0) throw std::logic_error("rtl backend: frame_op before begin_frame");
  if (impl_->in_pass) throw std::logic_error("rtl backend: frame_op inside a pass");
  apply_frame_op(impl_->fb, op);
  impl_->tiles.frame_op(op);
}

const Framebuffer& RtlRop::framebuffer() const { return impl_->fb; }
uint64_t RtlRop::tile_io_cycles() const { return impl_->io_cycles; }
uint64_t RtlRop::total_cycles() const { return impl_->cycles; }
uint64_t RtlRop::stall_cycles() const { return impl_->stalls; }
const std::vector<Fragment>& RtlRop::pass_fragments() const { return impl_->frags; }
const std::vector<uint64_t>& RtlRop::accept_cycles() const { return impl_->accepted; }
const std::vector<TileRun>& RtlRop::tile_runs() const { return impl_->runs; }
uint64_t RtlRop::pass_number() const { return impl_->pass_no == 0 ? 0 : impl_->pass_no - 1; }

void RtlRop::mark_waves(const WaveView& view) { impl_->sim.view = view; }

Framebuffer RtlRop::replay_tile(const Framebuffer& before, int x0, int y0,
                                const std::string& fst_path, uint64_t from, uint64_t to,
                                const WaveView& view) const {
  const Impl& m = *impl_;
  const TileRun* found = nullptr;
  for (const TileRun& r : m.runs)
    if (r.x0 == x0 && r.y0 == y0) found = &r;
  if (!found) throw std::invalid_argument("rtl replay: the last pass did not touch that tile");
  const size_t tile = size_t(y0 / kRtlTileH) * m.tiles_x() + x0 / kRtlTileW;
  Framebuffer out = before;
  prepare_stores(out, m.state);
  // The replay's context goes away with it: give the thread back the main model's context.
  struct RestoreContext {
    VerilatedContext* ctx;
    ~RestoreContext() { use_context(ctx); }
  } restore{m.sim.ctx.get()};
  // The run already judged these writes: the replay's monitor only names them in the probe,
  // with the golden writes the run's sink holds.
  struct Shows final : RetireSink {
    const RetireSink* run = nullptr;
    bool retire(const Retire&) override { return true; }
    bool store(const StoreBeat&) override { return true; }
    const PixelWrites* expected(uint32_t f) const override {
      return run ? run->expected(f) : nullptr;
    }
  } shows;
  shows.run = m.opt.retire_sink;
  RtlOptions quiet = m.opt;
  quiet.retire_sink = &shows;
  quiet.check_timing = false;  // the waveform is wanted whatever the timing
  Sim sim(fst_path, quiet, nullptr, from, to);
  sim.view = view;
  sim.wave.pass_no = uint32_t(m.pass_no - 1);
  // Same cycle numbers as the original run, so the waveform's times match the report.
  sim.cycle = found->load_begin;
  std::vector<uint64_t> accepted(m.frags.size(), 0);
  TileRun run;
  PassStats stats;
  m.run_tile(sim, before, out, x0, y0, found->io, m.binned.data() + m.tile_first[tile],
             m.tile_first[tile + 1] - m.tile_first[tile], m.tile_seed(m.pass_no - 1, tile),
             accepted.data(), run, stats);
  return out;
}

}  // namespace zb
