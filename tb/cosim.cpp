#include "cosim.h"

#include <filesystem>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

namespace zb {
namespace {

std::string hex(uint64_t v, int digits) {
  static const char kDigits[] = "0123456789abcdef";
  std::string s;
  for (int i = 0; i < 16 && (i < digits || v); ++i, v >>= 4) s.insert(s.begin(), kDigits[v & 15]);
  return "0x" + s;
}

std::string rgba(Rgba8 c) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "rgba(%u,%u,%u,%u)", c.r, c.g, c.b, c.a);
  return buf;
}

std::string state_text(const RopState& s) {
  std::ostringstream o;
  o << "depth_test=" << s.depth_test << " func=" << to_string(s.depth_func)
    << " depth_write=" << s.depth_write << " blend=" << to_string(s.blend)
    << " color_mask=" << hex(s.color_mask, 1) << " peel_test=" << s.peel_test;
  if (s.blend == BlendMode::kLayers) o << " layers=" << int(s.layers);
  o << " (packed " << hex(pack_state(s), 4) << ")";
  return o.str();
}

CosimOptions with_sink(CosimOptions o, RetireSink* sink) {
  if (o.lockstep) o.rtl.retire_sink = sink;
  return o;
}

}  // namespace

Cosim::Cosim(CosimOptions options)
    : opt_(with_sink(std::move(options), &scoreboard_)), rtl_(opt_.rtl) {}

void Cosim::begin_frame(int width, int height, int depth_bits, Rgba8 clear_color,
                        int coverage_samples, const WboitFormat& wboit) {
  run_group();  // the last frame's group, if it was not finished
  golden_.begin_frame(width, height, depth_bits, clear_color, coverage_samples, wboit);
  rtl_.begin_frame(width, height, depth_bits, clear_color, coverage_samples, wboit);
  ++frame_no_;
  pass_in_frame_ = 0;
}

void Cosim::begin_pass(const RopState& state) {
  if (!rtl_.pending()) {  // a new group
    before_ = golden_.framebuffer();
    group_.clear();
    scoreboard_.begin_pass();
  }
  ++pass_in_frame_;
  group_.push_back(GroupPass{state, std::move(next_pass_name_), pass_in_frame_, {}});
  next_pass_name_.clear();
  op_name_.clear();
  state_ = state;
  golden_.begin_pass(state);
  rtl_.begin_pass(state);
}

void Cosim::draw(const Fragment* fragments, size_t count) {
  if (opt_.lockstep) {
    for (size_t i = 0; i < count; ++i) scoreboard_.expect(golden_.process(fragments[i]));
  } else {
    golden_.draw(fragments, count);
  }
  rtl_.draw(fragments, count);
  fragments_ += count;
}

std::string Cosim::pass_label(size_t k) const {
  std::string s = "frame " + std::to_string(frame_no_);
  if (!op_name_.empty() || group_.empty()) return s + " pass " + std::to_string(pass_in_frame_) +
                                                   (op_name_.empty() ? "" : " \"" + op_name_ + "\"");
  if (k == std::string::npos && group_.size() > 1)
    return s + " passes " + std::to_string(group_.front().in_frame) + ".." +
           std::to_string(group_.back().in_frame) + " (on the resident tile)";
  const GroupPass& p = group_[k == std::string::npos ? 0 : k];
  s += " pass " + std::to_string(p.in_frame);
  if (!p.name.empty()) s += " \"" + p.name + "\"";
  return s;
}

PassStats Cosim::end_pass() {
  group_.back().golden = golden_.end_pass();
  if (opt_.rtl.schedule == TileSchedule::kTile) {
    rtl_.end_pass();
    return PassStats{};
  }
  scoreboard_.arm(golden_.framebuffer());
  PassStats r;
  try {
    r = rtl_.end_pass();
  } catch (const RtlStopped&) {
    ++passes_;
    report_divergence(*scoreboard_.first());
  }
  if (rtl_.pending()) return PassStats{};  // a layers pass waits for its resolve (RtlRop::end_pass)
  check_group({r});
  return r;
}

void Cosim::run_group() {
  if (!rtl_.pending()) return;
  scoreboard_.arm(golden_.framebuffer());
  std::vector<PassStats> r;
  try {
    r = rtl_.flush();
  } catch (const RtlStopped&) {
    passes_ += group_.size();
    report_divergence(*scoreboard_.first());
  }
  check_group(r);
}

void Cosim::check_group(const std::vector<PassStats>& rtl) {
  passes_ += rtl.size();
  compare_frames();
  for (size_t k = 0; k < rtl.size(); ++k) {
    const PassStats &g = group_[k].golden, &r = rtl[k];
    if (g.fragments_in != r.fragments_in || g.fragments_passed != r.fragments_passed ||
        g.depth_reads != r.depth_reads || g.depth_writes != r.depth_writes ||
        g.color_reads != r.color_reads || g.color_writes != r.color_writes) {
      at_pass(k);
      report_counters(r, g, k);
    }
  }
}

