#include "sizing_cost.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include "metrics/scene_analysis.h"

namespace zb {

const TileCost& MethodCost::at(int tile) const {
  for (const TileCost& t : tiles)
    if (t.tile == tile) return t;
  throw std::invalid_argument("cost model: no tile size " + std::to_string(tile));
}

std::vector<int> cost_tile_sizes() {
  std::vector<int> sizes(std::begin(kAnalysisTileSizes), std::end(kAnalysisTileSizes));
  if (std::find(sizes.begin(), sizes.end(), kRtlTileW) == sizes.end()) sizes.push_back(kRtlTileW);
  return sizes;
}

uint64_t tile_pixel_bits(int depth_bits, int coverage_samples, const WboitFormat& wboit) {
  return 32u + 2u * uint64_t(depth_bits) + uint64_t(coverage_bits(coverage_samples)) +
         uint64_t(accum_word_bits(wboit));
}

namespace {

// Bits the tile port moves for `pixels` per plane, each plane its width.
uint64_t port_bits(const std::array<uint64_t, kTilePlanes>& pixels, int depth_bits,
                   int coverage_samples, const WboitFormat& wboit) {
  const std::array<uint64_t, kTilePlanes> bits{32, uint64_t(depth_bits),
                                               uint64_t(coverage_bits(coverage_samples)),
                                               uint64_t(depth_bits),
                                               uint64_t(accum_word_bits(wboit))};
  uint64_t io = 0;
  for (size_t p = 0; p < bits.size(); ++p) io += pixels[p] * bits[p];
  return io;
}

}  // namespace

uint64_t MethodCost::traffic_bytes(int tile, int depth_bits, int coverage_samples) const {
  const uint64_t word = uint64_t(accum_word_bits(wboit));
  const uint64_t io = port_bits(at(tile).plane_pixels, depth_bits, coverage_samples, wboit);
  const uint64_t access = 32 * (totals.color_reads + totals.color_writes - accum_accesses) +
                          word * accum_accesses +
                          uint64_t(depth_bits) * (totals.depth_reads + totals.depth_writes);
  return (io + access + 7) / 8;
}

uint64_t TileCost::port_bytes(TileSchedule s, int depth_bits, int coverage_samples,
                              const WboitFormat& wboit) const {
  const auto& pixels = s == TileSchedule::kTile ? resident.plane_pixels : plane_pixels;
  return (port_bits(pixels, depth_bits, coverage_samples, wboit) + 7) / 8;
}

int MethodCost::best_tile(int depth_bits, int coverage_samples) const {
  int best = 0;
  for (const TileCost& t : tiles) {
    if (best == 0) {
      best = t.tile;
      continue;
    }
    const uint64_t c = cycles(t.tile), cb = cycles(best);
    const uint64_t b = traffic_bytes(t.tile, depth_bits, coverage_samples);
    const uint64_t bb = traffic_bytes(best, depth_bits, coverage_samples);
    if (c < cb || (c == cb && (b < bb || (b == bb && t.tile < best)))) best = t.tile;
  }
  return best;
}

void CostCounter::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                              int coverage_samples, const WboitFormat& wboit) {
  inner_.begin_frame(width, height, depth_bits, clear_color, coverage_samples, wboit);
  width_ = width;
  height_ = height;
  cost_ = MethodCost{};
  cost_.wboit = wboit;
  pass_states_.clear();
  group_steps_.clear();
  group_passes_ = 0;
  grids_.clear();
  const std::vector<int> sizes =
      scope_ == CostScope::kLab ? cost_tile_sizes() : std::vector<int>{kRtlTileW};
  for (const int size : sizes) {
    Grid g;
    g.size = size;
    g.columns = (width + size - 1) / size;
    g.stream.assign(size_t(g.columns) * size_t((height + size - 1) / size), {});
    g.states = TileStates(width, height, size, depth_bits, clear_color);
    g.resident_states = g.states;
    g.group_start = g.states;
    grids_.push_back(std::move(g));
    cost_.tiles.push_back(TileCost{});
    cost_.tiles.back().tile = size;
  }
}

void CostCounter::begin_pass(const RopState& state) {
  inner_.begin_pass(state);
  state_ = state;
  if (TileStates::closed(group_steps_)) end_group();
  if (group_passes_ == 0)
    for (Grid& g : grids_) g.group_start = g.resident_states;
  group_steps_.push_back(TileStates::GroupStep{true, false, state, FrameOp{}});
  ++group_passes_;
}

// The driver streams each tile's fragments in pass order (a stable binning).
void CostCounter::draw(const Fragment* fragments, size_t count) {
  inner_.draw(fragments, count);
  // The issue schedule tells pixels apart by key. The lab's two-buffer schedule runs tiles
  // together and needs frame-wide keys; the pass schedule runs a tile at a time, and the
  // tile's own keys keep its tables small.
  const bool frame_keys = scope_ == CostScope::kLab;
  for (Grid& g : grids_)
    for (size_t i = 0; i < count; ++i) {
      const Fragment& f = fragments[i];
      const size_t t = size_t(f.y / g.size) * size_t(g.columns) + size_t(f.x / g.size);
      if (g.stream[t].empty()) g.touched.push_back(uint32_t(t));
      g.stream[t].push_back(frame_keys ? uint32_t(size_t(f.y) * size_t(width_) + size_t(f.x))
                                       : uint32_t(f.y % g.size * g.size + f.x % g.size));
    }
}

