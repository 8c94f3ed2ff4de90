// zb_golden_pkg: zblend's golden model of the pixel datapath, as DPI-C imports
// (docs/conformance.md "The DPI-C package"). The calls are the C API's (conformance/capi/
// zb_golden.h) under the same names; their C side is conformance/sv/zb_golden_dpi.cpp, which a
// simulator links with zbgolden_c and zbmodel. Every call but destroy and last_error returns a
// status: ZB_OK, or a ZB_E* code with one line for zb_golden_last_error(handle).
package zb_golden_pkg;

  // Status of every call that can fail.
  localparam int ZB_OK        = 0;
  localparam int ZB_EARG      = 1;  // widths, pixel, depth, coverage, state word, plane, kind
  localparam int ZB_EORDER    = 2;  // a push outside a pass, a frame operation inside one, ...
  localparam int ZB_EHANDLE   = 3;  // a null handle
  localparam int ZB_ENOMEM    = 4;
  localparam int ZB_EINTERNAL = 5;

  // Planes (zb_golden_read), in the order of the conformance signatures.
  localparam int ZB_PLANE_COLOR    = 0;
  localparam int ZB_PLANE_DEPTH    = 1;
  localparam int ZB_PLANE_COVERAGE = 2;
  localparam int ZB_PLANE_PEEL     = 3;
  localparam int ZB_PLANE_ACC_R    = 4;  // the accumulation word's parts
  localparam int ZB_PLANE_ACC_G    = 5;
  localparam int ZB_PLANE_ACC_B    = 6;
  localparam int ZB_PLANE_ACC_A    = 7;
  localparam int ZB_PLANE_REVEAL   = 8;

  // Bits of zb_golden_push's `wrote`.
  localparam int unsigned ZB_WROTE_DEPTH    = 32'd1;
  localparam int unsigned ZB_WROTE_COVERAGE = 32'd2;
  localparam int unsigned ZB_WROTE_COLOR    = 32'd4;
  localparam int unsigned ZB_WROTE_ACCUM    = 32'd8;  // the word: read its planes after the push
  localparam int unsigned ZB_WROTE_LAYERS   = 32'd16; // the layers: seen in the colour at the resolve

  // Frame operations (docs/datapath.md "Frame operations"), between passes.
  localparam int ZB_OP_CLEAR_COLOR        = 0;
  localparam int ZB_OP_CLEAR_DEPTH        = 1;
  localparam int ZB_OP_COPY_DEPTH_TO_PEEL = 2;
  localparam int ZB_OP_RESOLVE_UNDER      = 3;
  localparam int ZB_OP_RESOLVE_WBOIT      = 4;
  localparam int ZB_OP_RESOLVE_LAYERS     = 5;

  // Colours are packed RGBA8: r | g << 8 | b << 16 | a << 24 (frag_rgba_i's lane order).

  // A frame: width x height (1 to 8192), depth_bits (8 to 32), coverage_samples (1, 2, 4, 8,
  // 16), cleared to clear_rgba, the far depth, coverage 0, peel 0, accumulation 0 and
  // revealage 1.0. On failure handle is null and zb_golden_last_error(null) says why.
  import "DPI-C" zb_dpi_create = function int zb_golden_create(
      output chandle handle, input int width, input int height, input int depth_bits,
      input int coverage_samples, input int unsigned clear_rgba);

  import "DPI-C" zb_dpi_destroy = function void zb_golden_destroy(input chandle handle);

  // The accumulation planes' widths (default 16, 8, 4), before the first pass or frame operation.
  import "DPI-C" zb_dpi_set_wboit = function int zb_golden_set_wboit(
      input chandle handle, input int acc_bits, input int rev_bits, input int weight_bits);

  // The blend arithmetic the DUT declares, by name (docs/datapath.md "Declared arithmetic").
  import "DPI-C" zb_dpi_set_arithmetic = function int zb_golden_set_arithmetic(
      input chandle handle, input string name);

  // The 16-bit pass state register (docs/datapath.md "The pass state"; zb_pass_state below).
  import "DPI-C" zb_dpi_begin_pass = function int zb_golden_begin_pass(
      input chandle handle, input int unsigned state);

  // One fragment, in stream order; the writes it made: wrote holds ZB_WROTE_* bits, and depth,
  // coverage_out and rgba_out the values written (0 where not written).
  import "DPI-C" zb_dpi_push = function int zb_golden_push(
      input chandle handle, input int x, input int y, input int unsigned z,
      input int unsigned rgba, input int coverage, output int unsigned wrote,
      output int unsigned depth, output int unsigned coverage_out, output int unsigned rgba_out);

  // The pass's counters (docs/datapath.md "Counters").
  import "DPI-C" zb_dpi_end_pass = function int zb_golden_end_pass(
      input chandle handle, output longint unsigned fragments_in,
      output longint unsigned fragments_passed, output longint unsigned depth_reads,
      output longint unsigned depth_writes, output longint unsigned color_reads,
      output longint unsigned color_writes);

  // A frame operation (ZB_OP_*), between passes; depth is clamped to the far depth.
  import "DPI-C" zb_dpi_frame_op = function int zb_golden_frame_op(
      input chandle handle, input int kind, input int unsigned value_rgba,
      input int unsigned depth);

  // Pixel (x, y) of a plane (ZB_PLANE_*).
  import "DPI-C" zb_dpi_read = function int zb_golden_read(
      input chandle handle, input int plane, input int x, input int y,
      output int unsigned value);

  // The last call's error on this handle ("" after a success); null: a failed create's.
  import "DPI-C" zb_dpi_last_error = function string zb_golden_last_error(input chandle handle);

  // The pass state register from its fields: depth_func and blend as docs/datapath.md codes
  // them (less = 1, ...; replace 0, alpha 1, additive 2, coverage 3, under 4, accumulate 5).
  function automatic int unsigned zb_pass_state(input bit depth_test, input bit [2:0] depth_func,
                                                input bit depth_write, input bit [2:0] blend,
                                                input bit [3:0] color_mask, input bit peel_test);
    return {19'd0, peel_test, color_mask, blend, depth_write, depth_func, depth_test};
  endfunction

  // A layers-mode state (blend 6) keeping k layers a pixel (1 to 8): K - 1 at [15:13].
  function automatic int unsigned zb_layers_state(input int unsigned state, input int unsigned k);
    return (state & 32'h1fff) | ((k - 32'd1) & 32'd7) << 13;
  endfunction

  // A packed colour from its channels.
  function automatic int unsigned zb_rgba(input bit [7:0] r, input bit [7:0] g, input bit [7:0] b,
                                          input bit [7:0] a);
    return {a, b, g, r};
  endfunction

endpackage