void Cosim::finish_frame(std::vector<PassStats>& stats) {
  run_group();
  rtl_.finish_frame(stats);
}

void Cosim::compare_frames() {
  const Framebuffer& gf = golden_.framebuffer();
  const Framebuffer& rf = rtl_.framebuffer();
  size_t differing = 0, first = 0;
  for (size_t i = 0; i < gf.color.size(); ++i)
    if (gf.color[i] != rf.color[i] || gf.depth[i] != rf.depth[i] ||
        gf.coverage[i] != rf.coverage[i] || gf.peel[i] != rf.peel[i] ||
        gf.accum_at(i) != rf.accum_at(i) || gf.reveal_at(i) != rf.reveal_at(i) ||
        gf.layers_at(i) != rf.layers_at(i)) {
      if (differing++ == 0) first = i;
    }
  pixels_compared_ += gf.color.size();
  if (differing) {
    mismatches_ += differing;
    report_pixel(int(first % gf.width), int(first / gf.width), differing);
  }
}

void Cosim::frame_op(const FrameOp& op) {
  if (rtl_.on_tile()) {  // with the RTL's group: compared at its end
    golden_.frame_op(op);
    rtl_.frame_op(op);
    if (resolves(op.kind)) run_group();  // on its store: the group ends
    return;
  }
  run_group();
  before_ = golden_.framebuffer();
  golden_.frame_op(op);
  rtl_.frame_op(op);
  op_name_ = std::string("frame op ") + to_string(op.kind);
  compare_frames();
}

void Cosim::report_pixel(int x, int y, size_t differing) {
  const Framebuffer& gf = golden_.framebuffer();
  const Framebuffer& rf = rtl_.framebuffer();
  const int bits = gf.depth_bits;
  const int zd = (bits + 3) / 4;
  std::ostringstream o;
  o << "MISMATCH in " << pass_label() << ": " << differing << " of " << gf.color.size()
    << " pixels differ\n";
  o << "pixel (" << x << "," << y << ") rtl=" << rgba(rf.color_at(x, y)) << " z="
    << hex(rf.depth_at(x, y), zd) << " cov=" << rf.coverage_at(x, y)
    << " golden=" << rgba(gf.color_at(x, y)) << " z=" << hex(gf.depth_at(x, y), zd)
    << " cov=" << gf.coverage_at(x, y) << "\n";
  o << "  peel: rtl=" << hex(rf.peel_at(x, y), zd) << " golden=" << hex(gf.peel_at(x, y), zd)
    << "\n";
  const size_t i = gf.index(x, y);
  o << "  accumulation: rtl=" << accum_text(rf.accum_at(i), rf.reveal_at(i))
    << " golden=" << accum_text(gf.accum_at(i), gf.reveal_at(i)) << "\n";
  o << "  before the " << (group_.size() > 1 ? "group" : "pass") << ": "
    << rgba(before_.color_at(x, y)) << " z=" << hex(before_.depth_at(x, y), zd)
    << " cov=" << before_.coverage_at(x, y) << " "
    << accum_text(before_.accum_at(i), before_.reveal_at(i)) << "\n";
  if (group_.size() > 1 && op_name_.empty()) {
    for (const GroupPass& p : group_)
      o << "  state of pass " << p.in_frame << ": " << state_text(p.state) << "\n";
  } else {
    o << "  state: " << state_text(state_) << "\n";
  }
  uint64_t lo = std::numeric_limits<uint64_t>::max(), hi = 0;
  o << pixel_history(x, y, lo, hi, 64);
  const TileRun* run = tile_run(x, y);
  std::string fst;
  WaveView view;
  view.markers = accept_markers(x, y);
  view.title = "pixel (" + std::to_string(x) + "," + std::to_string(y) + ") differs after " +
               pass_label() + "; markers: its fragments' accepts";
  if (run) {
    o << waveform(x, y, *run, lo, hi, view, fst);
  } else {
    o << "  waveform: the pass did not stream the tile of (" << x << "," << y
      << "): the pixel changed without a fragment\n";
  }
  throw MismatchError(o.str(), x, y, fst);
}

void Cosim::report_counters(const PassStats& r, const PassStats& g, size_t k) {
  std::ostringstream o;
  o << "MISMATCH in " << pass_label(k) << ": counters differ (frame bits agree)\n";
  auto row = [&](const char* name, uint64_t a, uint64_t b) {
    if (a != b) o << "  counter " << name << " rtl=" << a << " golden=" << b << "\n";
  };
  row("fragments_in", r.fragments_in, g.fragments_in);
  row("fragments_passed", r.fragments_passed, g.fragments_passed);
  row("depth_reads", r.depth_reads, g.depth_reads);
  row("depth_writes", r.depth_writes, g.depth_writes);
  row("color_reads", r.color_reads, g.color_reads);
  row("color_writes", r.color_writes, g.color_writes);
  o << "  state: " << state_text(state_) << "\n";
  throw MismatchError(o.str(), -1, -1, "");
}

