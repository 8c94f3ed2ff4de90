#include "rtl_rop.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>

#include "driver_checks.h"
#include "parallel/parallel.h"
#include "rop_model.h"
#include "tile_driver.h"

namespace zb {

struct RtlRop::Impl {
  // A pass of the group: its state and its fragments, frags[base, base + n), binned by tile
  // (Streamed::index counts from the group's first fragment).
  struct Pass {
    RopState state;
    size_t base = 0, n = 0;
    uint64_t number = 0;              // passes since construction
    std::vector<uint32_t> tile_first; // per tile, start in `binned`; one extra at the end
    std::vector<Streamed> binned;
  };
  // A tile's run: which passes touch it (indices in `group`), what runs before each, the store.
  struct Plan {
    size_t tile = 0;
    std::vector<size_t> passes;
    TileStates::RunPlan run;
  };

  RtlOptions opt;
  Sim sim;
  std::vector<std::unique_ptr<Sim>> helpers;  // the other models of a tile-parallel run
  Framebuffer fb;
  std::vector<Pass> group;          // the passes run together (one pass under kPass)
  // The group's passes and the frame operations run on its resident tiles, in order; the
  // frame's tile states at its start (a resolve, last, closes it: TileStates::closed).
  std::vector<TileStates::GroupStep> steps;
  TileStates group_start;
  // The frame at the group's start, kept once an operation joins the group (the host applies
  // it to `fb` at once): the group's loads read it, its stores write `fb`.
  std::unique_ptr<Framebuffer> start_fb;
  bool ran = false;                 // the group has run (its records stay for reports)
  std::vector<Fragment> frags;      // the group's fragments, pass after pass
  std::vector<uint64_t> accepted;   // accept cycle per fragment
  std::vector<TileRun> runs;        // the group's, one a tile
  std::vector<Plan> plans;          // beside runs
  std::vector<PassStats> frame_stats;  // the frame's passes so far
  TileStates tiles;                 // the frame's planes per tile: cleared or stored
  uint64_t pass_no = 0;
  bool in_pass = false;
  bool deferred = false;            // under kPass, a layers pass waited for its resolve
  uint64_t io_cycles = 0, stalls = 0;
  uint64_t cycles = 0;              // one model's cycles since reset: reset, sweep, every tile

  explicit Impl(RtlOptions o)
      : opt(std::move(o)), sim(opt.trace_path, opt, opt.coverage), cycles(sim.cycle) {}

  int models() const { return opt.trace_path.empty() ? std::max(1, opt.threads) : 1; }
  // The group's layers never leave the tile: it waits for their resolve under either schedule.
  bool layered() const {
    for (const Pass& p : group)
      if (planes_written(p.state) & kPlaneLayers) return true;
    return false;
  }
  int tiles_x() const { return (fb.width + kRtlTileW - 1) / kRtlTileW; }
  bool pending() const { return !ran && !group.empty(); }

  TileJob job(const Plan& plan, const Framebuffer& src, Framebuffer& dst,
              uint64_t* accept_out) const {
    TileJob j;
    j.x0 = int(plan.tile % size_t(tiles_x())) * kRtlTileW;
    j.y0 = int(plan.tile / size_t(tiles_x())) * kRtlTileH;
    for (size_t k = 0; k < plan.passes.size(); ++k) {
      const Pass& p = group[plan.passes[k]];
      const TileStates::RunPlan::Step& rs = plan.run.steps[k];
      TileStep st;
      st.state = pack_state(p.state);
      st.io = rs.io;
      st.preload = rs.preload;
      st.copy = rs.copy;
      st.sweep = rs.sweep;
      st.swap = rs.swap;
      st.stream = p.binned.data() + p.tile_first[plan.tile];
      st.n = p.tile_first[plan.tile + 1] - p.tile_first[plan.tile];
      st.seed = tile_seed(opt.seed, p.number, plan.tile);
      j.steps.push_back(st);
    }
    j.store = plan.run.store;
    j.preload_after = plan.run.preload_after;
    j.copy_after = plan.run.copy_after;
    j.sweep_after = plan.run.sweep_reads();
    j.swap_after = plan.run.swap_after;
    j.swap_after_depth = plan.run.swap_after_depth;
    j.clear_after = plan.run.clear_after;
    j.resolve = plan.run.resolve;
    if (j.resolve == StoreResolve::kUnder) j.background = pack_rgba(steps.back().op.value);
    j.src = &src;
    j.dst = &dst;
    j.pass = frags.data();
    j.accepted = accept_out;
    j.backpressure = opt.backpressure;
    j.check_timing = opt.check_timing;
    j.reread_stores = opt.reread_stores;
    return j;
  }

