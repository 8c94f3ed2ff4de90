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

  // Tile `tile` of pass `pass`, loaded from `src` and stored to `dst`.
  TileJob job(size_t tile, uint64_t pass, const TileIo& io, const Framebuffer& src,
              Framebuffer& dst, uint64_t* accept_out) const {
    TileJob j;
    j.x0 = int(tile % size_t(tiles_x())) * kRtlTileW;
    j.y0 = int(tile / size_t(tiles_x())) * kRtlTileH;
    j.io = io;
    j.state = pack_state(state);
    j.src = &src;
    j.dst = &dst;
    j.stream = binned.data() + tile_first[tile];
    j.n = tile_first[tile + 1] - tile_first[tile];
    j.pass = frags.data();
    j.accepted = accept_out;
    j.seed = tile_seed(opt.seed, pass, tile);
    j.backpressure = opt.backpressure;
    j.check_timing = opt.check_timing;
    j.reread_stores = opt.reread_stores;
    return j;
  }

  size_t run_tiles(const std::vector<size_t>& touched, const std::vector<TileIo>& ios,
                   std::vector<TileResult>& out, bool& stopped);
  PassStats rebase(const std::vector<size_t>& touched, const std::vector<TileIo>& ios,
                   const std::vector<TileResult>& out, size_t ran);
};

// Each model takes the next tile; the tiles touch disjoint pixels of fb and of accepted. One
// model runs on this thread, in tile order. A stop (the retire sink's) lets the running tiles
// finish, so the tiles that ran are the first ones, whole. Returns how many ran.
size_t RtlRop::Impl::run_tiles(const std::vector<size_t>& touched, const std::vector<TileIo>& ios,
                               std::vector<TileResult>& out, bool& stopped) {
  const int n = int(std::min<size_t>(size_t(models()), touched.size()));
  while (helpers.size() + 1 < size_t(n))
    helpers.push_back(std::make_unique<Sim>(std::string(), opt, opt.coverage));
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false}, stop{false};
  run_workers(n, [&](int w) {
    Sim& s = w == 0 ? sim : *helpers[size_t(w - 1)];
    use_context(s.ctx.get());
    s.wave.pass_no = uint32_t(pass_no);
    try {
      for (size_t j; !failed && !stop && (j = next++) < touched.size();) {
        out[j] = run_tile(s, job(touched[j], pass_no, ios[j], fb, fb, accepted.data()));
        if (!out[j].go) stop = true;
      }
    } catch (...) {
      failed = true;
      throw;
    }
  });
  use_context(sim.ctx.get());
  stopped = stop;
  return std::min(next.load(), touched.size());
}

// One model's cycles: the tiles back to back in tile order, from where the last pass ended.
PassStats RtlRop::Impl::rebase(const std::vector<size_t>& touched,
                               const std::vector<TileIo>& ios,
                               const std::vector<TileResult>& out, size_t ran) {
  PassStats stats;
  runs.resize(ran);
  for (size_t j = 0; j < ran; ++j) {
    TileRun& r = runs[j] = out[j].run;
    const uint64_t from = r.load_begin;
    auto at = [&](uint64_t c) { return c - from + cycles; };
    for (uint32_t k = tile_first[touched[j]]; k < tile_first[touched[j] + 1]; ++k)
      accepted[binned[k].index] = at(accepted[binned[k].index]);
    r.load_begin = at(r.load_begin);
    r.stream_begin = at(r.stream_begin);
    r.stream_end = at(r.stream_end);
    r.store_end = at(r.store_end);
    cycles = r.store_end;
    stats += out[j].stats;
    tiles.stored(touched[j], ios[j].store);
    io_cycles += (r.stream_begin - r.load_begin) + (r.store_end - r.stream_end);
    stalls += r.stall_cycles;
  }
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
  impl_->fb = Framebuffer(width, height, depth_bits, clear_color, coverage_samples, wboit);
  impl_->tiles = TileStates(width, height, kRtlTileW, depth_bits, clear_color, wboit);
  impl_->in_pass = false;
}

void RtlRop::begin_pass(const RopState& state) {
  if (impl_->fb.width == 0) fail<std::logic_error>("rtl backend: begin_pass before begin_frame");
  impl_->state = state;
  impl_->frags.clear();
  impl_->in_pass = true;
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

PassStats RtlRop::end_pass() {
  Impl& m = *impl_;
  if (!m.in_pass) fail<std::logic_error>("rtl backend: end_pass outside a pass");
  m.in_pass = false;
  stream_by_tile(m.frags.data(), m.frags.size(), m.fb.width, m.fb.height, m.tile_first, m.binned);
  m.accepted.assign(m.frags.size(), 0);
  std::vector<size_t> touched;  // tiles with fragments, in tile order
  std::vector<TileIo> ios;
  for (size_t tile = 0; tile + 1 < m.tile_first.size(); ++tile) {
    if (m.tile_first[tile] == m.tile_first[tile + 1]) continue;
    touched.push_back(tile);
    ios.push_back(m.tiles.plan(tile, m.state));
  }
  std::vector<TileResult> out(touched.size());
  prepare_stores(m.fb, m.state);  // here, not in a tile's store: the tiles run concurrently
  bool stopped = false;
  const size_t ran = m.run_tiles(touched, ios, out, stopped);
  const PassStats stats = m.rebase(touched, ios, out, ran);
  ++m.pass_no;
  if (stopped) throw RtlStopped();
  return stats;
}

// The host's frame operation on the driver's frame copy; the next pass loads it into the
// tile memory (colour, depth, coverage, peel and accumulation planes).
void RtlRop::frame_op(const FrameOp& op) {
  if (impl_->fb.width == 0) fail<std::logic_error>("rtl backend: frame_op before begin_frame");
  if (impl_->in_pass) fail<std::logic_error>("rtl backend: frame_op inside a pass");
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
  const TileRun* found = nullptr;
  for (const TileRun& r : m.runs)
    if (r.x0 == x0 && r.y0 == y0) found = &r;
  if (!found) fail<std::invalid_argument>("rtl replay: the last pass did not touch that tile");
  const size_t tile = size_t(y0 / kRtlTileH) * m.tiles_x() + x0 / kRtlTileW;
  Framebuffer out = before;
  prepare_stores(out, m.state);
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
  sim.wave.pass_no = uint32_t(m.pass_no - 1);
  // Same cycle numbers as the original run, so the waveform's times match the report.
  sim.cycle = found->load_begin;
  std::vector<uint64_t> accepted(m.frags.size(), 0);
  run_tile(sim, m.job(tile, m.pass_no - 1, found->io, before, out, accepted.data()));
  return out;
}

}  // namespace zb
