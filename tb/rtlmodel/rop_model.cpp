#include "rop_model.h"

#include <cstdio>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#if defined(VM_COVERAGE) && VM_COVERAGE
#include <verilated_cov.h>

#include "code_coverage.h"
#endif

#include "port_lanes.h"

namespace zb {

static_assert(VParams::TILE_W == kRtlTileW, "tb mirror of TILE_W disagrees with the RTL");
static_assert(VParams::TILE_H == kRtlTileH, "tb mirror of TILE_H disagrees with the RTL");
static_assert(VParams::DEPTH_BITS == kRtlDepthBits, "tb mirror of DEPTH_BITS disagrees");
static_assert(VParams::COV_SAMPLES == kRtlCoverageSamples, "tb mirror of COV_SAMPLES disagrees");
static_assert(VParams::CNT_W == 32, "the driver reads 32-bit counters");
static_assert(VParams::BEAT == kRtlBeat, "tb mirror of BEAT disagrees with the RTL");
static_assert(VParams::DEPTH_GEN == kRtlDepthGenBits, "tb mirror of DEPTH_GEN disagrees");
static_assert(VParams::ACC_BITS == kRtlWboit.acc_bits, "tb mirror of ACC_BITS disagrees");
static_assert(VParams::REV_BITS == kRtlWboit.rev_bits, "tb mirror of REV_BITS disagrees");
static_assert(VParams::WEIGHT_BITS == kRtlWboit.weight_bits, "tb mirror of WEIGHT_BITS disagrees");

namespace {

// Verilator 5.006 keeps the context a thread set last in a plain static pointer
// (Verilated::lastContextp), which a VerilatedContext's constructor, a model's (its symbol
// table's) and every Verilated::threadContextp call write. Models on several threads
// (tile-parallel models, the lab's scenes) are made, unmade and given their contexts under this
// one lock, so they do not race on it.
std::mutex context_mutex;

}  // namespace

void use_context(VerilatedContext* ctx) {
  const std::lock_guard<std::mutex> lock(context_mutex);
  Verilated::threadContextp(ctx);
}

Sim::Sim(const std::string& path, const RtlOptions& o, CoverageTotals* totals, uint64_t from,
         uint64_t to)
    : fst_path(path),
      coverage(totals),
      feed(o.retire_sink, path.empty() ? nullptr : &wave),
      dump_from(from),
      dump_to(to) {
  make(path, o);
  reset();
}

void Sim::make(const std::string& path, const RtlOptions& o) {
  std::unique_lock<std::mutex> lock(context_mutex);
  ctx = std::make_unique<VerilatedContext>();
  // The model's threads: Verilator's default (every core) would start an idle thread pool
  // beside each of the tile-parallel models.
  ctx->threads(kVerilatorThreads);
  std::vector<const char*> argv{"zb_rop"};
  for (const std::string& a : o.plusargs) argv.push_back(a.c_str());
  ctx->commandArgs(int(argv.size()), argv.data());
  ctx->assertOn(o.assertions);
  ctx->fatalOnError(true);
  if (!path.empty()) ctx->traceEverOn(true);  // before the model exists
  top = std::make_unique<VModel>(ctx.get(), "zb_rop");
  if (path.empty()) return;
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  probe = std::make_unique<VProbe>(ctx.get(), "tb");
  lock.unlock();
  fst = std::make_unique<VerilatedFstC>();
  top->trace(fst.get(), 99);
  probe->trace(fst.get(), 99);
}

void Sim::reset() {
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

Sim::~Sim() {
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

// The context's coverage points die with the model: their counts go to the run's totals now.
void Sim::add_coverage() noexcept {
#if defined(VM_COVERAGE) && VM_COVERAGE
  if (!coverage) return;
  try {
#ifdef ZB_RTL_FCOV
    // Per instance: Verilator otherwise sums a generate loop's covers (the coverage plan's
    // crosses, tb/cov/) into one point.
    ctx->coveragep()->forcePerInstance(true);
#endif
    ctx->coveragep()->write(coverage->scratch_path().c_str());
    coverage->add_file(coverage->scratch_path());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "zblend_tb: %s\n", e.what());
  }
#endif
}

void Sim::idle_inputs() {
  top->state_we_i = 0;
  top->frag_valid_i = 0;
  top->stall_i = 0;
  top->tile_req_i = 0;
  top->tile_we_i = 0;
  top->tile_clear_i = 0;
  top->tile_planes_i = 0;
  top->tile_mlab_i = 0;
  top->cnt_clear_i = 0;
}

void Sim::begin_dump() {
  if (!fst->isOpen()) {
    fst->open(fst_path.c_str());
    if (!fst->isOpen()) fail("cannot write waveform {}", fst_path);
  }
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
  p.x11_golden_lwe = wave.x11_lwe;
  for (int i = 0; i < 16; ++i) p.x11_golden_layers[i] = 0;  // 512 bits
  {
    lanes::Writer layers(p.x11_golden_layers);
    lanes::put_layers(layers, wave.x11_layers);
  }
  p.mismatch = wave.mismatch || cycle == view.mismatch;
  p.eval();
}

}  // namespace zb
