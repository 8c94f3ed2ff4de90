#include "pixel_retires.h"

#include <algorithm>
#include <filesystem>

namespace zb {

PixelRetires::PixelRetires(const std::vector<std::pair<int, int>>& pixels) : pixels_(pixels) {
  std::sort(pixels_.begin(), pixels_.end());
}

bool PixelRetires::retire(const Retire& r) {
  if (std::binary_search(pixels_.begin(), pixels_.end(), std::pair<int, int>{r.x, r.y})) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(r);
  }
  return true;
}

void PixelRetires::settle(const RtlRop& rtl) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_.empty()) return;
  // The group's fragments run pass after pass: each pass's first index in the group.
  const size_t n = rtl.pass_fragments().size(), passes = rtl.group_passes();
  std::vector<uint32_t> first(passes + 1, uint32_t(n));
  for (size_t i = n; i-- > 0;) first[rtl.pass_of(uint32_t(i))] = uint32_t(i);
  for (size_t k = passes; k-- > 0;) first[k] = std::min(first[k], first[k + 1]);
  const size_t pass0 = size_t(rtl.pass_number()) + 1 - passes;
  for (const Retire& r : pending_) {
    RetireRecord p;
    p.x11 = r.stage == RetireStage::kX11;
    p.extra = r.kind == Retire::Kind::kExtra;
    p.missing = r.kind == Retire::Kind::kMissing;
    p.writes = r.writes;
    uint64_t base = 0;
    for (const TileRun& t : rtl.tile_runs())
      if (t.x0 == r.tile_x0 && t.y0 == r.tile_y0) base = t.load_begin;
    p.cycle = base + r.tile_cycle;
    if (r.fragment != Retire::kNoFragment) {
      const size_t k = rtl.pass_of(r.fragment);
      p.pass = pass0 + k;
      p.index = r.fragment - first[k];
      p.stream = r.fragment;
      p.accepted = rtl.accept_cycles().at(r.fragment);
    }
    done_.push_back({r.x, r.y, p});
  }
  pending_.clear();
}

SettledRtl::SettledRtl(RtlOptions options, PixelRetires& retires)
    : retires_(retires), rtl_(with_sink(std::move(options), retires)) {}

PassStats SettledRtl::end_pass() {
  const PassStats s = rtl_.end_pass();
  retires_.settle(rtl_);
  return s;
}

void SettledRtl::frame_op(const FrameOp& op) {
  rtl_.frame_op(op);
  retires_.settle(rtl_);
}

void SettledRtl::finish_frame(std::vector<PassStats>& stats) {
  rtl_.finish_frame(stats);
  retires_.settle(rtl_);
}

void add_rtl_retires(FrameHistory& f, const RtlOptions& options,
                     const std::function<void(Backend&)>& run) {
  std::vector<std::pair<int, int>> pixels;
  for (const PixelHistory& h : f.pixels) pixels.emplace_back(h.x, h.y);
  PixelRetires retires(pixels);
  SettledRtl rtl(options, retires);
  run(rtl);
  const Framebuffer& fb = rtl.framebuffer();
  for (PixelHistory& h : f.pixels) {
    h.rtl_ran = true;
    h.rtl_final = PixelValue::of(fb, fb.index(h.x, h.y));
    for (const PixelRetire& r : retires.retires())
      if (r.x == h.x && r.y == h.y) h.rtl.push_back(r.record);
    std::stable_sort(h.rtl.begin(), h.rtl.end(),
                     [](const RetireRecord& a, const RetireRecord& b) { return a.cycle < b.cycle; });
  }
}

std::string pixel_save_file_path(const std::string& fst, int x, int y, bool several, size_t page) {
  const std::filesystem::path p(fst);
  std::string stem = p.stem().string();
  if (several) stem += "-" + std::to_string(x) + "-" + std::to_string(y);
  if (page > 1) stem += "-" + std::to_string(page);
  return (p.parent_path() / (stem + ".gtkw")).string();
}

std::vector<std::vector<std::string>> write_pixel_save_files(const FrameHistory& f, const std::string& fst) {
  std::vector<std::vector<std::string>> paths;
  const bool several = f.pixels.size() > 1;
  for (const PixelHistory& h : f.pixels) {
    std::vector<WaveMarker> all;
    for (const RetireRecord& r : h.rtl) {
      if (r.extra || r.missing) continue;
      const std::string n = "pass " + std::to_string(r.pass) + " fragment " + std::to_string(r.index) +
                            " (#" + std::to_string(r.stream) + ")";
      if (!r.x11) all.push_back({r.accepted, n + " accepted"});
      all.push_back({r.cycle, n + (r.x11 ? " X11" : " X4")});
    }
    std::stable_sort(all.begin(), all.end(),
                     [](const WaveMarker& a, const WaveMarker& b) { return a.cycle < b.cycle; });
    const size_t pages = std::max<size_t>(1, (all.size() + kMarkersPerSaveFile - 1) / kMarkersPerSaveFile);
    paths.emplace_back();
    for (size_t page = 1; page <= pages; ++page) {
      WaveView view;
      const size_t from = (page - 1) * kMarkersPerSaveFile;
      const size_t to = std::min(all.size(), from + kMarkersPerSaveFile);
      view.markers.assign(all.begin() + std::ptrdiff_t(from), all.begin() + std::ptrdiff_t(to));
      if (!view.markers.empty()) {
        view.from = view.markers.front().cycle > 8 ? view.markers.front().cycle - 8 : 0;
        view.to = view.markers.back().cycle + 8;
      }
      view.title = "pixel (" + std::to_string(h.x) + ", " + std::to_string(h.y) + ")";
      if (pages > 1) view.title += ", markers " + std::to_string(from + 1) + " to " +
                                   std::to_string(to) + " of " + std::to_string(all.size());
      paths.back().push_back(write_save_file(fst, view, pixel_save_file_path(fst, h.x, h.y, several, page)));
    }
  }
  return paths;
}

}  // namespace zb
