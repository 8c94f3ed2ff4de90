// zb_conf_adapter around zb_ref_rop, or with ZB_REF_PIPE around its pipelined variant zb_ref_pipe
// (conformance/ref/README.md): the conformance testbench's DUT interface (docs/conformance.md
// "The adapter") on the reference DUT. Both speak pixels a clock, so the adapter only narrows and
// widens: depth and peel to DEPTH_BITS, the coverage count to its width. Only zb_ref_rop with
// ZB_REF_FULL has the accumulation plane (planes_o = 5'b11111); the others 5'b01111. No retire
// port (the valids tied low).
// The testbench instantiates the adapter as zb_conf_adapter whatever its file is called.
/* verilator lint_off DECLFILENAME */
module zb_conf_adapter #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 16,
  parameter int TILE_H      = 16,
  // The testbench passes every adapter these: BEAT is zb_rop's tile-port width (this DUT takes
  // a pixel a clock), WEIGHT_BITS the accumulate blend's (unused by zb_ref_pipe).
  /* verilator lint_off UNUSEDPARAM */
  parameter int BEAT        = 8,
  parameter int WEIGHT_BITS = 4,
  /* verilator lint_on UNUSEDPARAM */
  parameter int ACC_BITS    = 16,  // the accumulation word's widths (zb_ref_rop with ZB_REF_FULL)
  parameter int REV_BITS    = 8
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        state_we_i,
  input  logic [12:0] state_i,
  input  logic [15:0] tile_x0_i,
  input  logic [15:0] tile_y0_i,
  input  logic        ld_valid_i,
  output logic        ld_ready_o,
  input  logic [31:0] ld_color_i,
  input  logic [31:0] ld_depth_i,
  input  logic [7:0]  ld_cov_i,
  input  logic [31:0] ld_peel_i,
  input  logic [4*ACC_BITS+REV_BITS-1:0] ld_acc_i,
  input  logic        frag_valid_i,
  output logic        frag_ready_o,
  input  logic [15:0] frag_x_i,
  input  logic [15:0] frag_y_i,
  input  logic [31:0] frag_z_i,
  input  logic [31:0] frag_rgba_i,
  input  logic [7:0]  frag_cov_i,
  output logic        idle_o,
  input  logic        st_start_i,
  output logic        st_valid_o,
  output logic [31:0] st_color_o,
  output logic [31:0] st_depth_o,
  output logic [7:0]  st_cov_o,
  output logic [31:0] st_peel_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] st_acc_o,
  output logic [4:0]  planes_o,
  output logic        ret_d_valid_o,
  output logic [31:0] ret_d_pixel_o,
  output logic        ret_dwe_o,
  output logic [31:0] ret_wdepth_o,
  output logic        ret_vwe_o,
  output logic [7:0]  ret_wcov_o,
  output logic        ret_c_valid_o,
  output logic [31:0] ret_c_pixel_o,
  output logic        ret_cwe_o,
  output logic [31:0] ret_wcolor_o,
  output logic        ret_awe_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] ret_wacc_o
);

  localparam int D    = DEPTH_BITS;
  localparam int CovW = $clog2(COV_SAMPLES + 1);

  logic [D-1:0]    st_depth, st_peel;
  logic [CovW-1:0] st_cov;

`ifdef ZB_REF_PIPE
  // No accumulate or coverage blend: the accumulation word and the fragment's coverage unread.
  zb_ref_pipe #(
    .DEPTH_BITS (DEPTH_BITS),
    .COV_SAMPLES(COV_SAMPLES),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H)
  ) u_pipe (
    .clk_i,
    .rst_ni,
    .state_we_i,
    .state_i,
    .tile_x0_i,
    .tile_y0_i,
    .ld_valid_i,
    .ld_ready_o,
    .ld_color_i,
    .ld_depth_i  (ld_depth_i[D-1:0]),
    .ld_cov_i    (ld_cov_i[CovW-1:0]),
    .ld_peel_i   (ld_peel_i[D-1:0]),
    .frag_valid_i,
    .frag_ready_o,
    .frag_x_i,
    .frag_y_i,
    .frag_z_i    (frag_z_i[D-1:0]),
    .frag_rgba_i,
    .idle_o,
    .st_start_i,
    .st_valid_o,
    .st_color_o,
    .st_depth_o  (st_depth),
    .st_cov_o    (st_cov),
    .st_peel_o   (st_peel)
  );
  assign st_acc_o = '0;
  logic unused_pipe;
  assign unused_pipe = ^ld_acc_i;
`else
  zb_ref_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .COV_SAMPLES(COV_SAMPLES),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .ACC_BITS   (ACC_BITS),
    .REV_BITS   (REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS)
  ) u_ref (
    .clk_i,
    .rst_ni,
    .state_we_i,
    .state_i,
    .tile_x0_i,
    .tile_y0_i,
    .ld_valid_i,
    .ld_ready_o,
    .ld_color_i,
    .ld_depth_i  (ld_depth_i[D-1:0]),
    .ld_cov_i    (ld_cov_i[CovW-1:0]),
    .ld_peel_i   (ld_peel_i[D-1:0]),
    .ld_acc_i,
    .frag_valid_i,
    .frag_ready_o,
    .frag_x_i,
    .frag_y_i,
    .frag_z_i    (frag_z_i[D-1:0]),
    .frag_rgba_i,
    .frag_cov_i  (frag_cov_i[CovW-1:0]),
    .idle_o,
    .st_start_i,
    .st_valid_o,
    .st_color_o,
    .st_depth_o  (st_depth),
    .st_cov_o    (st_cov),
    .st_peel_o   (st_peel),
    .st_acc_o
  );
`endif

  assign st_depth_o = 32'(st_depth);
  assign st_peel_o  = 32'(st_peel);
  assign st_cov_o   = 8'(st_cov);
`ifdef ZB_REF_PIPE
  assign planes_o   = 5'b01111;  // colour, depth, coverage, peel: no accumulation plane
`elsif ZB_REF_FULL
  assign planes_o   = 5'b11111;  // colour, depth, coverage, peel, accumulation
`else
  assign planes_o   = 5'b01111;  // colour, depth, coverage, peel: no accumulation plane
`endif

  // No retire port: the testbench runs it without --lockstep.
  assign ret_d_valid_o = 1'b0;
  assign ret_d_pixel_o = '0;
  assign ret_dwe_o     = 1'b0;
  assign ret_wdepth_o  = '0;
  assign ret_vwe_o     = 1'b0;
  assign ret_wcov_o    = '0;
  assign ret_c_valid_o = 1'b0;
  assign ret_c_pixel_o = '0;
  assign ret_cwe_o     = 1'b0;
  assign ret_wcolor_o  = '0;
  assign ret_awe_o     = 1'b0;
  assign ret_wacc_o    = '0;

  // The ports' bits above DEPTH_BITS and the coverage width. Lint leaves signals named unused*
  // alone (Verilator's default -unused-regexp).
  logic unused_inputs;
  assign unused_inputs = ^{frag_cov_i, ld_depth_i, ld_peel_i, ld_cov_i, frag_z_i};

endmodule
