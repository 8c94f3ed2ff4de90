// The suite's file formats (conformance_spec.md, docs/conformance.md "The vectors"): a trace as
// a command stream of 128-bit words, and a plane of a frame as a signature file.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "history/pixel_history.h"
#include "io/trace.h"
#include "rop/arithmetic.h"
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

// FRAME (with the accumulation planes' widths), then per pass its frame operations, PASS, its fragments and END_PASS, then the final
// frame operations and END. Frame operations are written as the trace holds them (test_trace
// clamps clear depths).
Stream encode_stream(const Trace& t);

// stream.hex back into a trace, encode_stream's inverse: every word checked against the format
// and against what the golden model accepts (widths, pixels, depths, coverage, pass states,
// frame operations, the commands' order), so replay_trace can take the result. Passes are named
// "pass-<k>" from 1; the fragments' front and prim, which the stream does not carry, are zero.
// Throws TraceError, one line: "NAME line N: what is wrong (how to fix it)"; line 1 is the count.
Trace decode_stream(const std::string& text, const std::string& name);
// decode_stream of the file at `path`; a file that cannot be read is a TraceError too.
Trace read_stream(const std::string& path);

// The histories of `pixels` in a decoded stream's replay (record_history). A stream names no
// passes (decode's "pass-<k>" count from 1), so they are shown by number, from 0 as the
// lock-step report counts them.
FrameHistory stream_history(Trace t, const std::vector<std::pair<int, int>>& pixels,
                            const Arithmetic& arithmetic = {});

// The planes, in signature order; the name in expect.<name>.hex and got.<name>.hex. kAccum is
// the accumulation word {r, acc_A, acc_B, acc_G, acc_R} (acc_R at bit 0; zb_rop's AccW bits).
enum class Plane { kColor, kDepth, kCoverage, kPeel, kAccum };
constexpr Plane kPlanes[] = {Plane::kColor, Plane::kDepth, Plane::kCoverage, Plane::kPeel,
                             Plane::kAccum};
const char* to_string(Plane p);
// 8, but 2 for coverage and accum_word_bits(f) / 4 rounded up for the accumulation word.
int hex_digits(Plane p, const WboitFormat& f);

// Pixel i (row-major) of a plane as hex_digits lower-case digits; a colour packed
// r | g << 8 | b << 16 | a << 24.
std::string plane_word(const Framebuffer& fb, Plane p, size_t i);

// One word a line (plane_word), width * height lines, row 0 first.
std::string plane_hex(const Framebuffer& fb, Plane p);

// What the testbench writes after each pass (got.passes.hex, docs/conformance.md "Every pass
// seen"): FNV-1a over 64 bits of the colour, depth, coverage and peel planes' words, plane after
// plane, each row-major (offset 0xcbf29ce484222325, prime 0x100000001b3; h = (h ^ word) * prime).
uint64_t frame_digest(const Framebuffer& fb);
struct PassDigest {
  int pass = 0;  // from 1
  uint64_t digest = 0;
};
// `trace` replayed on the golden model in `arithmetic` (replay_trace): frame_digest after each
// pass, before the next pass's frame operations, and the frame at the end.
struct GoldenReplay {
  std::vector<PassDigest> digests;
  Framebuffer frame;
};
GoldenReplay replay_golden(const Trace& trace, const Arithmetic& arithmetic);

}  // namespace zb::conformance
