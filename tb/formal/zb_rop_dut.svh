// zb_rop at the formal parameters, as the zb_rop-level harnesses (zb_stream_check,
// zb_raw_check, zb_paths_cover) drive and observe it: the parameter and port list that follows
// a harness's `module NAME`, its local widths, and the instance `dut` (taps name dut.*). Every
// zb_rop input is a free harness input; the harness constrains them with assumptions.
#(
  parameter int unsigned DEPTH_BITS  = 8,
  parameter int unsigned TILE_W      = 2,
  parameter int unsigned TILE_H      = 2,
  parameter int unsigned CNT_W       = 2,
  parameter int unsigned COV_SAMPLES = 1,
  parameter int unsigned WINDOW      = 2,
  parameter int unsigned BEAT        = 2,
  parameter int unsigned ACC_BITS    = 8,   // the accumulation word at its narrowest: 40 bits
  parameter int unsigned REV_BITS    = 8,
  parameter int unsigned WEIGHT_BITS = 0,
  parameter int unsigned DEPTH_GEN   = 2    // the depth banks' generation bits (TILE_OPS)
) (
  input logic                            clk_i,
  input logic                            rst_ni,
  input logic                            state_we_i,
  input zb_pkg::pass_state_t             state_i,
  input logic [15:0]                     tile_x0_i,
  input logic [15:0]                     tile_y0_i,
  input logic                            frag_valid_i,
  input logic [15:0]                     frag_x_i,
  input logic [15:0]                     frag_y_i,
  input logic [DEPTH_BITS-1:0]           frag_z_i,
  input logic [31:0]                     frag_rgba_i,
  input logic [$clog2(COV_SAMPLES+1)-1:0] frag_cov_i,
  input logic                            stall_i,
  input logic                            tile_req_i,
  input logic                            tile_we_i,
  input logic                            tile_clear_i,
  input zb_pkg::planes_t                 tile_planes_i,
  input logic [$clog2(TILE_W*TILE_H/BEAT)-1:0] tile_addr_i,
  input logic [BEAT*32-1:0]              tile_wcolor_i,
  input logic [BEAT*DEPTH_BITS-1:0]      tile_wdepth_i,
  input logic [BEAT*$clog2(COV_SAMPLES+1)-1:0] tile_wcov_i,
  input logic [BEAT*DEPTH_BITS-1:0]      tile_wpeel_i,
  input logic [BEAT*(4*ACC_BITS+REV_BITS)-1:0] tile_wacc_i,
  input logic                            cnt_clear_i
);
  localparam int unsigned AddrW = $clog2(TILE_W * TILE_H);
  localparam int unsigned XW    = $clog2(TILE_W);
  localparam int unsigned YW    = $clog2(TILE_H);
  localparam int unsigned CovW  = $clog2(COV_SAMPLES + 1);
  localparam int unsigned CntW  = 6;   // harness counters: more than the fragments in flight
  localparam int unsigned AccW  = 4 * ACC_BITS + REV_BITS;

  logic                  frag_ready, busy;
  logic                  mon_x4_valid, mon_dwe, mon_vwe, mon_x11_valid, mon_cwe;
  logic [AddrW-1:0]      mon_x4_addr, mon_x11_addr;
  logic [DEPTH_BITS-1:0] mon_wdepth;
  logic [CovW-1:0]       mon_wcov;
  logic [31:0]           mon_wcolor;
  logic                  mon_awe;
  logic [AccW-1:0]       mon_wacc;

  zb_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .CNT_W      (CNT_W),
    .COV_SAMPLES(COV_SAMPLES),
    .WINDOW     (WINDOW),
    .BEAT       (BEAT),
    .ACC_BITS   (ACC_BITS),
    .REV_BITS   (REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS),
    .DEPTH_GEN  (DEPTH_GEN)
  ) dut (
    .clk_i, .rst_ni, .state_we_i, .state_i, .state_layers_i(3'b000), .tile_x0_i, .tile_y0_i, .frag_valid_i,
    .frag_ready_o(frag_ready),
    .frag_x_i, .frag_y_i, .frag_z_i, .frag_rgba_i, .frag_cov_i, .stall_i,
    .tile_req_i, .tile_we_i, .tile_clear_i, .tile_planes_i, .tile_addr_i, .tile_wcolor_i,
    // The tile operations (copy, resolve) are not in these proofs yet (docs/formal.md).
    .tile_copy_i(1'b0), .tile_resolve_i(1'b0), .tile_wboit_i(1'b0), .tile_mlab_i(1'b0),
    .tile_wdepth_i, .tile_wcov_i, .tile_wpeel_i, .tile_wacc_i,
    .tile_rcolor_o(), .tile_rdepth_o(), .tile_rcov_o(), .tile_rpeel_o(), .tile_racc_o(),
    .busy_o(busy),
    .cnt_clear_i,
    .cnt_frag_in_o(), .cnt_frag_passed_o(), .cnt_frag_killed_o(), .cnt_depth_reads_o(),
    .cnt_depth_writes_o(), .cnt_color_reads_o(), .cnt_color_writes_o(),
    .cnt_stall_cycles_o(), .cnt_cycles_o(), .cnt_tile_loads_o(), .cnt_tile_stores_o(),
    .mon_x4_valid_o (mon_x4_valid),
    .mon_x4_addr_o  (mon_x4_addr),
    .mon_dwe_o      (mon_dwe),
    .mon_wdepth_o   (mon_wdepth),
    .mon_vwe_o      (mon_vwe),
    .mon_wcov_o     (mon_wcov),
    .mon_x11_valid_o(mon_x11_valid),
    .mon_x11_addr_o (mon_x11_addr),
    .mon_cwe_o      (mon_cwe),
    .mon_wcolor_o   (mon_wcolor),
    .mon_awe_o      (mon_awe),
    .mon_wacc_o     (mon_wacc),
    .mon_lwe_o      (),
    .mon_wlayers_o  ()
  );
