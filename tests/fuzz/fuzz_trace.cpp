// libFuzzer: the trace reader on arbitrary bytes. What it accepts must be canonical (written
// back byte for byte; a version 4 file as the same bytes of the current version) and replay on
// the golden model (frames up to 256 x 256, for speed).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "rop/rop.h"
#include "io/trace.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  zb::Trace trace;
  try {
    trace = zb::parse_trace(bytes, "fuzz.zbt");
  } catch (const zb::TraceError& e) {
    // The reader's one exception: one line naming the file and the byte.
    const std::string what = e.what();
    FUZZ_CHECK(what.rfind("trace 'fuzz.zbt': byte ", 0) == 0);
    FUZZ_CHECK(what.find_first_of("\r\n") == std::string::npos);
    return 0;
  }
  std::string canonical = bytes;  // the version word, bytes 8 to 11, as the writer's
  const std::string written = zb::serialize_trace(trace);
  FUZZ_CHECK(written.size() == bytes.size());
  canonical.replace(8, 4, written, 8, 4);
  FUZZ_CHECK(written == canonical);
  if (trace.width * trace.height > 256 * 256) return 0;
  zb::GoldenRop rop;
  const std::vector<zb::PassStats> stats = zb::replay_trace(trace, rop);
  FUZZ_CHECK(stats.size() == trace.passes.size());
  const zb::Framebuffer& fb = rop.framebuffer();
  FUZZ_CHECK(fb.color.size() == size_t(trace.width) * size_t(trace.height));
  for (uint32_t z : fb.depth) FUZZ_CHECK(z <= zb::depth_max(trace.depth_bits));
  return 0;
}
