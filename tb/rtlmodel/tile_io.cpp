#include "tile_io.h"

#include <algorithm>
#include <stdexcept>

#include "rop/blend.h"
#include "rop/fixed.h"

namespace zb {

std::string accum_text(const std::array<uint32_t, 4>& acc, uint32_t reveal) {
  return "acc(" + std::to_string(acc[0]) + "," + std::to_string(acc[1]) + "," +
         std::to_string(acc[2]) + "," + std::to_string(acc[3]) + ") reveal " +
         std::to_string(reveal);
}
std::string accum_text(const AccumWord& w) { return accum_text(w.acc, w.reveal); }

AccumWord accum_clear_word(const WboitFormat& f) {
  AccumWord w;
  w.reveal = wboit_reveal_one(f.rev_bits);
  return w;
}

// The plane a pass with a colour mask reads and writes: the accumulation word in accumulate
// mode, the layers in layers mode, else the colour.
static uint8_t blended_plane(const RopState& s) {
  if (s.color_mask == 0) return 0;
  if (s.blend == BlendMode::kLayers) return kPlaneLayers;
  return s.blend == BlendMode::kAccumulate ? kPlaneAccum : kPlaneColor;
}

// As zb_rop: coverage mode reads depth (nearer) and the coverage plane; the peel test is not
// used there. Colour (or the accumulation word) is read only by a pass that writes it.
uint8_t planes_read(const RopState& s) {
  const bool cov = is_coverage_pass(s);
  uint8_t p = blended_plane(s);
  if (p & kPlaneLayers) p |= kPlaneColor;  // the opaque colour, for the resolve on the store
  if (s.depth_test || cov) p |= kPlaneDepth;
  if (cov) p |= kPlaneCoverage;
  if (s.peel_test && !cov) p |= kPlanePeel;
  return p;
}

uint8_t planes_written(const RopState& s) {
  uint8_t p = blended_plane(s);
  if (s.depth_test && s.depth_write) p |= kPlaneDepth;
  if (is_coverage_pass(s)) p |= kPlaneCoverage;
  return p;
}

BeatWords clear_beat(const TileIo& io) {
  BeatWords w{};
  for (size_t p = 0; p < kWordPlanes; ++p) w[p][0] = io.clear_value[p];
  w.accum[0] = io.accum_clear;
  return w;
}

TileSweep::TileSweep(int frame_w, int frame_h, int x0, int y0)
    : x0_(x0), y0_(y0), w_(std::min(kRtlTileW, frame_w - x0)), h_(std::min(kRtlTileH, frame_h - y0)) {}

int64_t TileSweep::pixel(const Framebuffer& fb, int k, int l) const {
  constexpr int per_row = kRtlTileW / kRtlBeat;
  const int x = k % per_row * kRtlBeat + l, y = k / per_row;
  if (x >= w_ || y >= h_) return -1;
  return int64_t(fb.index(x0_ + x, y0_ + y));
}

BeatWords TileSweep::load(const Framebuffer& fb, int k) const {
  BeatWords w{};
  for (int l = 0; l < kRtlBeat; ++l) {
    const int64_t i = pixel(fb, k, l);
    if (i < 0) continue;
    w[0][size_t(l)] = pack_rgba(fb.color[size_t(i)]);
    w[1][size_t(l)] = fb.depth[size_t(i)];
    w[2][size_t(l)] = fb.coverage[size_t(i)];
    w[3][size_t(l)] = fb.peel[size_t(i)];
    w.accum[size_t(l)] = AccumWord{fb.accum_at(size_t(i)), fb.reveal_at(size_t(i))};
  }
  return w;
}

void prepare_stores(Framebuffer& fb, const RopState& s) {
  if (planes_written(s) & kPlaneAccum) fb.touch_accum();
}

void TileSweep::store(const BeatWords& w, uint8_t planes, Framebuffer& fb, int k) const {
  const size_t n = size_t(fb.width) * size_t(fb.height);
  const bool whole = fb.color.size() == n && fb.depth.size() == n && fb.coverage.size() == n &&
                     (!(planes & kPlaneAccum) || (fb.accum.size() == n && fb.reveal.size() == n));
  if (!whole || x0_ + w_ > fb.width || y0_ + h_ > fb.height)
    throw std::logic_error(
        "tile store: tile (" + std::to_string(x0_) + "," + std::to_string(y0_) + ") beat " +
        std::to_string(k) + " found the frame's planes missing or replaced (" +
        std::to_string(fb.width) + "x" + std::to_string(fb.height) +
        (fb.accum.empty() ? ", no accumulation planes" : "") +
        "): a host-side fault, not the RTL's");
  for (int l = 0; l < kRtlBeat; ++l) {
    const int64_t i = pixel(fb, k, l);
    if (i < 0) continue;
    if (planes & kPlaneColor) fb.color[size_t(i)] = unpack_rgba(w[0][size_t(l)]);
    if (planes & kPlaneDepth) fb.depth[size_t(i)] = w[1][size_t(l)];
    if (planes & kPlaneCoverage) fb.coverage[size_t(i)] = uint8_t(w[2][size_t(l)]);
    if (planes & kPlanePeel) fb.peel[size_t(i)] = w[3][size_t(l)];
    if (planes & kPlaneAccum) {
      fb.accum[size_t(i)] = w.accum[size_t(l)].acc;
      fb.reveal[size_t(i)] = w.accum[size_t(l)].reveal;
    }
  }
}

uint64_t tile_beats(int w, int h, int beat) {
  if (w <= 0 || h <= 0 || beat <= 0) return 0;
  return uint64_t(h) * uint64_t((w + beat - 1) / beat);
}

uint64_t tile_io_cycles(uint64_t beats, const TileIo& io) {
  return kRtlTileSetup + (io.load ? beats : 0) + (io.store ? beats : 0);
}

TileStates::TileStates(int width, int height, int tile, int depth_bits, Rgba8 clear_color,
                       const WboitFormat& wboit)
    : depth_bits_(depth_bits), tile_(tile), columns_((width + tile - 1) / tile),
      accum_clear_(accum_clear_word(wboit)) {
  if (width < 1 || height < 1 || tile < 1)
    throw std::invalid_argument("tile states: empty frame or tile");
  const size_t n = size_t(columns_) * size_t((height + tile - 1) / tile);
  std::array<Plane, kTilePlanes> fresh;
  fresh[0] = {true, pack_rgba(clear_color)};
  fresh[1] = {true, depth_max(depth_bits)};
  fresh[2] = {true, 0};
  fresh[3] = {true, 0};
  fresh[4] = {true, 0};  // its value is accum_clear_
  fresh[5] = {true, 0};  // empty
  planes_.assign(n, fresh);
}

void TileStates::apply(std::array<Plane, kTilePlanes>& t, const FrameOp& op) const {
  switch (op.kind) {
    case FrameOpKind::kClearColor: t[0] = {true, pack_rgba(op.value)}; break;
    case FrameOpKind::kClearDepth: t[1] = {true, std::min(op.depth, depth_max(depth_bits_))}; break;
    case FrameOpKind::kCopyDepthToPeel: t[3] = t[1]; break;
    case FrameOpKind::kResolveUnder:
      if (t[0].cleared) {  // a uniform colour resolves to a uniform colour
        const Rgba8 c = unpack_rgba(t[0].value);
        t[0].value = pack_rgba({resolve_under(c.r, op.value.r, c.a), resolve_under(c.g, op.value.g, c.a),
                                resolve_under(c.b, op.value.b, c.a), resolve_under(c.a, op.value.a, c.a)});
      }
      break;
    case FrameOpKind::kResolveWboit:  // colour made per pixel from the accumulation; a
      // cleared accumulation (acc_A = 0, r = 1.0) leaves a uniform colour as it is
      if (!t[4].cleared) t[0].cleared = false;
      break;
    case FrameOpKind::kResolveLayers:  // always on the store of the group that made the layers
      break;                           // (they never leave the tile): its store marks colour

  }
}

void TileStates::frame_op(const FrameOp& op) {
  for (auto& t : planes_) apply(t, op);
}

TileIo TileStates::plan(size_t tile, const RopState& s) const { return plan(planes_.at(tile), s); }

TileIo TileStates::plan(const std::array<Plane, kTilePlanes>& t, const RopState& s) const {
  TileIo io;
  const uint8_t needed = planes_read(s) | planes_written(s);
  for (int p = 0; p < kTilePlanes; ++p) {
    if (!(needed >> p & 1)) continue;
    const Plane& pl = t[size_t(p)];
    if (pl.cleared) {
      io.clear |= uint8_t(1u << p);
      if (p == kAccumPlane)
        io.accum_clear = accum_clear_;
      else if (p < kWordPlanes)  // the layers plane clears empty: no value
        io.clear_value[size_t(p)] = pl.value;
    } else {
      io.load |= uint8_t(1u << p);
    }
  }
  io.store = planes_written(s);
  return io;
}

// Per plane: resident (in the tile memory, loaded or fast-cleared this run) and made (written
// or copied in the tile since its last clear: stored at the end). Per bank, as zb_plane's fast
// clear: the epoch's steps since every word was last at the epoch (a load writes them, a read
// of every beat writes the fresh ones back) and all_fresh (fast-cleared, nothing written since:
// a fast clear then keeps the epoch). A fast clear that would take a written bank past
// 2^gen_bits - 1 steps needs a read of every beat first: a sweep (a copy is one too).
TileStates::RunPlan TileStates::plan_tile(size_t tile, const GroupStep* steps, size_t n,
                                          TileBanks banks) const {
  struct Bank {
    int steps = 0;
    bool all_fresh = false;  // a store's reads ended the tile before: all at the epoch
  };
  RunPlan out;
  std::array<Plane, kTilePlanes> t = planes_.at(tile);
  std::array<Bank, kTilePlanes> bank{};
  std::array<size_t, kTilePlanes> role = {0, 1, 2, 3, 4, 5};  // plane p's bank
  // The epoch's steps a written bank takes between reads of every beat: the depth banks'
  // generations are gen_bits wide, the other planes' one bit.
  const int depth_steps = (1 << std::clamp(banks.gen_bits, 1, 16)) - 1;
  auto max_steps = [&](size_t b) { return b == 1 || b == 3 ? depth_steps : 1; };
  uint8_t resident = 0, made = 0;
  bool copy = false, sweep = false, swap = false;  // pending before the next pass
  uint8_t preload = 0;
  auto needs_sweep = [&](int p) {
    const Bank& b = bank[role[size_t(p)]];
    return !b.all_fresh && b.steps + 1 > max_steps(role[size_t(p)]);
  };
  auto each = [](uint8_t planes, auto&& f) {
    for (int p = 0; p < kTilePlanes; ++p)
      if (planes >> p & 1) f(p);
  };
  auto read_all = [&] {
    for (Bank& b : bank) b = Bank{};
  };
  auto fast_clear = [&](int p) {  // the epoch steps unless every word is at it already
    Bank& b = bank[role[size_t(p)]];
    if (!b.all_fresh) ++b.steps;
    b.all_fresh = true;
  };
  for (size_t k = 0; k < n; ++k) {
    const GroupStep& st = steps[k];
    if (!st.pass) {
      const FrameOp& op = st.op;
      if (op.kind == FrameOpKind::kResolveUnder) {  // on the store
        out.resolve = StoreResolve::kUnder;  // under the step's op.value
      } else if (op.kind == FrameOpKind::kResolveWboit ||
                 op.kind == FrameOpKind::kResolveLayers) {  // on the store: colour and the
        const bool wboit = op.kind == FrameOpKind::kResolveWboit;  // accumulation (layers)
        out.resolve = wboit ? StoreResolve::kWboit : StoreResolve::kLayers;  // resident
        for (const int p : {0, wboit ? int(kAccumPlane) : int(kLayersPlane)}) {
          if (resident >> p & 1) continue;
          if (t[size_t(p)].cleared) {
            if (needs_sweep(p)) {
              if (!copy) sweep = true;
              read_all();
            }
            out.clear_after.clear |= uint8_t(1u << p);
            if (p == kAccumPlane)
              out.clear_after.accum_clear = accum_clear_;
            else if (p < kWordPlanes)  // the layers plane clears empty: no value
              out.clear_after.clear_value[size_t(p)] = t[size_t(p)].value;
            fast_clear(p);
          } else {
            preload |= uint8_t(1u << p);
          }
          resident |= uint8_t(1u << p);
        }
        made |= kPlaneColor;
      } else if (op.kind == FrameOpKind::kCopyDepthToPeel) {
        if (!(resident & kPlaneDepth) && !t[1].cleared) {  // the frame's depth, for the copy
          preload |= kPlaneDepth;
          resident |= kPlaneDepth;
          bank[role[1]] = Bank{};
        }
        const bool cleared_next = k + 1 < n && !steps[k + 1].pass &&
                                  steps[k + 1].op.kind == FrameOpKind::kClearDepth;
        if ((resident & kPlaneDepth) && banks.rename && cleared_next) {  // peel takes depth's bank
          std::swap(role[1], role[3]);
          swap = !swap;
          resident |= kPlanePeel;
          made |= kPlanePeel;
        } else if (resident & kPlaneDepth) {  // the tile's depth into peel
          copy = true;
          sweep = false;
          read_all();
          resident |= kPlanePeel;
          made |= kPlanePeel;
        } else {  // depth is cleared: so is peel, to its value (apply below)
          if (swap) {  // a trade still pending is moot (it may not clear peel with depth)
            std::swap(role[1], role[3]);
            swap = false;
          }
          if (needs_sweep(1) || needs_sweep(3)) {
            if (!copy) sweep = true;
            read_all();
          }
          resident &= uint8_t(~kPlanePeel);
          made &= uint8_t(~kPlanePeel);
        }
      } else {  // a clear: the host's frame holds the value; the next pass needing it clears it
        const int p = op.kind == FrameOpKind::kClearColor ? 0 : 1;
        if (needs_sweep(p)) {
          if (!copy) sweep = true;
          read_all();
        }
        resident &= uint8_t(~(1u << p));
        made &= uint8_t(~(1u << p));
      }
      apply(t, op);
      continue;
    }
    if (!st.touches) continue;
    RunPlan::Step s;
    s.step = k;
    s.io = plan(t, st.state);
    s.io.clear &= uint8_t(~resident);
    s.io.load &= uint8_t(~resident);
    s.io.store = 0;
    if (swap && !(s.io.clear & kPlaneDepth)) {  // the trade takes the fast clear of depth
      s.io.clear |= kPlaneDepth;
      s.io.clear_value[1] = t[1].value;
    }
    s.preload = preload;
    s.copy = copy;
    s.sweep = sweep;
    s.swap = swap;
    copy = sweep = swap = false;
    preload = 0;
    const uint8_t written = planes_written(st.state);
    each(s.io.clear, fast_clear);
    each(s.io.load, [&](int p) { bank[role[size_t(p)]] = Bank{}; });
    each(written, [&](int p) { bank[role[size_t(p)]].all_fresh = false; });
    resident |= planes_read(st.state) | written | s.io.clear;
    made |= written;
    out.steps.push_back(s);
  }
  out.preload_after = preload;
  out.copy_after = copy;
  out.sweep_after = sweep;
  out.swap_after = swap;
  out.swap_after_depth = t[1].value;
  out.store = made & uint8_t(~kPlaneLayers);  // the layers never leave the tile
  return out;
}

const char* to_string(TileSchedule s) { return s == TileSchedule::kTile ? "tile" : "pass"; }

bool parse_schedule(const std::string& name, TileSchedule& out) {
  if (name == "pass") out = TileSchedule::kPass;
  else if (name == "tile") out = TileSchedule::kTile;
  else return false;
  return true;
}

void TileStates::loaded(const RegionLoad& r) {
  const uint8_t planes = uint8_t(kPlaneColor | (r.depth.empty() ? 0 : kPlaneDepth));
  for (int ty = r.y0 / tile_; ty <= (r.y0 + r.height - 1) / tile_; ++ty)
    for (int tx = r.x0 / tile_; tx <= (r.x0 + r.width - 1) / tile_; ++tx)
      stored(size_t(ty) * size_t(columns_) + size_t(tx), planes);
}

void TileStates::stored(size_t tile, uint8_t planes) {
  planes &= uint8_t(~kPlaneLayers);
  for (int p = 0; p < kTilePlanes; ++p)
    if (planes >> p & 1) planes_.at(tile)[size_t(p)].cleared = false;
}

}  // namespace zb
