// zb_plane's protocol assertions fail on a driver that breaks the protocol: zb_rop driven port
// by port (not through RtlRop, which keeps it), each broken order against the same order kept.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <verilated.h>

#include "Vzb_rop.h"
#include "rtl_params.h"
#include "tile_io.h"

namespace zb {
namespace {

class Port {
 public:
  Port() {
    ctx_.fatalOnError(false);  // an assertion's failure marks the context; the run goes on
    top_ = std::make_unique<Vzb_rop>(&ctx_, "zb_rop");
    Verilated::threadContextp(&ctx_);  // where a failure is recorded
    top_->clk_i = 1;
    top_->rst_ni = 0;
    top_->eval();
    tick();
    top_->rst_ni = 1;
    tick();
  }
  ~Port() {
    Verilated::threadContextp(&ctx_);  // a model is erased through its own context
    top_->final();
    top_.reset();
  }
  Port(const Port&) = delete;
  Port& operator=(const Port&) = delete;

  // As RtlRop: the inputs evaluated at the falling edge, then sampled at the rising edge.
  void tick() {
    Verilated::threadContextp(&ctx_);
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
    top_->tile_req_i = 0;
    top_->tile_we_i = 0;
    top_->tile_clear_i = 0;
    top_->tile_planes_i = 0;
  }
  // One read of every beat, as the driver does after reset.
  void sweep() {
    for (int k = 0; k < kRtlTileW * kRtlTileH / kRtlBeat; ++k) read(k);
    tick();
    tick();
  }
  void read(int beat) {
    top_->tile_req_i = 1;
    top_->tile_addr_i = uint32_t(beat);
    tick();
  }
  void fast_clear_color() {
    top_->tile_clear_i = 1;
    top_->tile_planes_i = kPlaneColor;
    tick();
  }
  bool failed() const { return ctx_.gotError(); }

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vzb_rop> top_;
};

TEST(RtlPortAsserts, FastClearAfterSweep) {
  Port bad;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  bad.fast_clear_color();  // no sweep since reset: the words' generations are unknown
  const std::string out = testing::internal::GetCapturedStdout() +
                          testing::internal::GetCapturedStderr();
  EXPECT_TRUE(bad.failed());
  EXPECT_NE(out.find("FastClearAfterSweep"), std::string::npos) << out;

  Port good;
  good.sweep();
  good.fast_clear_color();
  EXPECT_FALSE(good.failed());
}

// A store's read of a fast-cleared plane, then two fast clears in a row: the second meets the
// read's write-back at the epoch while the plane counts as all fresh.
TEST(RtlPortAsserts, WriteBackBeforeClear) {
  Port bad;
  bad.sweep();
  bad.fast_clear_color();
  bad.read(0);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  bad.fast_clear_color();
  bad.fast_clear_color();
  const std::string out = testing::internal::GetCapturedStdout() +
                          testing::internal::GetCapturedStderr();
  EXPECT_TRUE(bad.failed());
  EXPECT_NE(out.find("WriteBackBeforeClear"), std::string::npos) << out;

  Port good;  // the driver's order: one fast clear (a tile's setup cycle) after the store
  good.sweep();
  good.fast_clear_color();
  good.read(0);
  good.fast_clear_color();
  good.tick();
  good.fast_clear_color();
  EXPECT_FALSE(good.failed());
}

}  // namespace
}  // namespace zb
