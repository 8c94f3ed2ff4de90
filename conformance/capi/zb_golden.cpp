// The C API over GoldenRop (zb_golden.h). Each call checks its arguments against the rules of
// docs/datapath.md before the model sees them, so the model's own checks (which throw) are never
// reached from here; a catch-all turns anything left into a status all the same. A stream file
// is checked word by word by the kit's decoder (vectors.h decode_stream) before it is replayed.
#include "zb_golden.h"

#include <cstring>

#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "geometry/geometry.h"
#include "rop/rop.h"
#include "history/history_report.h"
#include "vectors.h"

struct zb_golden {
  zb::GoldenRop rop;
  bool started = false;  // a pass or a frame operation has been: the widths are fixed
  bool in_pass = false;
  std::string error;  // the last call's, "" after a success
};

namespace {

// A failed create or replay_file has no handle to hold its error: this thread's, as errno and
// dlerror() do.
thread_local std::string handleless_error;

// A failed call's status and line; the line is what is wrong, then how to fix it.
struct Failure {
  int status;
  std::string line;
};

uint32_t pack(zb::Rgba8 c) {
  return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24;
}
zb::Rgba8 unpack(uint32_t w) {
  return {uint8_t(w), uint8_t(w >> 8), uint8_t(w >> 16), uint8_t(w >> 24)};
}

template <class T>
void put(T* out, T value) {
  if (out) *out = value;
}

// `body`'s Failure (an empty line on success), or any exception it throws as one.
template <class Body>
Failure caught(Body body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return {ZB_ENOMEM, "out of memory"};
  } catch (const std::exception& e) {
    return {ZB_EINTERNAL, fmt::format("internal error of the golden model, please report it: {}", e.what())};
  } catch (...) {
    return {ZB_EINTERNAL, "internal error of the golden model, please report it"};
  }
}

// Runs `body(*g)` with g's error cleared, and turns a failure into a status and g's line.
// `call` names the function.
template <class Body>
int guarded(zb_golden* g, const char* call, Body body) {
  if (!g) {
    handleless_error = fmt::format("{}: the handle is NULL (create one with zb_golden_create)", call);
    return ZB_EHANDLE;
  }
  g->error.clear();
  const Failure f = caught([&] { return body(*g); });
  if (f.status != ZB_OK) g->error = fmt::format("{}: {}", call, f.line);
  return f.status;
}

// The same for a call that makes a handle: its error is the thread's.
template <class Body>
int handleless(const char* call, Body body) {
  handleless_error.clear();
  const Failure f = caught(body);
  if (f.status != ZB_OK) handleless_error = fmt::format("{}: {}", call, f.line);
  return f.status;
}

const Failure kOk{ZB_OK, ""};
const char* const kNoHandle = "out is NULL (pass the address of a zb_golden* to receive the handle)";

Failure check_pixel(const zb::Framebuffer& fb, int x, int y) {
  if (x < 0 || x >= fb.width || y < 0 || y >= fb.height)
    return {ZB_EARG, fmt::format("pixel ({}, {}) is outside the {}x{} frame (x 0 to {}, y 0 to {})",
                                 x, y, fb.width, fb.height, fb.width - 1, fb.height - 1)};
  return kOk;
}

Failure check_plane(int plane) {
  if (plane < ZB_PLANE_COLOR || plane > ZB_PLANE_REVEAL)
    return {ZB_EARG, fmt::format("plane {} is not a plane (0 colour, 1 depth, 2 coverage, 3 peel, "
                                 "4 to 7 accumulation R, G, B, A, 8 revealage)", plane)};
  return kOk;
}

// Pixel i of a plane that check_plane accepted.
uint32_t plane_value(const zb::Framebuffer& fb, int plane, size_t i) {
  switch (plane) {
    case ZB_PLANE_COLOR: return pack(fb.color[i]);
    case ZB_PLANE_DEPTH: return fb.depth[i];
    case ZB_PLANE_COVERAGE: return fb.coverage[i];
    case ZB_PLANE_PEEL: return fb.peel[i];
    case ZB_PLANE_REVEAL: return fb.reveal_at(i);
    default: return fb.accum_at(i)[size_t(plane - ZB_PLANE_ACC_R)];
  }
}

}  // namespace