  void plan_group();
  size_t run_tiles(std::vector<TileResult>& out, bool& stopped);
  std::vector<PassStats> rebase(const std::vector<TileResult>& out, size_t ran);
  std::vector<PassStats> run_group();
};

// The group's touched tiles in tile order, each with the passes that touch it and what runs on
// the resident tile (TileStates::plan_tile, from the frame's tile states at the group's start).
void RtlRop::Impl::plan_group() {
  plans.clear();
  const size_t ntiles = group.front().tile_first.size() - 1;
  for (size_t t = 0; t < ntiles; ++t) {
    Plan plan;
    plan.tile = t;
    size_t k = 0;
    for (TileStates::GroupStep& st : steps) {
      if (!st.pass) continue;
      st.touches = group[k].tile_first[t] != group[k].tile_first[t + 1];
      if (st.touches) plan.passes.push_back(k);
      ++k;
    }
    if (plan.passes.empty()) continue;
    plan.run = group_start.plan_tile(t, steps.data(), steps.size());
    plans.push_back(std::move(plan));
  }
}

// Each model takes the next tile; the tiles touch disjoint pixels of fb and of accepted. One
// model runs on this thread, in tile order. A stop (the retire sink's) lets the running tiles
// finish, so the tiles that ran are the first ones, whole. Returns how many ran.
size_t RtlRop::Impl::run_tiles(std::vector<TileResult>& out, bool& stopped) {
  const int n = int(std::min<size_t>(size_t(models()), plans.size()));
  while (helpers.size() + 1 < size_t(n))
    helpers.push_back(std::make_unique<Sim>(std::string(), opt, opt.coverage));
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false}, stop{false};
  run_workers(n, [&](int w) {
    Sim& s = w == 0 ? sim : *helpers[size_t(w - 1)];
    use_context(s.ctx.get());
    s.wave.pass_no = uint32_t(group.back().number);
    try {
      for (size_t j; !failed && !stop && (j = next++) < plans.size();) {
        out[j] = run_tile(s, job(plans[j], start_fb ? *start_fb : fb, fb, accepted.data()));
        if (!out[j].go) stop = true;
      }
    } catch (...) {
      failed = true;
      throw;
    }
  });
  use_context(sim.ctx.get());
  stopped = stop;
  return std::min(next.load(), plans.size());
}

// One model's cycles: the tiles back to back in tile order, from where the last group ended.
// Returns each pass's counters summed over its tiles.
std::vector<PassStats> RtlRop::Impl::rebase(const std::vector<TileResult>& out, size_t ran) {
  std::vector<PassStats> stats(group.size());
  runs.resize(ran);
  for (size_t j = 0; j < ran; ++j) {
    TileRun& r = runs[j] = out[j].run;
    const Plan& plan = plans[j];
    const uint64_t from = r.load_begin;
    auto at = [&](uint64_t c) { return c - from + cycles; };
    for (const size_t k : plan.passes) {
      const Pass& p = group[k];
      for (uint32_t i = p.tile_first[plan.tile]; i < p.tile_first[plan.tile + 1]; ++i)
        accepted[p.binned[i].index] = at(accepted[p.binned[i].index]);
    }
    for (size_t k = 0; k < plan.passes.size(); ++k) stats[plan.passes[k]] += out[j].stats[k];
    r.load_begin = at(r.load_begin);
    r.stream_begin = at(r.stream_begin);
    r.stream_end = at(r.stream_end);
    r.store_end = at(r.store_end);
    cycles = r.store_end;
    tiles.stored(plan.tile, plan.run.store);
    io_cycles += (r.store_end - r.load_begin) - r.stream_cycles;
    stalls += r.stall_cycles;
  }
  return stats;
}

