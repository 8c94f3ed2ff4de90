#include "zb_sc_types.h"

namespace zb::sc {

PassCommand PassCommand::begin_frame(int w, int h, int depth_bits, Rgba8 clear, int samples,
                                     const WboitFormat& wboit) {
  PassCommand c;
  c.kind = Kind::kBeginFrame;
  c.width = w;
  c.height = h;
  c.depth_bits = depth_bits;
  c.clear = clear;
  c.coverage_samples = samples;
  c.wboit = wboit;
  return c;
}

PassCommand PassCommand::begin_pass(const RopState& s, uint64_t fragments) {
  PassCommand c;
  c.kind = Kind::kBeginPass;
  c.state = s;
  c.fragments = fragments;
  return c;
}

PassCommand PassCommand::end_pass() { return PassCommand{}; }

PassCommand PassCommand::frame_op(const FrameOp& op) {
  PassCommand c;
  c.kind = Kind::kFrameOp;
  c.op = op;
  return c;
}

std::ostream& operator<<(std::ostream& os, const PassCommand& c) {
  switch (c.kind) {
    case PassCommand::Kind::kBeginFrame:
      return os << "begin_frame " << c.width << "x" << c.height;
    case PassCommand::Kind::kBeginPass: return os << "begin_pass " << c.fragments;
    case PassCommand::Kind::kEndPass: return os << "end_pass";
    case PassCommand::Kind::kFrameOp: return os << "frame_op " << to_string(c.op.kind);
  }
  return os;
}

}  // namespace zb::sc

namespace zb {

std::ostream& operator<<(std::ostream& os, const Fragment& f) {
  return os << "(" << f.x << "," << f.y << " z=" << f.z << ")";
}

std::ostream& operator<<(std::ostream& os, const PassStats& s) {
  return os << "in=" << s.fragments_in << " passed=" << s.fragments_passed
            << " cycles=" << s.cycles;
}

}  // namespace zb