// The driver's run of a pass (tb/rtlmodel/tile_driver.cpp): per touched tile, the setup cycle and the
// load beats of its planes (tile_io.h; the whole tile, also where the frame clips it), stream
// through zb_rop's issue window and drain (IssueSchedule), the store beats; and the same tiles
// with a second tile buffer.
PassStats CostCounter::end_pass() {
  const PassStats s = inner_.end_pass();
  pass_states_.push_back(state_);
  cost_.totals += s;
  if (state_.blend == BlendMode::kAccumulate) cost_.accum_accesses += s.color_reads + s.color_writes;
  ++cost_.passes;
  for (size_t k = 0; k < grids_.size(); ++k) {
    Grid& g = grids_[k];
    TileCost& c = cost_.tiles[k];
    // The driver runs the touched tiles in tile order; the two-buffer schedule depends on it.
    std::sort(g.touched.begin(), g.touched.end());
    std::vector<TileStream> overlapped;
    std::vector<uint64_t> streams;
    for (const uint32_t t : g.touched) {
      const int x0 = int(t % uint32_t(g.columns)) * g.size;
      const int y0 = int(t / uint32_t(g.columns)) * g.size;
      const int w = std::min(g.size, width_ - x0), h = std::min(g.size, height_ - y0);
      const uint64_t beats = tile_beats(g.size, g.size, beat_), pixels = uint64_t(w) * uint64_t(h);
      const TileIo io = g.states.plan(t, state_);
      g.states.stored(t, io.store);
      streams.push_back(schedule_.run(g.stream[t].data(), g.stream[t].size()));
      c.stream_cycles += streams.back();
      c.tile_io_cycles += tile_io_cycles(beats, io);
      c.tile_beats += (io.load ? beats : 0) + (io.store ? beats : 0);
      for (int p = 0; p < kTilePlanes; ++p)
        c.plane_pixels[size_t(p)] += pixels * ((io.load >> p & 1) + (io.store >> p & 1));
      overlapped.push_back(TileStream{g.stream[t].data(), g.stream[t].size(),
                                      kRtlTileSetup + (io.load ? beats : 0),
                                      io.store ? beats : 0});
    }
    if (scope_ == CostScope::kLab) {
      const OverlapCycles two = schedule_.run_two_buffers(overlapped);
      c.two_buffer_stream += two.stream;
      c.two_buffer_cycles += two.total;
      for (TileStream& t : overlapped) t.load_cycles = t.store_cycles = 0;
      c.two_buffer_pipe += schedule_.run_two_buffers(overlapped).stream;
    }
    for (const uint32_t t : g.touched) g.stream[t].clear();
    c.tiles_loaded += g.touched.size();
    g.group.push_back(std::move(g.touched));
    g.group_stream.push_back(std::move(streams));
    g.touched.clear();
  }
  return s;
}