std::vector<PassStats> RtlRop::Impl::run_group() {
  if (!pending()) return {};
  if (layered() && !(TileStates::closed(steps) &&
                     steps.back().op.kind == FrameOpKind::kResolveLayers))
    fail<std::invalid_argument>(
        "rtl backend: a layers pass's layers are not resolved (they never leave the tile: "
        "resolve-layers must follow the pass before the next resolve or the frame's end)");
  ran = true;
  accepted.assign(frags.size(), 0);
  plan_group();
  std::vector<TileResult> out(plans.size());
  for (const Pass& p : group) prepare_stores(fb, p.state);  // not in a tile: they run at once
  bool stopped = false;
  const size_t done = run_tiles(out, stopped);
  std::vector<PassStats> stats = rebase(out, done);
  start_fb.reset();
  if (stopped) throw RtlStopped();
  frame_stats.insert(frame_stats.end(), stats.begin(), stats.end());
  return stats;
}

const char* RtlRop::build() {
#if defined(ZB_RTL_FAST)
  return "speed build, no assertions";
#elif defined(ZB_RTL_MUT)
  return "mutant netlist, no assertions";
#elif defined(ZB_RTL_BUG)
  return "assertion build with injected defects";
#elif defined(ZB_RTL_FCOV)
  return "assertion build counting the coverage plan's bins";
#else
  return "assertion build";
#endif
}

int RtlRop::model_layers() {
#if defined(ZB_RTL_MUT) && !defined(ZB_RTL_MUT_LAYERS)
  return 0;  // the mutant netlist is of zb_rop without the layers unit (tb/mutation)
#else
  return kRtlLayers;
#endif
}

RtlRop::RtlRop(RtlOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
RtlRop::~RtlRop() = default;

void RtlRop::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                         int coverage_samples, const WboitFormat& wboit) {
  using E = std::invalid_argument;
  if (wboit != kRtlWboit)
    fail<E>("rtl backend: accumulation {} bits, revealage {} bits, weight {} bits; the Verilated "
            "zb_rop has ACC_BITS {}, REV_BITS {}, WEIGHT_BITS {} (CMake ZBLEND_RTL_ACC_BITS, "
            "_REV_BITS, _WEIGHT_BITS)",
            wboit.acc_bits, wboit.rev_bits, wboit.weight_bits, kRtlWboit.acc_bits,
            kRtlWboit.rev_bits, kRtlWboit.weight_bits);
  if (coverage_samples != kRtlCoverageSamples)
    fail<E>("rtl backend: coverage samples {}, the Verilated zb_rop has {}", coverage_samples,
            kRtlCoverageSamples);
  if (depth_bits != kRtlDepthBits)
    fail<E>("rtl backend: depth bits {}, the Verilated zb_rop has {}", depth_bits, kRtlDepthBits);
  if (width < 1 || height < 1 || width > 65535 || height > 65535)
    fail<E>("rtl backend: frame size {}x{} outside 1..65535", width, height);
  if (impl_->pending())
    fail<std::logic_error>("rtl backend: begin_frame with the last frame's passes not yet run "
                           "(finish_frame)");
  impl_->fb = Framebuffer(width, height, depth_bits, clear_color, coverage_samples, wboit);
  impl_->tiles = TileStates(width, height, kRtlTileW, depth_bits, clear_color, wboit);
  impl_->in_pass = false;
  impl_->group.clear();
  impl_->steps.clear();
  impl_->frags.clear();
  impl_->frame_stats.clear();
  impl_->deferred = false;
}

