// zblend_window_sweep: the issue window's depth against streaming cycles per fragment, by the
// RTL's own schedule (tb/rtlmodel/rtl_timing.h), on the scenes and methods where fragments wait
// for their pixels; with one tile buffer (zb_rop) and with two (the proposed design: each
// pass's tiles as one stream, IssueSchedule::run_two_buffers, its tile port taking no cycles). Usage: zblend_window_sweep [WIDTH HEIGHT] [SCENE...] (scene files or
// built-in names; default the lab's two real meshes).
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <exception>
#include <string>
#include <vector>

#include "io/scene_file.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "rtl_params.h"
#include "rtl_timing.h"
#include "scene/builtin_scenes.h"

namespace zb {
namespace {

constexpr unsigned kWindows[] = {2, 4, 8, 12, 16};

// The golden model, with every pass's stream kept and scheduled at each window depth.
class Sweep final : public Backend {
 public:
  const char* name() const override { return "window-sweep"; }
  using Backend::begin_frame;
  void begin_frame(int w, int h, int d, Rgba8 c, int s, const WboitFormat& f) override {
    width_ = w;
    height_ = h;
    golden_.begin_frame(w, h, d, c, s, f);
  }
  void begin_pass(const RopState& s) override {
    frags_.clear();
    golden_.begin_pass(s);
  }
  using Backend::draw;
  void draw(const Fragment* f, size_t n) override {
    frags_.insert(frags_.end(), f, f + n);
    golden_.draw(f, n);
  }
  PassStats end_pass() override {
    bin_by_tile(frags_.data(), frags_.size(), width_, height_, kRtlTileW, kRtlTileH, bins_);
    fragments_ += frags_.size();
    keys_.assign(bins_.order.size(), 0);
    std::vector<TileStream> tiles;
    for (size_t t = 0; t + 1 < bins_.first.size(); ++t) {
      for (uint32_t k = bins_.first[t]; k < bins_.first[t + 1]; ++k) {
        const Fragment& g = frags_[bins_.order[k]];
        keys_[k] = uint32_t(g.y) * uint32_t(width_) + g.x;
      }
      if (bins_.first[t + 1] > bins_.first[t])
        tiles.push_back(TileStream{keys_.data() + bins_.first[t], bins_.first[t + 1] - bins_.first[t], 0, 0});
    }
    for (size_t w = 0; w < std::size(kWindows); ++w) {
      IssueSchedule schedule(kWindows[w]);
      for (size_t t = 0; t + 1 < bins_.first.size(); ++t)
        cycles_[w] += schedule.run_tile(bins_, t, frags_.data(), width_);
      two_[w] += schedule.run_two_buffers(tiles).stream;
    }
    return golden_.end_pass();
  }
  void frame_op(const FrameOp& op) override { golden_.frame_op(op); }
  const Framebuffer& framebuffer() const override { return golden_.framebuffer(); }

  double per_fragment(size_t w) const { return double(cycles_[w]) / double(fragments_); }
  double two_per_fragment(size_t w) const { return double(two_[w]) / double(fragments_); }

 private:
  GoldenRop golden_;
  int width_ = 0, height_ = 0;
  std::vector<Fragment> frags_;
  TileBins bins_;
  uint64_t fragments_ = 0;
  std::vector<uint32_t> keys_;  // the pass's frame pixel indices, in tile order
  uint64_t cycles_[std::size(kWindows)] = {};
  uint64_t two_[std::size(kWindows)] = {};
};

}  // namespace
}  // namespace zb

int main(int argc, char** argv) {
  using namespace zb;
  int width = 320, height = 240, first = 1;
  if (argc >= 3 && std::isdigit(static_cast<unsigned char>(argv[1][0]))) {
    width = std::atoi(argv[1]);
    height = std::atoi(argv[2]);
    first = 3;
  }
  std::vector<std::string> scenes(argv + first, argv + argc);
  if (scenes.empty())
    scenes = {"/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf",
              "/usr/share/glmark2/models/bunny.obj", "parts", "crossing-quads"};
  try {
    std::printf("streaming cycles per fragment, %dx%d, tile %d; window slots:", width, height,
                kRtlTileW);
    for (const unsigned w : kWindows) std::printf(" %6u", w);
    std::printf("\n");
    for (const std::string& name : scenes) {
      const std::optional<Scene> builtin = builtin_scene(name);
      const Scene scene = builtin ? *builtin : load_scene_file(name);
      const RasterizedScene rs = rasterize_scene(scene, Viewport{width, height, kRtlDepthBits});
      for (const char* method : {"hidden-line-dim", "hidden-line", "coverage-aa", "three-pass"}) {
        Sweep sweep;
        render(rs, *find_plan(method), sweep);
        const size_t slash = name.find_last_of('/');
        std::printf("%-24s %-16s", name.substr(slash == std::string::npos ? 0 : slash + 1).c_str(),
                    method);
        for (size_t w = 0; w < std::size(kWindows); ++w) std::printf(" %6.4f", sweep.per_fragment(w));
        std::printf("\n%-24s %-16s", "", "  two buffers");
        for (size_t w = 0; w < std::size(kWindows); ++w)
          std::printf(" %6.4f", sweep.two_per_fragment(w));
        std::printf("\n");
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "zblend_window_sweep: %s\n", e.what());
    return 2;
  }
}
