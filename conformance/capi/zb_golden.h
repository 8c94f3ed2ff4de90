/* zb_golden.h: a C API to zblend's golden model of the per-pixel datapath (docs/conformance.md
 * "The C API"; the bit-level rules are docs/datapath.md's). C99 and C++; nothing C++ crosses it.
 *
 * One handle is one frame: create it with the widths, then per pass: begin (the 13-bit pass
 * state register), push fragments one by one (each returns the writes it made), end (the
 * counters); frame operations between passes; read any pixel of any plane at any time. Or
 * replay a conformance test's stream.hex onto a new frame in one call and read whole planes.
 *
 * Every call that can fail returns a status (ZB_OK or a ZB_E* code), changes nothing when it
 * fails, and leaves one line, what is wrong and how to fix it, for zb_golden_last_error. No call
 * throws or aborts on bad input. Arguments are ints and pointers to ints, so each call maps onto
 * a DPI-C import (conformance/sv/zb_golden_pkg.sv). A handle is not safe to share across threads
 * without a lock; distinct handles are independent. */
#ifndef ZB_GOLDEN_H_
#define ZB_GOLDEN_H_

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct zb_golden zb_golden; /* opaque: one frame and its golden datapath */

/* Status of every call that can fail. */
enum {
  ZB_OK = 0,
  ZB_EARG = 1,      /* a bad argument: widths, pixel, depth, coverage, state word, plane, kind */
  ZB_EORDER = 2,    /* the call does not fit the sequence: a push outside a pass, ... */
  ZB_EHANDLE = 3,   /* a null handle */
  ZB_ENOMEM = 4,    /* the frame does not fit in memory */
  ZB_EINTERNAL = 5  /* a fault of the model itself (please report it) */
};

/* The planes of a frame (zb_golden_read), in the order of the conformance signatures. The
 * accumulation word {r, acc_A, acc_B, acc_G, acc_R} (the signatures' accum plane) is read in its
 * parts, each at most 32 bits: the four accumulation channels and the revealage. */
enum {
  ZB_PLANE_COLOR = 0, ZB_PLANE_DEPTH = 1, ZB_PLANE_COVERAGE = 2, ZB_PLANE_PEEL = 3,
  ZB_PLANE_ACC_R = 4, ZB_PLANE_ACC_G = 5, ZB_PLANE_ACC_B = 6, ZB_PLANE_ACC_A = 7,
  ZB_PLANE_REVEAL = 8
};

/* Bits of zb_golden_push's `wrote`: which planes the fragment wrote. ZB_WROTE_ACCUM: the
 * accumulation word (accumulate mode); its new value is the pixel's ZB_PLANE_ACC_* and
 * ZB_PLANE_REVEAL, read right after the push. ZB_WROTE_LAYERS: the pixel's layers (layers mode,
 * mlab-K), which stay inside the model: they show in the colour at ZB_OP_RESOLVE_LAYERS. */
enum { ZB_WROTE_DEPTH = 1, ZB_WROTE_COVERAGE = 2, ZB_WROTE_COLOR = 4, ZB_WROTE_ACCUM = 8,
       ZB_WROTE_LAYERS = 16 };

/* Frame operations (docs/datapath.md "Frame operations"), done between passes. */
enum {
  ZB_OP_CLEAR_COLOR = 0,        /* every colour := value */
  ZB_OP_CLEAR_DEPTH = 1,        /* every depth := min(depth, ZMAX) */
  ZB_OP_COPY_DEPTH_TO_PEEL = 2, /* peel := depth */
  ZB_OP_RESOLVE_UNDER = 3,      /* colour := min(255, c + m(value_c, 255 - A)) per channel */
  ZB_OP_RESOLVE_WBOIT = 4,      /* colour := from the accumulation word (datapath.md "Resolve") */
  ZB_OP_RESOLVE_LAYERS = 5      /* colour := its layers over it; the layers emptied ("8. Layers") */
};

/* Colours are packed RGBA8 words: r | g << 8 | b << 16 | a << 24 (frag_rgba_i's lane order). */

/* A frame of width x height pixels (1 to 8192 each), depth_bits (8 to 32) wide depths and
 * coverage_samples (1, 2, 4, 8 or 16) samples per pixel, cleared as a frame starts: colour
 * clear_rgba, depth ZMAX = 2^depth_bits - 1, coverage 0, peel 0, accumulation 0 and revealage
 * 1.0 at the default widths (16, 8, 4; zb_golden_set_wboit). On success *out is the handle; on
 * failure *out is NULL and zb_golden_last_error(NULL) says why. */
int zb_golden_create(zb_golden** out, int width, int height, int depth_bits,
                     int coverage_samples, uint32_t clear_rgba);

/* The accumulation planes' widths (docs/datapath.md "Parameters": acc_bits 8 to 32, rev_bits 8
 * to 16, weight_bits 0 to 16), the frame cleared again. Only before the first pass or frame
 * operation. */
int zb_golden_set_wboit(zb_golden* g, int acc_bits, int rev_bits, int weight_bits);