extern "C" {

int zb_golden_create(zb_golden** out, int width, int height, int depth_bits,
                     int coverage_samples, uint32_t clear_rgba) {
  return handleless("zb_golden_create", [&]() -> Failure {
    if (!out) return {ZB_EARG, kNoHandle};
    *out = nullptr;
    if (width < 1 || width > zb::kMaxFrameSize || height < 1 || height > zb::kMaxFrameSize)
      return {ZB_EARG, fmt::format("frame {}x{} is out of range (width and height 1 to {})", width,
                                   height, zb::kMaxFrameSize)};
    if (depth_bits < zb::kMinDepthBits || depth_bits > zb::kMaxDepthBits)
      return {ZB_EARG, fmt::format("depth_bits {} is out of range ({} to {})", depth_bits,
                                   zb::kMinDepthBits, zb::kMaxDepthBits)};
    if (!zb::valid_coverage_samples(coverage_samples))
      return {ZB_EARG, fmt::format("coverage_samples {} is not 1, 2, 4, 8 or 16", coverage_samples)};
    try {
      auto g = std::make_unique<zb_golden>();
      g->rop.begin_frame(width, height, depth_bits, unpack(clear_rgba), coverage_samples);
      *out = g.release();
    } catch (const std::bad_alloc&) {
      return {ZB_ENOMEM, fmt::format("out of memory for a {}x{} frame (choose a smaller one)",
                                     width, height)};
    }
    return kOk;
  });
}

namespace {

// A test's stream.hex into `t`, or the failure naming the file (and the line).
Failure read_stream(const char* stream_path, zb::Trace& t) {
  if (!stream_path) return {ZB_EARG, "stream_path is NULL (give a test's stream.hex)"};
  try {
    t = zb::conformance::read_stream(stream_path);
  } catch (const zb::TraceError& e) {
    return {ZB_EARG, e.what()};
  }
  return kOk;
}

}  // namespace

int zb_golden_replay_file(zb_golden** out, const char* stream_path) {
  return handleless("zb_golden_replay_file", [&]() -> Failure {
    if (!out) return {ZB_EARG, kNoHandle};
    *out = nullptr;
    zb::Trace t;
    if (const Failure f = read_stream(stream_path, t); f.status != ZB_OK) return f;
    auto g = std::make_unique<zb_golden>();
    try {
      zb::replay_trace(t, g->rop);
    } catch (const std::bad_alloc&) {
      return {ZB_ENOMEM, fmt::format("{}: out of memory for its {}x{} frame", stream_path,
                                     t.width, t.height)};
    }
    g->started = true;
    *out = g.release();
    return kOk;
  });
}

int zb_golden_pixel_history(const char* stream_path, int x, int y, char* json, size_t size,
                            size_t* needed) {
  return handleless("zb_golden_pixel_history", [&]() -> Failure {
    zb::Trace t;
    if (const Failure f = read_stream(stream_path, t); f.status != ZB_OK) return f;
    if (x < 0 || y < 0 || x >= t.width || y >= t.height)
      return {ZB_EARG, fmt::format("pixel ({}, {}) is outside the {}x{} frame of {}", x, y, t.width,
                                   t.height, stream_path)};
    const std::string text =
        zb::history_json(zb::conformance::stream_history(t, {{x, y}}), stream_path, "");
    if (needed) *needed = text.size() + 1;
    if (!json && size == 0) return kOk;  // the length asked for
    if (!json || size < text.size() + 1)
      return {ZB_EARG, fmt::format("json holds {} bytes; the history needs {} (ask with size 0)",
                                   json ? size : 0, text.size() + 1)};
    std::memcpy(json, text.c_str(), text.size() + 1);
    return kOk;
  });
}

int zb_golden_frame_info(zb_golden* g, int* width, int* height, int* depth_bits,
                         int* coverage_samples, int* acc_bits, int* rev_bits, int* weight_bits) {
  return guarded(g, "zb_golden_frame_info", [&](zb_golden& h) -> Failure {
    const zb::Framebuffer& fb = h.rop.framebuffer();
    put(width, fb.width);
    put(height, fb.height);
    put(depth_bits, fb.depth_bits);
    put(coverage_samples, fb.coverage_samples);
    put(acc_bits, fb.wboit.acc_bits);
    put(rev_bits, fb.wboit.rev_bits);
    put(weight_bits, fb.wboit.weight_bits);
    return kOk;
  });
}

void zb_golden_destroy(zb_golden* g) { delete g; }

int zb_golden_set_wboit(zb_golden* g, int acc_bits, int rev_bits, int weight_bits) {
  return guarded(g, "zb_golden_set_wboit", [&](zb_golden& h) -> Failure {
    if (h.started)
      return {ZB_EORDER, "a pass or frame operation has been (set the widths right after "
                         "zb_golden_create)"};
    const zb::WboitFormat f{acc_bits, rev_bits, weight_bits};
    if (!zb::valid_wboit_format(f))
      return {ZB_EARG, fmt::format("acc_bits {}, rev_bits {}, weight_bits {}: the ranges are {} to "
                                   "{}, {} to {} and {} to {}", acc_bits, rev_bits, weight_bits,
                                   zb::kMinAccBits, zb::kMaxAccBits, zb::kMinRevBits,
                                   zb::kMaxRevBits, zb::kMinWeightBits, zb::kMaxWeightBits)};
    // Nothing has drawn yet, so every pixel still holds the frame's clear colour.
    const zb::Framebuffer& fb = h.rop.framebuffer();
    h.rop.begin_frame(fb.width, fb.height, fb.depth_bits, fb.color[0], fb.coverage_samples, f);
    return kOk;
  });
}

int zb_golden_set_arithmetic(zb_golden* g, const char* name) {
  return guarded(g, "zb_golden_set_arithmetic", [&](zb_golden& h) -> Failure {
    if (h.in_pass)
      return {ZB_EORDER, "a pass is open: the arithmetic changes between passes (end it with "
                         "zb_golden_end_pass first)"};
    const std::optional<zb::Arithmetic> r =
        name ? zb::parse_arithmetic(name) : std::optional<zb::Arithmetic>{};
    if (!r)
      return {ZB_EARG, zb::arithmetic_error(name ? name : "(null)")};
    h.rop.set_arithmetic(*r);
    return kOk;
  });
}

int zb_golden_begin_pass(zb_golden* g, uint32_t state) {
  return guarded(g, "zb_golden_begin_pass", [&](zb_golden& h) -> Failure {
    if (h.in_pass)
      return {ZB_EORDER, "a pass is already open (end it with zb_golden_end_pass first)"};
    zb::RopState s;
    if (state >> zb::kStateBits != 0 || !zb::unpack_state(uint16_t(state), s))
      return {ZB_EARG, fmt::format("state 0x{:x} is not a pass state register (bits 16 and up "
                                   "zero, blend [7:5] at most 6; docs/datapath.md \"The pass "
                                   "state\")", state)};
    h.rop.begin_pass(s);
    h.in_pass = true;
    h.started = true;
    return kOk;
  });
}

int zb_golden_push(zb_golden* g, int x, int y, uint32_t z, uint32_t rgba, int coverage,
                   uint32_t* wrote, uint32_t* depth, uint32_t* coverage_out, uint32_t* rgba_out) {
  put<uint32_t>(wrote, 0);
  put<uint32_t>(depth, 0);
  put<uint32_t>(coverage_out, 0);
  put<uint32_t>(rgba_out, 0);
  return guarded(g, "zb_golden_push", [&](zb_golden& h) -> Failure {
    if (!h.in_pass) return {ZB_EORDER, "no pass is open (start one with zb_golden_begin_pass)"};
    const zb::Framebuffer& fb = h.rop.framebuffer();
    if (Failure f = check_pixel(fb, x, y); f.status != ZB_OK) return f;
    if (z > zb::depth_max(fb.depth_bits))
      return {ZB_EARG, fmt::format("depth 0x{:x} exceeds the {}-bit depth (at most 0x{:x})", z,
                                   fb.depth_bits, zb::depth_max(fb.depth_bits))};
    if (coverage < 0 || coverage > fb.coverage_samples)
      return {ZB_EARG, fmt::format("coverage {} is out of range (0 to the frame's {} samples)",
                                   coverage, fb.coverage_samples)};
    zb::Fragment f;
    f.x = uint16_t(x);
    f.y = uint16_t(y);
    f.z = z;
    f.color = unpack(rgba);
    f.coverage = uint8_t(coverage);
    const zb::PixelWrites w = h.rop.process(f);
    put<uint32_t>(wrote, (w.depth ? ZB_WROTE_DEPTH : 0) | (w.coverage ? ZB_WROTE_COVERAGE : 0) |
                             (w.color ? ZB_WROTE_COLOR : 0) | (w.accum ? ZB_WROTE_ACCUM : 0) |
                             (w.layers ? ZB_WROTE_LAYERS : 0));
    put<uint32_t>(depth, w.depth ? w.z : 0);
    put<uint32_t>(coverage_out, w.coverage ? w.cov : 0);
    put<uint32_t>(rgba_out, w.color ? pack(w.rgba) : 0);
    return kOk;
  });
}

int zb_golden_end_pass(zb_golden* g, uint64_t* fragments_in, uint64_t* fragments_passed,
                       uint64_t* depth_reads, uint64_t* depth_writes, uint64_t* color_reads,
                       uint64_t* color_writes) {
  return guarded(g, "zb_golden_end_pass", [&](zb_golden& h) -> Failure {
    if (!h.in_pass) return {ZB_EORDER, "no pass is open (start one with zb_golden_begin_pass)"};
    const zb::PassStats s = h.rop.end_pass();
    h.in_pass = false;
    put(fragments_in, s.fragments_in);
    put(fragments_passed, s.fragments_passed);
    put(depth_reads, s.depth_reads);
    put(depth_writes, s.depth_writes);
    put(color_reads, s.color_reads);
    put(color_writes, s.color_writes);
    return kOk;
  });
}

int zb_golden_frame_op(zb_golden* g, int kind, uint32_t value_rgba, uint32_t depth) {
  return guarded(g, "zb_golden_frame_op", [&](zb_golden& h) -> Failure {
    if (h.in_pass)
      return {ZB_EORDER, "a pass is open: frame operations come between passes (end it with "
                         "zb_golden_end_pass first)"};
    if (kind < 0 || kind >= int(zb::kFrameOpKinds))
      return {ZB_EARG, fmt::format("kind {} is not a frame operation (0 clear colour, 1 clear "
                                   "depth, 2 copy depth to peel, 3 resolve under, 4 resolve "
                                   "wboit, 5 resolve layers)", kind)};
    zb::FrameOp op;
    op.kind = zb::FrameOpKind(kind);
    op.value = unpack(value_rgba);
    op.depth = depth;  // apply_frame_op clamps it to ZMAX
    h.rop.frame_op(op);
    h.started = true;
    return kOk;
  });
}

int zb_golden_read(zb_golden* g, int plane, int x, int y, uint32_t* value) {
  return guarded(g, "zb_golden_read", [&](zb_golden& h) -> Failure {
    if (!value) return {ZB_EARG, "value is NULL (pass the address of a uint32_t)"};
    const zb::Framebuffer& fb = h.rop.framebuffer();
    if (Failure f = check_pixel(fb, x, y); f.status != ZB_OK) return f;
    if (Failure f = check_plane(plane); f.status != ZB_OK) return f;
    *value = plane_value(fb, plane, fb.index(x, y));
    return kOk;
  });
}

int zb_golden_read_plane(zb_golden* g, int plane, uint32_t* out, size_t count) {
  return guarded(g, "zb_golden_read_plane", [&](zb_golden& h) -> Failure {
    if (Failure f = check_plane(plane); f.status != ZB_OK) return f;
    const zb::Framebuffer& fb = h.rop.framebuffer();
    const size_t n = size_t(fb.width) * size_t(fb.height);
    if (!out) return {ZB_EARG, fmt::format("out is NULL (pass an array of {} uint32_t)", n)};
    if (count != n)
      return {ZB_EARG, fmt::format("count {} is not the {}x{} frame's {} pixels (pass an array "
                                   "of width * height values)", count, fb.width, fb.height, n)};
    for (size_t i = 0; i < n; ++i) out[i] = plane_value(fb, plane, i);
    return kOk;
  });
}

const char* zb_golden_last_error(const zb_golden* g) {
  return g ? g->error.c_str() : handleless_error.c_str();
}

}  // extern "C"
