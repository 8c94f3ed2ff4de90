// zb_pkg: the datapath's types (docs/datapath.md, "The pass state"): the GL depth functions, the
// blend modes and the pass state register, whose bit layout the C++ side packs (pack_state in
// cmodel/rop/fragment.cpp): [0] depth_test, [3:1] depth_func, [4] depth_write, [7:5] blend,
// [11:8] color_mask, [12] peel_test. The word's [15:13], K - 1 in layers mode, comes on zb_rop's
// state_layers_i, so builds without the layers unit keep this 13-bit register.
// Modules name its types and values qualified (zb_pkg::BlendAlpha): Yosys 0.23 reads no
// `import` statement.
package zb_pkg;

  // GL's depth functions, in GL's order (GL_NEVER + code).
  typedef enum logic [2:0] {
    DepthNever    = 3'd0,
    DepthLess     = 3'd1,
    DepthEqual    = 3'd2,
    DepthLequal   = 3'd3,
    DepthGreater  = 3'd4,
    DepthNotequal = 3'd5,
    DepthGequal   = 3'd6,
    DepthAlways   = 3'd7
  } depth_func_e;

  typedef enum logic [2:0] {
    BlendReplace    = 3'd0,
    BlendAlpha      = 3'd1,
    BlendAdditive   = 3'd2,
    BlendCoverage   = 3'd3,
    BlendUnder      = 3'd4,
    BlendAccumulate = 3'd5,  // weighted blended OIT: the accumulation word, not the colour
    BlendLayers     = 3'd6   // mlab-K: the pixel's layers (zb_layers), not the colour
  } blend_mode_e;

  // The pass state register; the first field is the most significant.
  typedef struct packed {
    logic        peel_test;    // [12] second compare, z > peel (depth peeling)
    logic [3:0]  color_mask;   // [11:8] bit c writes channel c
    blend_mode_e blend;        // [7:5]
    logic        depth_write;  // [4]
    depth_func_e depth_func;   // [3:1]
    logic        depth_test;   // [0]
  } pass_state_t;

  // The planes of the resident tile, as the tile port selects them (tile_planes_i).
  typedef struct packed {
    logic accum;     // [4] accumulation and revealage (accumulate mode)
    logic peel;      // [3]
    logic coverage;  // [2]
    logic depth;     // [1]
    logic color;     // [0]
  } planes_t;

endpackage

// Simulators without SystemVerilog's concurrent assertions and elaboration system tasks
// (Icarus 11; others define ZB_NO_SVA themselves, docs/rtl.md "Simulators"): every module
// leaves its assertions and covers out, and checks its parameters at time 0 instead.
// Every flow reads this file first.
`ifdef __ICARUS__
`define ZB_NO_SVA
`endif
`ifdef ZB_NO_SVA
`define ZB_PARAM_ERROR(msg) initial $fatal(1, msg)
`else
`define ZB_PARAM_ERROR(msg) $error(msg)
`endif

`ifdef __ICARUS__
// Icarus 11 looks a struct type up by its bare name from the scope that uses it, even when
// qualified (zb_pkg::planes_t), and aborts where that name is not imported. Yosys 0.23 reads
// no import, and Verilator needs none.
import zb_pkg::pass_state_t;
import zb_pkg::planes_t;
`endif