const TileRun* Cosim::tile_run(int x, int y) const {
  const int x0 = x / kRtlTileW * kRtlTileW, y0 = y / kRtlTileH * kRtlTileH;
  for (const TileRun& t : rtl_.tile_runs())
    if (t.x0 == x0 && t.y0 == y0) return &t;
  return nullptr;
}

std::string Cosim::pixel_history(int x, int y, uint64_t& lo, uint64_t& hi, size_t limit,
                                 size_t last) const {
  const std::vector<Fragment>& frags = rtl_.pass_fragments();
  const std::vector<uint64_t>& acc = rtl_.accept_cycles();
  const bool logged = opt_.lockstep && scoreboard_.rtl().size() == frags.size();
  const TileRun* run = tile_run(x, y);
  const int zd = (golden_.framebuffer().depth_bits + 3) / 4;
  size_t touching = 0, later = 0;
  std::ostringstream list;
  for (size_t i = 0; i < frags.size(); ++i) {
    const Fragment& f = frags[i];
    if (f.x != x || f.y != y) continue;
    if (i > last) {
      ++later;
      continue;
    }
    ++touching;
    lo = std::min(lo, acc[i]);
    hi = std::max(hi, acc[i]);
    if (touching > limit) continue;
    list << "    #" << i;
    if (group_.size() > 1) list << " (pass " << group_[rtl_.pass_of(uint32_t(i))].in_frame << ")";
    list << " z=" << hex(f.z, zd) << " " << rgba(f.color)
         << " cov=" << int(f.coverage) << " prim=" << f.prim << " accepted at cycle " << acc[i]
         << "\n";
    if (!logged) continue;
    const PixelWrites& g = scoreboard_.expected()[i];
    const RtlRetired& r = scoreboard_.rtl()[i];
    list << "      golden: " << describe_writes(RetireStage::kX4, g, kRtlDepthBits) << ", "
         << describe_writes(RetireStage::kX11, g, kRtlDepthBits) << "\n      rtl:    ";
    for (int s = 0; s < 2; ++s) {
      const RetireStage st = s ? RetireStage::kX11 : RetireStage::kX4;
      list << (s ? "; " : "") << to_string(st);
      if (r.cycle[s] == RtlRetired::kNever || !run)
        list << " not retired";
      else
        list << " at cycle " << run->load_begin + r.cycle[s] << ": "
             << describe_writes(st, r.writes[s], kRtlDepthBits);
    }
    list << "\n";
  }
  std::ostringstream o;
  o << "  fragments of this " << (group_.size() > 1 ? "group" : "pass") << " at (" << x << ","
    << y << "), oldest first: " << touching
    << "\n" << list.str();
  if (touching > limit) o << "    ... " << (touching - limit) << " more\n";
  if (later) o << "    (" << later << " younger fragments of this pixel not shown)\n";
  return o.str();
}

std::vector<WaveMarker> Cosim::accept_markers(int x, int y, size_t last) const {
  const std::vector<Fragment>& frags = rtl_.pass_fragments();
  const std::vector<uint64_t>& acc = rtl_.accept_cycles();
  std::vector<WaveMarker> m;
  for (size_t i = 0; i < frags.size() && i <= last; ++i)
    if (frags[i].x == x && frags[i].y == y)
      m.push_back({acc[i], "#" + std::to_string(i) + " accepted"});
  constexpr size_t kMost = 25;  // GTKWave's 26 named markers, one kept for the wrong write
  if (m.size() > kMost) m.erase(m.begin(), m.end() - kMost);  // the latest
  return m;
}

