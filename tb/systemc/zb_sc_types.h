// The transactions of the SystemC modules (zb_golden_sc.h, zb_rtl_sc.h): pass commands on one
// fifo, fragments on another, a PassStats back per end_pass. docs/systemc.md.
#pragma once

#include <cstdint>
#include <ostream>

#include "rop/backend.h"
#include "rop/fragment.h"

namespace zb::sc {

// One call of the Backend interface (backend.h) as a transaction. begin_pass names how many
// fragments of the fragment fifo belong to the pass; end_pass answers with one PassStats.
struct PassCommand {
  enum class Kind : uint8_t { kBeginFrame, kBeginPass, kEndPass, kFrameOp } kind = Kind::kEndPass;
  // kBeginFrame
  int width = 0, height = 0, depth_bits = kDefaultDepthBits;
  Rgba8 clear{};
  int coverage_samples = kDefaultCoverageSamples;
  WboitFormat wboit{};
  // kBeginPass
  RopState state{};
  uint64_t fragments = 0;
  // kFrameOp
  FrameOp op{};

  static PassCommand begin_frame(int w, int h, int depth_bits, Rgba8 clear, int samples,
                                 const WboitFormat& wboit);
  static PassCommand begin_pass(const RopState& s, uint64_t fragments);
  static PassCommand end_pass();
  static PassCommand frame_op(const FrameOp& op);
};

// sc_fifo<T> needs operator<< for T (sc_fifo::print); these print a short summary.
std::ostream& operator<<(std::ostream& os, const PassCommand& c);

}  // namespace zb::sc

namespace zb {
std::ostream& operator<<(std::ostream& os, const Fragment& f);
std::ostream& operator<<(std::ostream& os, const PassStats& s);
}  // namespace zb