/* The blend arithmetic the DUT declares (docs/datapath.md "Declared arithmetic"), by name:
 * "zblend" (the default), or "<each|sum>-<zblend|round255|floor256|ceil256|round256>" with an
 * optional "-one256" (for example "sum-round255", "sum-ceil256"). It rules the alpha and additive
 * blends from the next push on; allowed between passes. */
int zb_golden_set_arithmetic(zb_golden* g, const char* name);

/* Frees the handle; NULL is allowed and does nothing. */
void zb_golden_destroy(zb_golden* g);

/* Starts a pass with the pass state register (docs/datapath.md "The pass state"): [0]
 * depth_test, [3:1] depth_func, [4] depth_write, [7:5] blend (0 to 6), [11:8] color_mask, [12]
 * peel_test, [15:13] K - 1 (layers mode); every other bit zero. Blend 5 (accumulate) writes only
 * the accumulation word, blend 6 (layers) only the pixel's K layers. Fails inside a pass. */
int zb_golden_begin_pass(zb_golden* g, uint32_t state);

/* One fragment through the datapath, in stream order: pixel (x, y), depth z (at most ZMAX),
 * colour rgba, coverage count (0 to coverage_samples; read only by the coverage blend). The
 * writes it made: *wrote holds ZB_WROTE_* bits, and *depth, *coverage_out, *rgba_out the values
 * written to those planes (0 where not written). Any output pointer may be NULL. Fails outside
 * a pass. */
int zb_golden_push(zb_golden* g, int x, int y, uint32_t z, uint32_t rgba, int coverage,
                   uint32_t* wrote, uint32_t* depth, uint32_t* coverage_out, uint32_t* rgba_out);

/* Ends the pass; its counters (docs/datapath.md "Counters"; killed = in - passed). Any output
 * pointer may be NULL. Fails outside a pass. */
int zb_golden_end_pass(zb_golden* g, uint64_t* fragments_in, uint64_t* fragments_passed,
                       uint64_t* depth_reads, uint64_t* depth_writes, uint64_t* color_reads,
                       uint64_t* color_writes);

/* A frame operation (ZB_OP_*) on the whole frame, between passes: value_rgba is read by the
 * colour clear and the resolve (the background), depth by the depth clear (clamped to ZMAX, so
 * 0xffffffff is always the far depth). Fails inside a pass. */
int zb_golden_frame_op(zb_golden* g, int kind, uint32_t value_rgba, uint32_t depth);

/* The value of pixel (x, y) of a plane (ZB_PLANE_*): a packed colour, a depth, a coverage
 * count, a peel depth, an accumulation channel or the revealage. Allowed inside a pass (the
 * planes hold every write so far). */
int zb_golden_read(zb_golden* g, int plane, int x, int y, uint32_t* value);

/* Reads a command stream, a test's stream.hex (docs/conformance.md "stream.hex"), and replays it
 * on a new frame: FRAME's widths, clear colour and accumulation widths, then every pass,
 * fragment and frame operation in order, as the exporter did to compute the test's expect
 * files. On success *out is the handle, between passes: read its planes (or go on with more
 * passes). On failure *out is NULL and zb_golden_last_error(NULL) names the file and, for a
 * malformed or truncated stream, the line (line 1 is the count): ZB_EARG for a file that cannot
 * be read or is not a valid stream, ZB_ENOMEM for a frame too big. */
int zb_golden_replay_file(zb_golden** out, const char* stream_path);

/* The history of pixel (x, y) in the replay of a stream.hex (`zblend pixel`'s JSON,
 * docs/history.md): every fragment that reached the pixel, pass by pass, the tests' outcomes,
 * the blend, what was written, the frame operations and the final value, checked by replaying
 * its writes. The JSON and its NUL go to json[0..size) when they fit; *needed (may be NULL)
 * gets their length either way, so a call with json NULL and size 0 asks for it. ZB_EARG for
 * a bad stream, a pixel outside its frame, or a json too small (left untouched);
 * zb_golden_last_error(NULL) says which. */
int zb_golden_pixel_history(const char* stream_path, int x, int y, char* json, size_t size,
                            size_t* needed);

/* The frame's widths, as created (or read from FRAME); any pointer may be NULL. */
int zb_golden_frame_info(zb_golden* g, int* width, int* height, int* depth_bits,
                         int* coverage_samples, int* acc_bits, int* rev_bits, int* weight_bits);

/* A whole plane (ZB_PLANE_*), each pixel's value as zb_golden_read gives it, row-major from row
 * 0 (the expect files' order): out[y * width + x]. count is out's length in values and must be
 * width * height. */
int zb_golden_read_plane(zb_golden* g, int plane, uint32_t* out, size_t count);

/* The error of the last call on `g`: one line, "" when it succeeded. With NULL: the last error
 * of a call in this thread that had no handle (a failed create or replay_file, or a NULL handle
 * passed). The text stays valid until the next call with the same handle (or NULL). Never
 * NULL. */
const char* zb_golden_last_error(const zb_golden* g);

#ifdef __cplusplus
}
#endif

#endif /* ZB_GOLDEN_H_ */