std::string Cosim::waveform(int x, int y, const TileRun& run, uint64_t lo, uint64_t hi,
                            WaveView view, std::string& fst) {
  uint64_t from = run.load_begin, to = run.store_end;  // nothing streamed: the whole tile
  if (lo <= hi) {
    from = std::max(run.load_begin, lo > opt_.window ? lo - opt_.window : 0);
    to = std::min(hi + opt_.window, run.store_end);
  }
  view.from = from;
  view.to = to;
  std::ostringstream o;
  if (!opt_.rtl.trace_path.empty()) {  // the run's own FST: its save file shows the same
    rtl_.mark_waves(view);
    o << "  trace: " << opt_.rtl.trace_path << " with its save file "
      << std::filesystem::path(opt_.rtl.trace_path).replace_extension(".gtkw").string()
      << " (written as the run ends), zoomed to cycles " << from << ".." << to << "\n";
  }
  if (opt_.mismatch_fst.empty()) return o.str();
  const int x0 = run.x0, y0 = run.y0;
  const Framebuffer& rf = rtl_.framebuffer();
  try {
    const Framebuffer replayed =
        rtl_.replay_tile(before_, x0, y0, opt_.mismatch_fst, from, to, view);
    fst = opt_.mismatch_fst;
    const size_t i = rf.index(x, y);
    const bool same = replayed.color_at(x, y) == rf.color_at(x, y) &&
                      replayed.depth_at(x, y) == rf.depth_at(x, y) &&
                      replayed.coverage_at(x, y) == rf.coverage_at(x, y) &&
                      replayed.accum_at(i) == rf.accum_at(i) && replayed.reveal_at(i) == rf.reveal_at(i);
    o << "  waveform: " << fst << " (cycles " << from << ".." << to << " of tile (" << x0 << ","
      << y0 << "); a 10 ns clock, cycle c's rising edge at 10c+5 ns; replay "
      << (same ? "reproduced the RTL's pixel" : "did NOT reproduce the RTL's pixel: its "
                                                "fresh model lacks earlier passes' state")
      << ")\n";
    o << "  save file: " << std::filesystem::path(fst).replace_extension(".gtkw").string()
      << " (gtkwave " << std::filesystem::path(fst).replace_extension(".gtkw").string()
      << "): signals by stage, markers at "
      << (view.mismatch != WaveView::kNone ? "the first wrong write and " : "")
      << "the pixel's accepts\n";
  } catch (const std::exception& e) {
    o << "  waveform: not written: " << e.what() << "\n";
  }
  return o.str();
}

void Cosim::report_divergence(const Divergence& d) {
  const Retire& r = d.retire;
  const size_t k = !d.store && r.fragment != Retire::kNoFragment ? rtl_.pass_of(r.fragment)
                                                                  : group_.size() - 1;
  at_pass(k);
  const TileRun* run = tile_run(r.x, r.y);
  const uint64_t cycle = (run ? run->load_begin : 0) + r.tile_cycle;
  const int zd = (golden_.framebuffer().depth_bits + 3) / 4;
  ++mismatches_;
  std::ostringstream o;
  o << "LOCKSTEP MISMATCH in " << pass_label(k) << ": the first wrong write, at cycle " << cycle
    << " (its rising edge at " << wave_rise_text(cycle) << ")\n";
  if (!d.store && r.fragment != Retire::kNoFragment) {
    const Fragment& f = rtl_.pass_fragments().at(r.fragment);
    o << "  fragment #" << r.fragment << " (primitive " << f.prim << ") at pixel (" << r.x << ","
      << r.y << "), accepted at cycle " << rtl_.accept_cycles().at(r.fragment) << "\n";
  } else {
    o << "  pixel (" << r.x << "," << r.y << ")\n";
  }
  o << "  " << d.what << "\n";
  o << "  state: " << state_text(state_) << "\n";
  o << "  before the " << (group_.size() > 1 ? "group" : "pass") << ": "
    << rgba(before_.color_at(r.x, r.y))
    << " z=" << hex(before_.depth_at(r.x, r.y), zd) << " cov=" << before_.coverage_at(r.x, r.y)
    << " " << accum_text(before_.accum_at(before_.index(r.x, r.y)),
                         before_.reveal_at(before_.index(r.x, r.y)))
    << "\n";
  uint64_t lo = cycle, hi = cycle;
  // A store divergence follows every retire of the tile: the whole history.
  const size_t last = !d.store && r.fragment != Retire::kNoFragment ? r.fragment : SIZE_MAX;
  o << pixel_history(r.x, r.y, lo, hi, 64, last);
  std::string fst;
  WaveView view;
  const std::string what =
      !d.store && r.fragment != Retire::kNoFragment ? " #" + std::to_string(r.fragment) : "";
  view.markers.push_back({cycle, "first wrong write" + what});
  for (WaveMarker& m : accept_markers(r.x, r.y, last)) view.markers.push_back(std::move(m));
  view.mismatch = cycle;
  view.title = "the first wrong write at pixel (" + std::to_string(r.x) + "," +
               std::to_string(r.y) + "), " + pass_label(k) + "; markers: it, then its pixel's accepts";
  if (run) o << waveform(r.x, r.y, *run, lo, hi, view, fst);
  throw MismatchError(o.str(), r.x, r.y, fst);
}

std::string Cosim::nothing_checked_warning() const {
  if (pixels_compared_ == 0 || fragments_ == 0)
    return "warning: cosim checked nothing (" + std::to_string(pixels_compared_) +
           " pixels compared, " + std::to_string(fragments_) + " fragments)";
  return "";
}

}  // namespace zb
