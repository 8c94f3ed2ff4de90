// Trace files: a frame's fragment streams and pass states, so that a run on either backend is
// reproduced from the file alone. Format in docs/datapath.md, "Trace files".
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "rop/backend.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"

namespace zb {

struct TracePass {
  std::string name;
  std::vector<FrameOp> frame_ops;  // done before the pass (background already substituted)
  RopState state;
  std::vector<Fragment> fragments;
};

struct Trace {
  int width = 0;
  int height = 0;
  int depth_bits = kDefaultDepthBits;
  int coverage_samples = kDefaultCoverageSamples;
  WboitFormat wboit;  // accumulation, revealage and weight widths
  Rgba8 clear_color;
  std::vector<TracePass> passes;
  std::vector<FrameOp> final_ops;  // after the last pass
};

// A malformed trace file; what() names the file, the byte offset and what is wrong.
struct TraceError : std::runtime_error {
  explicit TraceError(const std::string& what, size_t at = 0) : std::runtime_error(what), byte(at) {}
  size_t byte;  // the byte offset of a malformed field (0 when the file could not be read)
};

// One fragment record of a trace ("Trace files": 20 bytes), the unit a fragment stream in memory
// is made of as well (the virtual platform's DRAW command, docs/systemc.md).
constexpr size_t kTraceFragmentBytes = 20;
void encode_fragment(uint8_t* rec, const Fragment& f);  // rec[0, kTraceFragmentBytes)
void encode_fragment(std::string& out, const Fragment& f);
// Decodes `rec` and checks it against the frame (inside width x height, depth within
// depth_bits, coverage at most `samples`, no reserved flag); false, with what is wrong in `why`
// when given, for a fragment that fails.
bool decode_fragment(const uint8_t* rec, int width, int height, int depth_bits, int samples,
                     Fragment& f, std::string* why = nullptr);
// Decodes records[0, n) into out[0, n); returns n, or the index of the first that fails, with
// what is wrong in `why`.
size_t decode_fragments(const uint8_t* records, size_t n, int width, int height, int depth_bits,
                        int samples, Fragment* out, std::string& why);

// The trace of rendering `rs` with `plan`: every pass's state and fragments.
Trace make_trace(const RasterizedScene& rs, const PassPlan& plan);

// Serialises `trace`. Returns an empty string, or what went wrong (no partial file is left).
std::string write_trace(const std::string& path, const Trace& trace);
std::string serialize_trace(const Trace& trace);
// serialize_trace(trace).size(), without making it.
size_t serialized_size(const Trace& trace);
// The same bytes into out[0, serialized_size(trace)): a buffer of the caller's, or memory in place.
void serialize_trace(const Trace& trace, uint8_t* out);

// What a serialised trace holds.
struct TraceCounts {
  size_t bytes = 0;
  uint64_t passes = 0, fragments = 0;
};
// serialize_trace(make_trace(rs, plan)) without the Trace: each pass's fragments encoded into
// `out` as the feeder hands them over, the same bytes. `out` holds `capacity` bytes, at least
// trace_bound(rs, plan) (std::logic_error, having written no byte past it, if not).
TraceCounts serialize_trace(const RasterizedScene& rs, const PassPlan& plan, uint8_t* out,
                            size_t capacity);
// An upper bound of that trace's bytes, without running the feeder: a pass draws at most the
// stored fragments (triangles or edges), a coverage pass at most the pixels of its triangles'
// boxes.
size_t trace_bound(const RasterizedScene& rs, const PassPlan& plan);

// Where scan_trace reads a trace from: bytes [0, size()), read in order. A pointer read()
// returns stays valid until the next call; read() may throw (scan_trace passes it on).
class TraceBytes {
 public:
  virtual ~TraceBytes() = default;
  virtual size_t size() const = 0;
  virtual const uint8_t* read(size_t at, size_t n) = 0;
};

// What scan_trace calls as it reads, each when set: the header (a Trace without passes); each
// pass's head (its name, operations and state; valid until the next call) with its fragment
// count, then its fragments block by block as they are read (a block valid until the next
// call), then pass_end; the final operations.
struct TraceScan {
  std::function<void(const Trace&)> header;
  std::function<void(const TracePass&, uint64_t fragments)> pass;
  std::function<void(const Fragment*, size_t)> fragments;
  std::function<void()> pass_end;
  std::function<void(const std::vector<FrameOp>&)> final_ops;
};
// Reads and validates a trace as it goes, the calls for what came before a fault made; throws
// TraceError at the fault. Fragments are read in blocks of at most kTraceReadRecords.
constexpr size_t kTraceReadRecords = 4096;
void scan_trace(TraceBytes& bytes, const std::string& name, const TraceScan& scan);
void scan_trace(std::string_view bytes, const std::string& name, const TraceScan& scan);

// Reads and validates a trace; throws TraceError.
Trace read_trace(const std::string& path);
Trace parse_trace(std::string_view bytes, const std::string& name);

// Runs every pass of the trace on `backend`; returns the stats of each pass.
std::vector<PassStats> replay_trace(const Trace& trace, Backend& backend);

}  // namespace zb
