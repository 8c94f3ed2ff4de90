// The RTL's side of a pixel's history (docs/history.md "Beside the RTL"): each retire of zb_rop
// at a few pixels, its pass, the fragment's index in the pass, the cycle it was accepted and the
// cycle its write lands, as the retire monitor reports them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "history/pixel_history.h"
#include "retire_monitor.h"
#include "rtl_rop.h"

namespace zb {

// A retire at one of the asked pixels, as the history holds it.
struct PixelRetire {
  int x = 0, y = 0;
  RetireRecord record;
};

// A retire sink keeping the retires at `pixels`; every other one passes. Thread-safe (models
// run tiles side by side).
class PixelRetires final : public RetireSink {
 public:
  explicit PixelRetires(const std::vector<std::pair<int, int>>& pixels);
  bool retire(const Retire& r) override;
  bool store(const StoreBeat&) override { return true; }
  // After `rtl` ran a group of passes: the retires it made get their pass, index and cycles.
  void settle(const RtlRop& rtl);
  const std::vector<PixelRetire>& retires() const { return done_; }

 private:
  std::vector<std::pair<int, int>> pixels_;
  std::mutex mutex_;
  std::vector<Retire> pending_;
  std::vector<PixelRetire> done_;
};

// An RtlRop whose pixel retires are settled after every call that may run a group.
class SettledRtl final : public Backend {
 public:
  SettledRtl(RtlOptions options, PixelRetires& retires);
  const char* name() const override { return "rtl"; }
  using Backend::begin_frame;
  void begin_frame(int w, int h, int d, Rgba8 c, int s, const WboitFormat& f) override {
    rtl_.begin_frame(w, h, d, c, s, f);
  }
  void label_pass(const std::string& name) override { rtl_.label_pass(name); }
  void begin_pass(const RopState& s) override { rtl_.begin_pass(s); }
  using Backend::draw;
  void draw(const Fragment* f, size_t n) override { rtl_.draw(f, n); }
  PassStats end_pass() override;
  void frame_op(const FrameOp& op) override;
  void finish_frame(std::vector<PassStats>& stats) override;
  const Framebuffer& framebuffer() const override { return rtl_.framebuffer(); }

 private:
  static RtlOptions with_sink(RtlOptions o, PixelRetires& r) {
    o.retire_sink = &r;
    return o;
  }
  PixelRetires& retires_;
  RtlRop rtl_;
};

// Runs the frame of `f` again on the RTL (`run` drives the backend it is given: a render or a
// trace's replay) and puts its retires at each of f's pixels into the histories, in cycle
// order, with the RTL's final value there.
void add_rtl_retires(FrameHistory& f, const RtlOptions& options,
                     const std::function<void(Backend&)>& run);

// GTKWave names 26 markers (A to Z) a save file, so a pixel's markers go 26 to a file: page 1
// is FST's own .gtkw for one pixel (FST's stem with "-X-Y.gtkw" for each of several), page k > 1
// adds "-k". `several`: the run asked for more than one pixel.
std::string pixel_save_file_path(const std::string& fst, int x, int y, bool several, size_t page = 1);
constexpr size_t kMarkersPerSaveFile = 26;

// The save files of a run's FST (options.trace_path of add_rtl_retires): per pixel, every
// fragment's accept ("pass P fragment N accepted") and writes ("... X4", "... X11") as markers in
// cycle order, numbered as the history's text numbers them, 26 a file, each file zoomed on its
// markers. Returns each pixel's files, page 1 first.
std::vector<std::vector<std::string>> write_pixel_save_files(const FrameHistory& f, const std::string& fst);

}  // namespace zb
