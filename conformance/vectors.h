// The suite's file formats (conformance_spec.md, docs/conformance.md "The vectors"): a trace as
// a command stream of 128-bit words, and a plane of a frame as a signature file.
#pragma once

#include <cstdint>
#include <string>

#include "io/trace.h"
#include "rop/framebuffer.h"

namespace zb::conformance {

// Command opcodes, bits [127:120] of a stream word.
enum Opcode : uint8_t {
  kOpFrame = 0x01, kOpPass = 0x02, kOpFrag = 0x03, kOpEndPass = 0x04, kOpFrameOp = 0x05,
  kOpEnd = 0x06,
};

struct Stream {
  std::string hex;        // stream.hex: the count line, then one word a line
  uint64_t words = 0;     // commands after the count line, FRAME to END
  uint64_t fragments = 0;
};

// FRAME, then per pass its frame operations, PASS, its fragments and END_PASS, then the final
// frame operations and END. Frame operations are written as the trace holds them (test_trace
// clamps clear depths).
Stream encode_stream(const Trace& t);

// The planes, in signature order; the name in expect.<name>.hex and got.<name>.hex.
enum class Plane { kColor, kDepth, kCoverage, kPeel };
constexpr Plane kPlanes[] = {Plane::kColor, Plane::kDepth, Plane::kCoverage, Plane::kPeel};
const char* to_string(Plane p);
int hex_digits(Plane p);  // 8, but 2 for coverage

// Pixel i (row-major) of a plane; a colour packed r | g << 8 | b << 16 | a << 24.
uint32_t plane_value(const Framebuffer& fb, Plane p, size_t i);

// One lower-case hex word a line, hex_digits(p) wide, width * height lines, row 0 first.
std::string plane_hex(const Framebuffer& fb, Plane p);

}  // namespace zb::conformance
