// Formal (docs/formal.md, group covers): a trace for every forwarding, bypass and reorder path
// of zb_rop (the RTL's cover properties, restated on taps because yosys 0.23 does not read
// them): depth and coverage forwarding (a read at the edge of a write of its pixel), colour
// and accumulation-word forwarding at the read edge (X5 meets X11) and the next (X6 meets
// X11), their bypasses (X6 meets X10, used in X7), a reorder (a pick past an older fragment that waits), the skid
// register taking a fragment, a full window. Each `formal-cover` wire must be reachable from
// reset under the driver's contract; the flow proves it by finding a trace (cover_<wire>.vcd).
module zb_paths_cover
`include "zb_rop_dut.svh"

  // formal-tap: tap_m_valid dut.m_valid_q
  // formal-tap: tap_m_addr dut.m_addr_q
  // formal-tap: tap_fwd5_hit dut.u_color.u_forward.fwd5_hit
  // formal-tap: tap_fwd6_hit dut.u_color.u_forward.fwd6_hit
  // formal-tap: tap_byp_hit dut.u_color.u_forward.byp_hit_q
  // formal-tap: tap_x7_dst dut.u_color.x7_dst
  // formal-tap: tap_x11_color dut.u_color.x11_color
  // formal-tap: tap_afwd5_hit dut.u_accum.u_forward.fwd5_hit
  // formal-tap: tap_afwd6_hit dut.u_accum.u_forward.fwd6_hit
  // formal-tap: tap_abyp_hit dut.u_accum.u_forward.byp_hit_q
  // formal-tap: tap_x7_acc dut.u_accum.x7_word
  // formal-tap: tap_x11_acc dut.u_accum.x11_word
  // formal-tap: tap_pick dut.u_window.pick
  // formal-tap: tap_win_valid dut.u_window.valid_q
  // formal-tap: tap_older dut.u_window.older_q
  // formal-tap: tap_accept dut.u_input.accept
  // formal-tap: tap_i_free dut.u_input.i_free
  logic                     tap_m_valid, tap_fwd5_hit, tap_fwd6_hit, tap_byp_hit;
  logic [AddrW-1:0]         tap_m_addr;
  logic [31:0]              tap_x7_dst, tap_x11_color;
  logic                     tap_afwd5_hit, tap_afwd6_hit, tap_abyp_hit;
  logic [AccW-1:0]          tap_x7_acc, tap_x11_acc;
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
    BlendCodeValid: assume (!state_we_i || state_i.blend <= zb_pkg::BlendAccumulate);
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
  // formal-cover: cover_accum_read_edge_forward 20
  // formal-cover: cover_accum_forward 20
  // formal-cover: cover_accum_bypass 20
  // formal-cover: cover_reorder 10
  // formal-cover: cover_skid_taken 8
  // formal-cover: cover_window_full 8
  (* keep *) logic cover_depth_forward, cover_cov_forward, cover_color_read_edge_forward;
  (* keep *) logic cover_color_forward, cover_color_bypass, cover_reorder, cover_skid_taken;
  (* keep *) logic cover_window_full, cover_accum_read_edge_forward, cover_accum_forward;
  (* keep *) logic cover_accum_bypass;
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
  assign cover_accum_read_edge_forward = rst_ni && tap_afwd5_hit;
  assign cover_accum_forward = rst_ni && tap_afwd6_hit;
  assign cover_accum_bypass  = rst_ni && tap_abyp_hit && tap_x7_acc == tap_x11_acc;
  assign cover_reorder       = rst_ni && |past_older;
  assign cover_skid_taken    = rst_ni && tap_accept && !tap_i_free;
  assign cover_window_full   = rst_ni && &tap_win_valid;
endmodule