// As the RTL driver's tile schedule (tb/rtlmodel/rtl_rop.cpp): per tile the group's passes that
// touch it and the operations on the resident tile (TileStates::plan_tile, from the tile states
// at the group's start): a copy or sweep before a pass, its setup cycle and loads, one store.
void CostCounter::end_group() {
  if (group_passes_ == 0) return;
  // The tile schedule's traffic: the lab's alone (the pass-schedule scope keeps none).
  for (size_t k = 0; k < grids_.size() && scope_ == CostScope::kLab; ++k) {
    Grid& g = grids_[k];
    ResidentTraffic& r = cost_.tiles[k].resident;
    const uint64_t beats = tile_beats(g.size, g.size, beat_);
    std::vector<uint32_t> all;
    for (const auto& p : g.group) all.insert(all.end(), p.begin(), p.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    std::vector<ResidentRun> runs;
    std::array<std::vector<ResidentRun>, kBankVariants.size()> variants;
    std::vector<uint64_t> stream(group_steps_.size());  // per step: tile t's stream cycles
    // A run's cycles: its loads (all ahead with two buffers), its work in the buffer (a copy's
    // or sweep's reads, each pass's setup and stream), its store.
    auto cycles = [&](const TileStates::RunPlan& run) {
      ResidentRun c;
      auto reads = [&](bool copy, bool sweep) { return copy ? beats + kRtlCopyTail : sweep ? beats : 0; };
      for (const TileStates::RunPlan::Step& st : run.steps) {
        c.load += (st.preload ? beats : 0) + (st.io.load ? beats : 0);
        c.work += reads(st.copy, st.sweep) + kRtlTileSetup + stream[st.step];
      }
      c.load += run.preload_after ? beats : 0;
      c.work += reads(run.copy_after, run.sweep_reads());
      c.work += run.closing_setup() ? kRtlTileSetup : 0;
      c.store += run.store ? beats : 0;
      return c;
    };
    for (const uint32_t t : all) {
      size_t pass = 0;
      uint64_t streams = 0;
      for (size_t k = 0; k < group_steps_.size(); ++k) {
        TileStates::GroupStep& st = group_steps_[k];
        if (!st.pass) continue;
        const std::vector<uint32_t>& tiles = g.group[pass];
        const auto it = std::lower_bound(tiles.begin(), tiles.end(), t);
        st.touches = it != tiles.end() && *it == t;
        stream[k] = st.touches ? g.group_stream[pass][size_t(it - tiles.begin())] : 0;
        streams += stream[k];
        ++pass;
      }
      const TileStates::RunPlan run = g.group_start.plan_tile(t, group_steps_.data(), group_steps_.size());
      g.resident_states.stored(t, run.store);
      const int x0 = int(t % uint32_t(g.columns)) * g.size;
      const int y0 = int(t / uint32_t(g.columns)) * g.size;
      const uint64_t pixels = uint64_t(std::min(g.size, width_ - x0)) *
                              uint64_t(std::min(g.size, height_ - y0));
      ++r.tile_runs;
      // A load or the store of these planes through the port: a beat a cycle, every plane's
      // pixels moved.
      auto move = [&](uint8_t planes) {
        if (!planes) return;
        r.beats += beats;
        for (int p = 0; p < kTilePlanes; ++p) r.plane_pixels[size_t(p)] += pixels * (planes >> p & 1);
      };
      for (const TileStates::RunPlan::Step& st : run.steps) {
        move(st.preload);
        move(st.io.load);
      }
      move(run.preload_after);
      move(run.store);
      const ResidentRun c = cycles(run);
      r.io_cycles += c.load + c.work + c.store - streams;
      runs.push_back(c);
      for (size_t v = 0; v < kBankVariants.size(); ++v) {
        const ResidentRun cv = cycles(g.group_start.plan_tile(
            t, group_steps_.data(), group_steps_.size(), kBankVariants[v].banks));
        r.variant_cycles[v] += cv.load + cv.work + cv.store;
        variants[v].push_back(cv);
      }
    }
    r.two_buffer_cycles += two_buffer_group(runs);
    for (size_t v = 0; v < kBankVariants.size(); ++v)
      r.two_buffer_variant_cycles[v] += two_buffer_group(variants[v]);
  }
  for (Grid& g : grids_) {
    g.group.clear();
    g.group_stream.clear();
  }
  group_steps_.clear();
  group_passes_ = 0;
}

// A backend that ran its passes only now (the RTL's tile schedule) gave zeros at end_pass: the
// counters are the frame's final ones.
void CostCounter::finish_frame(std::vector<PassStats>& stats) {
  inner_.finish_frame(stats);
  end_group();
  if (stats.size() != pass_states_.size()) return;
  cost_.totals = PassStats{};
  cost_.accum_accesses = 0;
  for (size_t k = 0; k < stats.size(); ++k) {
    cost_.totals += stats[k];
    if (pass_states_[k].blend == BlendMode::kAccumulate)
      cost_.accum_accesses += stats[k].color_reads + stats[k].color_writes;
  }
}

// Under the tile schedule an operation runs on the resident tiles when passes wait and no
// resolve has closed them (RtlRop::on_tile); else the group ends, and a copy or a resolve
// costs the host a pixel a clock (a clear is a fast clear wherever it is).
void CostCounter::frame_op(const FrameOp& op) {
  inner_.frame_op(op);
  if (group_passes_ > 0 && !TileStates::closed(group_steps_)) {
    group_steps_.push_back(TileStates::GroupStep{false, false, RopState{}, op});
  } else {
    end_group();
    if (op.kind != FrameOpKind::kClearColor && op.kind != FrameOpKind::kClearDepth)
      for (TileCost& c : cost_.tiles) c.resident.host_op_pixels += uint64_t(width_) * uint64_t(height_);
  }
  for (Grid& g : grids_) {
    g.states.frame_op(op);
    g.resident_states.frame_op(op);
  }
  // The layers' resolve runs on the store of their group's tiles under either schedule (they
  // never leave the tile, RtlRop): never on the host.
  if (op.kind == FrameOpKind::kResolveLayers) return;
  ++cost_.frame_ops;
  cost_.frame_op_pixels += uint64_t(width_) * uint64_t(height_);
}

// As the RTL driver takes a region (RtlRop::load_region): the passes waiting end their group,
// and the tiles it covers hold those planes in the frame, loaded at their next pass.
void CostCounter::load_region(const RegionLoad& r) {
  inner_.load_region(r);
  end_group();
  for (Grid& g : grids_) {
    g.states.loaded(r);
    g.resident_states.loaded(r);
  }
}

}  // namespace zb