void RtlRop::begin_pass(const RopState& state) {
  Impl& m = *impl_;
  if (m.fb.width == 0) fail<std::logic_error>("rtl backend: begin_pass before begin_frame");
  const int layers = model_layers();
  if (state.blend == BlendMode::kLayers && (state.layers < 1 || state.layers > layers))
    fail<std::invalid_argument>(
        "rtl backend: a layers pass of {} layers a pixel; the Verilated zb_rop keeps {} "
        "(LAYERS: CMake ZBLEND_RTL_LAYERS)",
        int(state.layers), layers);
  if (m.pending() && TileStates::closed(m.steps)) m.run_group();
  if (m.ran || m.group.empty()) {  // a new group: the last one's records go
    m.group.clear();
    m.steps.clear();
    m.frags.clear();
    m.ran = false;
    m.group_start = m.tiles;
    m.start_fb.reset();
  }
  m.steps.push_back(TileStates::GroupStep{true, false, state, FrameOp{}});
  Impl::Pass p;
  p.state = state;
  p.base = m.frags.size();
  p.number = m.pass_no++;
  m.group.push_back(std::move(p));
  m.in_pass = true;
}

void RtlRop::draw(const Fragment* fragments, size_t count) {
  Impl& m = *impl_;
  if (!m.in_pass) fail<std::logic_error>("rtl backend: draw outside a pass");
  for (size_t i = 0; i < count; ++i)
    if (fragments[i].x >= m.fb.width || fragments[i].y >= m.fb.height)
      fail<std::invalid_argument>("rtl backend: fragment ({},{}) outside the frame",
                                  fragments[i].x, fragments[i].y);
  for (size_t i = 0; i < count; ++i)
    if (fragments[i].coverage > kRtlCoverageSamples)
      fail<std::invalid_argument>("rtl backend: fragment coverage {} exceeds {} samples",
                                  fragments[i].coverage, kRtlCoverageSamples);
  m.frags.insert(m.frags.end(), fragments, fragments + count);
}

// Under kTile the pass waits for the group's end (a host frame operation, finish_frame); its
// counters come then, and this returns zeros.
PassStats RtlRop::end_pass() {
  Impl& m = *impl_;
  if (!m.in_pass) fail<std::logic_error>("rtl backend: end_pass outside a pass");
  m.in_pass = false;
  Impl::Pass& p = m.group.back();
  p.n = m.frags.size() - p.base;
  stream_by_tile(m.frags.data() + p.base, p.n, m.fb.width, m.fb.height, p.tile_first, p.binned);
  for (Streamed& f : p.binned) f.index += uint32_t(p.base);
  if (m.opt.schedule == TileSchedule::kTile) return PassStats{};
  if (m.layered()) {  // its resolve joins it (frame_op); the counters come at finish_frame
    m.deferred = true;
    return PassStats{};
  }
  return m.run_group().at(0);
}

std::vector<PassStats> RtlRop::flush() {
  if (impl_->in_pass) fail<std::logic_error>("rtl backend: flush inside a pass");
  return impl_->run_group();
}

bool RtlRop::pending() const { return impl_->pending(); }

void RtlRop::finish_frame(std::vector<PassStats>& stats) {
  flush();
  if (impl_->opt.schedule == TileSchedule::kTile || impl_->deferred) stats = impl_->frame_stats;
}

bool RtlRop::on_tile() const {  // every operation, while passes wait
  const Impl& m = *impl_;
  return (m.opt.schedule == TileSchedule::kTile || m.layered()) && m.pending() &&
         !TileStates::closed(m.steps);
}

// On the resident tiles (on_tile), the operation joins the group: a clear and a copy run there
// before the next pass, a resolve on the group's store, which it closes. The host applies it to
// its frame copy as well: there it stands where the group's stores do not write (tiles no pass
// of the group touches, planes the group does not make). Otherwise the passes waiting run
// first and the host applies it; the next pass loads what it needs from the host's frame.
void RtlRop::frame_op(const FrameOp& op) {
  Impl& m = *impl_;
  if (m.fb.width == 0) fail<std::logic_error>("rtl backend: frame_op before begin_frame");
  if (m.in_pass) fail<std::logic_error>("rtl backend: frame_op inside a pass");
  if (on_tile()) {
    if (!m.start_fb) m.start_fb = std::make_unique<Framebuffer>(m.fb);
    m.steps.push_back(TileStates::GroupStep{false, false, RopState{}, op});
  } else {
    flush();
  }
  apply_frame_op(m.fb, op);
  m.tiles.frame_op(op);
}

