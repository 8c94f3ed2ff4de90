// Formal (docs/formal.md, group covers): a trace for every forwarding, bypass and reorder path
// of zb_rop (the RTL's cover properties, restated on taps because yosys 0.23 does not read
// them): depth and coverage forwarding (a read at the edge of a write of its pixel), colour
// forwarding at the read edge (X5 meets X11) and the next (X6 meets X11), the colour bypass
// (X6 meets X10, used in X7), a reorder (a pick past an older fragment that waits), the skid
// register taking a fragment, a full window. Each `formal-cover` wire must be reachable from
// reset under the driver's contract; the flow proves it by finding a trace (cover_<wire>.vcd).
module zb_paths_cover #(
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

  // formal-tap: tap_m_valid dut.m_valid_q
  // formal-tap: tap_m_addr dut.m_addr_q
  // formal-tap: tap_fwd5_hit dut.u_color.fwd5_hit
  // formal-tap: tap_fwd6_hit dut.u_color.fwd6_hit
  // formal-tap: tap_byp_hit dut.u_color.byp_hit_q
  // formal-tap: tap_x7_dst dut.u_color.x7_dst
  // formal-tap: tap_x11_color dut.u_color.x11_color
  // formal-tap: tap_pick dut.u_window.pick
  // formal-tap: tap_win_valid dut.u_window.valid_q
  // formal-tap: tap_older dut.u_window.older_q
  // formal-tap: tap_accept dut.u_input.accept
  // formal-tap: tap_i_free dut.u_input.i_free
  logic                     tap_m_valid, tap_fwd5_hit, tap_fwd6_hit, tap_byp_hit;
  logic [AddrW-1:0]         tap_m_addr;
  logic [31:0]              tap_x7_dst, tap_x11_color;
  logic [WINDOW-1:0]        tap_pick, tap_win_valid;
  logic [WINDOW*WINDOW-1:0] tap_older;
  logic                     tap_accept, tap_i_free;

  logic first_q = 1'b1;
  always_ff @(posedge clk_i) first_q <= 1'b0;

  logic        accept;
  logic [15:0] dx, dy;
  assign accept = frag_valid_i && frag_ready;
  assign dx     = frag_x_i - tile_x0_i;
  assign dy     = frag_y_i - tile_y0_i;

  always_comb begin
    ResetFirstCycle: assume (rst_ni == !first_q);
    StateWriteIdle: assume (!state_we_i || !busy);
    BlendCodeValid: assume (!state_we_i || state_i.blend <= zb_pkg::BlendUnder);
    TilePortIdle: assume (!(tile_req_i || tile_clear_i) || !busy);
    FragInTile: assume (!accept || (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
    FragCoverageInRange: assume (!accept || frag_cov_i <= CovW'(COV_SAMPLES));
  end

  // The cover conditions (zb_depth, zb_color, zb_issue_window, zb_input); rst_ni gates each.
  // Each line names the wire and the trace length searched (a little above the shortest).
  // formal-cover: cover_depth_forward 12
  // formal-cover: cover_cov_forward 12
  // formal-cover: cover_color_read_edge_forward 20
  // formal-cover: cover_color_forward 20
  // formal-cover: cover_color_bypass 20
  // formal-cover: cover_reorder 10
  // formal-cover: cover_skid_taken 8
  // formal-cover: cover_window_full 8
  (* keep *) logic cover_depth_forward, cover_cov_forward, cover_color_read_edge_forward;
  (* keep *) logic cover_color_forward, cover_color_bypass, cover_reorder, cover_skid_taken;
  (* keep *) logic cover_window_full;
  logic [WINDOW-1:0] past_older;
  always_comb begin
    for (int unsigned i = 0; i < WINDOW; i++) begin
      past_older[i] = tap_pick[i] && |(tap_win_valid & tap_older[i*WINDOW +: WINDOW]);
    end
  end
  assign cover_depth_forward = rst_ni && tap_m_valid && mon_dwe && tap_m_addr == mon_x4_addr;
  assign cover_cov_forward   = rst_ni && tap_m_valid && mon_vwe && tap_m_addr == mon_x4_addr;
  assign cover_color_read_edge_forward = rst_ni && tap_fwd5_hit;
  assign cover_color_forward = rst_ni && tap_fwd6_hit;
  // The bypass taken with a word that differs from the RAM's: X7 uses X11's write data.
  assign cover_color_bypass  = rst_ni && tap_byp_hit && tap_x7_dst == tap_x11_color;
  assign cover_reorder       = rst_ni && |past_older;
  assign cover_skid_taken    = rst_ni && tap_accept && !tap_i_free;
  assign cover_window_full   = rst_ni && &tap_win_valid;
endmodule
