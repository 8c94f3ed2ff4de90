// Formal (docs/formal.md, group stream): zb_rop's input stream, bounded model check. Any
// stall_i, any tile-port use the protocol allows, any pass state, any fragments (inside the
// tile, coverage at most N). An arbitrary pixel P ($anyconst): the n-th fragment accepted to P
// carries depth n (a tag); at the retire port (X4) P's fragments must come back with tags 0, 1,
// 2, ... : none lost, duplicated or reordered within the pixel. Every accepted fragment retires
// once (counts), and frag_ready_o honours the holds and is the skid flop's "S empty".
module zb_stream_check
`include "zb_rop_dut.svh"

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
    BlendCodeValid: assume (!state_we_i || state_i.blend <= zb_pkg::BlendAccumulate);
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