// The passes waiting run first (their stores would write over the region); the host's frame
// takes the region, and the tiles it covers load those planes from there at their next pass.
void RtlRop::load_region(const RegionLoad& r) {
  Impl& m = *impl_;
  if (m.fb.width == 0) fail<std::logic_error>("rtl backend: load_region before begin_frame");
  if (m.in_pass) fail<std::logic_error>("rtl backend: load_region inside a pass");
  if (m.pending() && m.layered())
    fail<std::logic_error>("rtl backend: load_region while layers passes wait for their resolve");
  check_region_load(m.fb, r);  // refused before the waiting passes run
  flush();
  apply_region_load(m.fb, r);
  m.tiles.loaded(r);
}

const Framebuffer& RtlRop::framebuffer() const {
  if (impl_->pending())
    fail<std::logic_error>("rtl backend: the frame read with passes not yet run (finish_frame)");
  return impl_->fb;
}
uint64_t RtlRop::tile_io_cycles() const { return impl_->io_cycles; }
uint64_t RtlRop::total_cycles() const { return impl_->cycles; }
uint64_t RtlRop::stall_cycles() const { return impl_->stalls; }
const std::vector<Fragment>& RtlRop::pass_fragments() const { return impl_->frags; }
const std::vector<uint64_t>& RtlRop::accept_cycles() const { return impl_->accepted; }
const std::vector<TileRun>& RtlRop::tile_runs() const { return impl_->runs; }
uint64_t RtlRop::pass_number() const { return impl_->pass_no == 0 ? 0 : impl_->pass_no - 1; }
size_t RtlRop::group_passes() const { return impl_->group.size(); }
size_t RtlRop::pass_of(uint32_t fragment) const {
  const auto& g = impl_->group;
  size_t k = 0;
  while (k + 1 < g.size() && fragment >= g[k + 1].base) ++k;
  return k;
}

void RtlRop::mark_waves(const WaveView& view) { impl_->sim.view = view; }

namespace {

// A replay's sink: the run already judged these writes, so the replay's monitor only names them
// in the probe, with the golden writes the run's sink holds.
struct Shows final : RetireSink {
  const RetireSink* run = nullptr;
  bool retire(const Retire&) override { return true; }
  bool store(const StoreBeat&) override { return true; }
  const PixelWrites* expected(uint32_t f) const override {
    return run ? run->expected(f) : nullptr;
  }
};

}  // namespace

Framebuffer RtlRop::replay_tile(const Framebuffer& before, int x0, int y0,
                                const std::string& fst_path, uint64_t from, uint64_t to,
                                const WaveView& view) const {
  const Impl& m = *impl_;
  size_t found = m.runs.size();
  for (size_t j = 0; j < m.runs.size(); ++j)
    if (m.runs[j].x0 == x0 && m.runs[j].y0 == y0) found = j;
  if (found == m.runs.size())
    fail<std::invalid_argument>("rtl replay: the last group of passes did not touch that tile");
  Framebuffer out = before;
  for (const Impl::Pass& p : m.group) prepare_stores(out, p.state);
  // The replay's context goes away with it: give the thread back the main model's context.
  struct RestoreContext {
    VerilatedContext* ctx;
    ~RestoreContext() { use_context(ctx); }
  } restore{m.sim.ctx.get()};
  Shows shows;
  shows.run = m.opt.retire_sink;
  RtlOptions quiet = m.opt;
  quiet.retire_sink = &shows;
  quiet.check_timing = false;  // the waveform is wanted whatever the timing
  Sim sim(fst_path, quiet, nullptr, from, to);
  sim.view = view;
  sim.wave.pass_no = uint32_t(m.group.back().number);
  // Same cycle numbers as the original run, so the waveform's times match the report.
  sim.cycle = m.runs[found].load_begin;
  std::vector<uint64_t> accepted(m.frags.size(), 0);
  run_tile(sim, m.job(m.plans[found], before, out, accepted.data()));
  return out;
}

}  // namespace zb
