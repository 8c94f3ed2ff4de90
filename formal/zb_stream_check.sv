// Formal (docs/formal.md, group stream): zb_rop's input stream, bounded model check. Any
// stall_i, any tile-port use the protocol allows, any pass state, any fragments (inside the
// tile, coverage at most N). An arbitrary pixel P ($anyconst): the n-th fragment accepted to P
// carries depth n (a tag); at the retire port (X4) P's fragments must come back with tags 0, 1,
// 2, ... : none lost, duplicated or reordered within the pixel. Every accepted fragment retires
// once (counts), and frag_ready_o honours the holds and is the skid flop's "S empty".
module zb_stream_check #(
  parameter int unsigned DEPTH_BITS  = 8,
  parameter int unsigned TILE_W      = 2,
  parameter int unsigned TILE_H      = 2,
  parameter int unsigned CNT_W       = 2,
  parameter int unsigned COV_SAMPLES = 1,
  parameter int unsigned WINDOW      = 2,
  parameter int unsigned BEAT        = 2
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
  input logic                            cnt_clear_i
);
  localparam int unsigned AddrW = $clog2(TILE_W * TILE_H);
  localparam int unsigned XW    = $clog2(TILE_W);
  localparam int unsigned YW    = $clog2(TILE_H);
  localparam int unsigned CovW  = $clog2(COV_SAMPLES + 1);
  localparam int unsigned CntW  = 6;   // harness counters: more than the fragments in flight

  logic                  frag_ready, busy;
  logic                  mon_x4_valid, mon_dwe, mon_vwe, mon_x11_valid, mon_cwe;
  logic [AddrW-1:0]      mon_x4_addr, mon_x11_addr;
  logic [DEPTH_BITS-1:0] mon_wdepth;
  logic [CovW-1:0]       mon_wcov;
  logic [31:0]           mon_wcolor;

  zb_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .CNT_W      (CNT_W),
    .COV_SAMPLES(COV_SAMPLES),
    .WINDOW     (WINDOW),
    .BEAT       (BEAT)
  ) dut (
    .clk_i, .rst_ni, .state_we_i, .state_i, .tile_x0_i, .tile_y0_i, .frag_valid_i,
    .frag_ready_o(frag_ready),
    .frag_x_i, .frag_y_i, .frag_z_i, .frag_rgba_i, .frag_cov_i, .stall_i,
    .tile_req_i, .tile_we_i, .tile_clear_i, .tile_planes_i, .tile_addr_i, .tile_wcolor_i,
    .tile_wdepth_i, .tile_wcov_i, .tile_wpeel_i,
    .tile_rcolor_o(), .tile_rdepth_o(), .tile_rcov_o(), .tile_rpeel_o(),
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
    .mon_wcolor_o   (mon_wcolor)
  );

  // formal-tap: tap_in_ready dut.u_input.in_ready_q
  // formal-tap: tap_s_valid dut.u_input.s_valid_q
  logic tap_in_ready, tap_s_valid;

  // ---------------------------------------------------------------------------------------
  // The driver's contract (docs/rtl.md "Port timing").
  // ---------------------------------------------------------------------------------------
  logic first_q = 1'b1;
  always_ff @(posedge clk_i) first_q <= 1'b0;

  logic        accept;
  logic [15:0] dx, dy;
  logic [AddrW-1:0] in_addr;
  assign accept  = frag_valid_i && frag_ready;
  assign dx      = frag_x_i - tile_x0_i;
  assign dy      = frag_y_i - tile_y0_i;
  assign in_addr = {dy[YW-1:0], dx[XW-1:0]};

  (* anyconst *) logic [AddrW-1:0] pix;   // P
  logic [CntW-1:0] acc_p_q, ret_p_q, acc_all_q, ret_all_q;

  always_comb begin
    ResetFirstCycle: assume (rst_ni == !first_q);
    StateWriteIdle: assume (!state_we_i || !busy);
    BlendCodeValid: assume (!state_we_i || state_i.blend <= zb_pkg::BlendUnder);
    TilePortIdle: assume (!(tile_req_i || tile_clear_i) || !busy);
    FragInTile: assume (!accept || (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
    FragCoverageInRange: assume (!accept || frag_cov_i <= CovW'(COV_SAMPLES));
    // P's fragments are numbered in accept order by their depth.
    PixelTag: assume (!(accept && in_addr == pix) || frag_z_i == DEPTH_BITS'(acc_p_q));
  end

  // ---------------------------------------------------------------------------------------
  // Counts: accepted and retired, for P and for all.
  // ---------------------------------------------------------------------------------------
  logic ret_p;
  assign ret_p = mon_x4_valid && mon_x4_addr == pix;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      acc_p_q   <= '0;
      ret_p_q   <= '0;
      acc_all_q <= '0;
      ret_all_q <= '0;
    end else begin
      acc_p_q   <= acc_p_q + CntW'(accept && in_addr == pix);
      ret_p_q   <= ret_p_q + CntW'(ret_p);
      acc_all_q <= acc_all_q + CntW'(accept);
      ret_all_q <= ret_all_q + CntW'(mon_x4_valid);
    end
  end

  always_comb begin
    if (rst_ni) begin
      // Valid/ready: nothing accepted while held; ready is the flop "S empty" otherwise.
      ReadyHonoursHold: assert (!((stall_i || tile_req_i || tile_clear_i) && frag_ready));
      ReadyIsSkidEmpty: assert (frag_ready == (tap_in_ready && !stall_i && !tile_req_i &&
                                               !tile_clear_i) && tap_in_ready == !tap_s_valid);
      // P's fragments retire in accept order, each once.
      PixelInOrder: assert (!ret_p || mon_wdepth == DEPTH_BITS'(ret_p_q));
      RetireNotAhead: assert (acc_p_q - ret_p_q <= CntW'(WINDOW + 10));
      // Idle: every accepted fragment has retired.
      PixelDrained: assert (busy || acc_p_q == ret_p_q);
      AllDrained: assert (busy || acc_all_q == ret_all_q);
      // The planes' writes come from retiring fragments only.
      WritesFromRetire: assert ((!mon_dwe && !mon_vwe) || mon_x4_valid);
    end
  end
endmodule
