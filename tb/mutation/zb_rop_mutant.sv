// zb_rop with Yosys's mutants (make mutate, docs/mutation.md): the same parameters and ports as
// rtl/zb_rop.sv, around zb_rop_mutants, the netlist `mutate -ctrl` made of zb_rop at these
// parameters (build/tb/mutation/mutants.v). Mutant N is live when the simulation is started with
// +zb_mutant=N; without it, or with N = 0, the netlist is zb_rop unchanged. The netlist was
// elaborated with the build's widths: the parameters here only name them for the driver.
// With ZB_MUT_LAYERS the netlist has the layers unit (make mutate-layers) and its layers writes
// reach the driver; without, it has none.
module zb_rop
#(
  parameter int unsigned DEPTH_BITS  = 24,
  parameter int unsigned TILE_W      = 64,
  parameter int unsigned TILE_H      = 64,
  parameter int unsigned CNT_W       = 32,
  parameter int unsigned COV_SAMPLES = 16,
  parameter int unsigned WINDOW      = 8,
  parameter int unsigned BEAT        = 8,
  parameter int unsigned ACC_BITS    = 16,
  parameter int unsigned REV_BITS    = 8,
  parameter int unsigned WEIGHT_BITS = 4,
  parameter int unsigned DEPTH_GEN   = 2,
  parameter int unsigned LAYERS      = 0,    // the driver's view (the netlist's with ZB_MUT_LAYERS)
  parameter int unsigned MUT_W       = 11   // mutsel's width: mutants 1 .. 2^MUT_W - 1
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  state_we_i,
  input  zb_pkg::pass_state_t   state_i,
  input  logic [2:0]            state_layers_i,
  input  logic [15:0]           tile_x0_i,
  input  logic [15:0]           tile_y0_i,
  input  logic                  frag_valid_i,
  output logic                  frag_ready_o,
  input  logic [15:0]           frag_x_i,
  input  logic [15:0]           frag_y_i,
  input  logic [DEPTH_BITS-1:0] frag_z_i,
  input  logic [31:0]           frag_rgba_i,
  input  logic [$clog2(COV_SAMPLES + 1)-1:0] frag_cov_i,
  input  logic                  stall_i,
  input  logic                  tile_req_i,
  input  logic                  tile_we_i,
  input  logic                  tile_clear_i,
  input  logic                  tile_copy_i,
  input  logic                  tile_resolve_i,
  input  logic                  tile_wboit_i,
  input  logic                  tile_mlab_i,
  input  zb_pkg::planes_t       tile_planes_i,
  input  logic [$clog2(TILE_W * TILE_H / BEAT)-1:0] tile_addr_i,
  input  logic [BEAT*32-1:0]         tile_wcolor_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wdepth_i,
  input  logic [BEAT*$clog2(COV_SAMPLES + 1)-1:0] tile_wcov_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wpeel_i,
  input  logic [BEAT*(4*ACC_BITS+REV_BITS)-1:0] tile_wacc_i,
  output logic [BEAT*32-1:0]         tile_rcolor_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rdepth_o,
  output logic [BEAT*$clog2(COV_SAMPLES + 1)-1:0] tile_rcov_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rpeel_o,
  output logic [BEAT*(4*ACC_BITS+REV_BITS)-1:0] tile_racc_o,
  output logic                  busy_o,
  input  logic                  cnt_clear_i,
  output logic [CNT_W-1:0]      cnt_frag_in_o,
  output logic [CNT_W-1:0]      cnt_frag_passed_o,
  output logic [CNT_W-1:0]      cnt_frag_killed_o,
  output logic [CNT_W-1:0]      cnt_depth_reads_o,
  output logic [CNT_W-1:0]      cnt_depth_writes_o,
  output logic [CNT_W-1:0]      cnt_color_reads_o,
  output logic [CNT_W-1:0]      cnt_color_writes_o,
  output logic [CNT_W-1:0]      cnt_stall_cycles_o,
  output logic [CNT_W-1:0]      cnt_cycles_o,
  output logic [CNT_W-1:0]      cnt_tile_loads_o,
  output logic [CNT_W-1:0]      cnt_tile_stores_o,
  output logic                  mon_x4_valid_o,
  output logic [$clog2(TILE_W * TILE_H)-1:0] mon_x4_addr_o,
  output logic                  mon_dwe_o,
  output logic [DEPTH_BITS-1:0] mon_wdepth_o,
  output logic                  mon_vwe_o,
  output logic [$clog2(COV_SAMPLES + 1)-1:0] mon_wcov_o,
  output logic                  mon_x11_valid_o,
  output logic [$clog2(TILE_W * TILE_H)-1:0] mon_x11_addr_o,
  output logic                  mon_cwe_o,
  output logic [31:0]           mon_wcolor_o,
  output logic                  mon_awe_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] mon_wacc_o,
  output logic                  mon_lwe_o,
  output logic [(LAYERS > 0 ? LAYERS * (DEPTH_BITS + 32) : 1)-1:0] mon_wlayers_o
);

`ifndef ZB_MUT_LAYERS
  assign mon_lwe_o     = 1'b0;
  assign mon_wlayers_o = '0;
`endif

  logic [MUT_W-1:0] mutsel;
  initial begin
    if (!$value$plusargs("zb_mutant=%d", mutsel)) mutsel = '0;
  end

  zb_rop_mutants u_mutants (
    .clk_i, .rst_ni, .state_we_i, .state_i, .state_layers_i, .tile_x0_i, .tile_y0_i, .frag_valid_i,
    .frag_ready_o, .frag_x_i, .frag_y_i, .frag_z_i, .frag_rgba_i, .frag_cov_i, .stall_i,
    .tile_req_i, .tile_we_i, .tile_clear_i, .tile_copy_i, .tile_resolve_i, .tile_wboit_i, .tile_mlab_i,
    .tile_planes_i,
    .tile_addr_i, .tile_wcolor_i,
    .tile_wdepth_i, .tile_wcov_i, .tile_wpeel_i, .tile_wacc_i, .tile_rcolor_o, .tile_rdepth_o,
    .tile_rcov_o, .tile_rpeel_o, .tile_racc_o, .busy_o, .cnt_clear_i, .cnt_frag_in_o,
    .cnt_frag_passed_o,
    .cnt_frag_killed_o, .cnt_depth_reads_o, .cnt_depth_writes_o, .cnt_color_reads_o,
    .cnt_color_writes_o, .cnt_stall_cycles_o, .cnt_cycles_o, .cnt_tile_loads_o,
    .cnt_tile_stores_o, .mon_x4_valid_o, .mon_x4_addr_o, .mon_dwe_o, .mon_wdepth_o, .mon_vwe_o,
    .mon_wcov_o, .mon_x11_valid_o, .mon_x11_addr_o, .mon_cwe_o, .mon_wcolor_o, .mon_awe_o,
`ifdef ZB_MUT_LAYERS
    .mon_wacc_o, .mon_lwe_o, .mon_wlayers_o, .mutsel
`else
    .mon_wacc_o, .mon_lwe_o(), .mon_wlayers_o(), .mutsel
`endif
  );
endmodule
