// Formal (docs/formal.md, group stream): zb_rop's input stream, by k-induction. Any
// stall_i, any tile-port use the protocol allows, any pass state, any fragments (inside the
// tile, coverage at most N). An arbitrary pixel P ($anyconst): the n-th fragment accepted to P
// carries depth n (a tag); at the retire port (X4) P's fragments must come back with tags 0, 1,
// 2, ... : none lost, duplicated or reordered within the pixel. Every accepted fragment retires
// once (counts), and frag_ready_o honours the holds and is the skid flop's "S empty".
// Strengthened for induction (below, and zb_window_inv.svh): every place a fragment waits is
// counted and P's fragments there carry the tags their order gives them.
module zb_stream_check
`include "zb_rop_dut.svh"
`include "zb_window_inv.svh"

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

  // ---------------------------------------------------------------------------------------
  // Induction strengthening. A fragment not yet retired is in exactly one place: I, S, a
  // window slot, K (the pick), M or X1..X4. Oldest first they are X4..X1, M, K, the slots in
  // age order, I, S, and P's fragments keep that order (the window issues a pixel's oldest
  // first), so P's fragment at place L carries tag ret_p + (P's fragments older than L).
  // The counters then equal the counts of these places.
  // ---------------------------------------------------------------------------------------
  // formal-tap: tap_i_valid dut.u_input.i_valid_q
  // formal-tap: tap_i_addr dut.u_input.i_addr_q
  // formal-tap: tap_i_z dut.u_input.i_z_q
  // formal-tap: tap_s_addr dut.u_input.s_addr_q
  // formal-tap: tap_s_z dut.u_input.s_z_q
  // formal-tap: tap_w_mem dut.u_window.u_data.mem_q[*]
  // formal-tap: tap_k_data dut.u_window.pick_data_o
  // formal-tap: tap_m_valid dut.m_valid_q
  // formal-tap: tap_m_addr dut.m_addr_q
  // formal-tap: tap_m_z dut.m_z_q
  // formal-tap: tap_x_valid dut.x_valid_q
  // formal-tap: tap_x1_addr dut.x_addr_q[1]
  // formal-tap: tap_x2_addr dut.x_addr_q[2]
  // formal-tap: tap_x3_addr dut.x_addr_q[3]
  // formal-tap: tap_x4_addr dut.x_addr_q[4]
  // formal-tap: tap_x1_z dut.u_depth.x1_z_q
  // formal-tap: tap_x2_z dut.u_depth.x2_z_q
  // formal-tap: tap_x3_z dut.u_depth.x3_z_q
  // formal-tap: tap_x4_z dut.u_depth.x4_z_q
  localparam int unsigned WinW = 10 + CovW + 32 + DEPTH_BITS;  // a slot: {3a, cov, rgba, z}
  logic                    tap_i_valid, tap_m_valid;
  logic [AddrW-1:0]        tap_i_addr, tap_s_addr, tap_m_addr;
  logic [DEPTH_BITS-1:0]   tap_i_z, tap_s_z, tap_m_z;
  (* keep *) logic [WINDOW*WinW-1:0] tap_w_mem;  // keep: connected after memory_map, whole
  logic [WinW-1:0]         tap_k_data;
  logic [11:1]             tap_x_valid;
  logic [AddrW-1:0]        tap_x1_addr, tap_x2_addr, tap_x3_addr, tap_x4_addr;
  logic [DEPTH_BITS-1:0]   tap_x1_z, tap_x2_z, tap_x3_z, tap_x4_z;

  // The places after the window, oldest first: X4, X3, X2, X1, M, K (index 0..5).
  localparam int unsigned NPipe = 6;
  logic [NPipe-1:0]      pl_valid, pl_p;
  logic [AddrW-1:0]      pl_addr [NPipe];
  logic [DEPTH_BITS-1:0] pl_z [NPipe];
  assign pl_valid = {|tap_w_pick_q, tap_m_valid, tap_x_valid[1], tap_x_valid[2],
                     tap_x_valid[3], tap_x_valid[4]};
  assign pl_addr[0] = tap_x4_addr;
  assign pl_addr[1] = tap_x3_addr;
  assign pl_addr[2] = tap_x2_addr;
  assign pl_addr[3] = tap_x1_addr;
  assign pl_addr[4] = tap_m_addr;
  assign pl_addr[5] = tap_k_addr;
  assign pl_z[0] = tap_x4_z;
  assign pl_z[1] = tap_x3_z;
  assign pl_z[2] = tap_x2_z;
  assign pl_z[3] = tap_x1_z;
  assign pl_z[4] = tap_m_z;
  assign pl_z[5] = tap_k_data[DEPTH_BITS-1:0];

  // Running counts: pl_older_p[n] = P's fragments in places 0..n-1 (and all fragments).
  logic [CntW-1:0] pl_older_p [NPipe+1];
  logic [CntW-1:0] pl_older_all [NPipe+1];
  logic [NPipe-1:0] pl_tag_ok;
  assign pl_older_p[0]   = '0;
  assign pl_older_all[0] = '0;
  for (genvar n = 0; n < NPipe; n++) begin : g_pipe
    assign pl_p[n] = pl_valid[n] && pl_addr[n] == pix;
    assign pl_older_p[n+1]   = pl_older_p[n] + CntW'(pl_p[n]);
    assign pl_older_all[n+1] = pl_older_all[n] + CntW'(pl_valid[n]);
    assign pl_tag_ok[n] = !pl_p[n] || pl_z[n] == DEPTH_BITS'(CntW'(ret_p_q + pl_older_p[n]));
  end

  // The slots: each after the pipeline and after the older slots.
  logic [WINDOW-1:0] sl_p, sl_tag_ok;
  logic [CntW-1:0]   sl_older_p [WINDOW];
  logic [CntW-1:0]   sl_sum_p [WINDOW+1];
  logic [CntW-1:0]   sl_sum_all [WINDOW+1];
  assign sl_sum_p[0]   = '0;
  assign sl_sum_all[0] = '0;
  for (genvar i = 0; i < WINDOW; i++) begin : g_sl
    logic [CntW-1:0] older [WINDOW+1];
    assign sl_p[i] = tap_w_valid[i] && tap_w_addr[i*AddrW +: AddrW] == pix;
    assign older[0] = '0;
    for (genvar j = 0; j < WINDOW; j++) begin : g_older
      assign older[j+1] = older[j] + CntW'(sl_p[j] && tap_w_older[i*WINDOW + j]);
    end
    assign sl_older_p[i] = older[WINDOW];
    assign sl_sum_p[i+1]   = sl_sum_p[i] + CntW'(sl_p[i]);
    assign sl_sum_all[i+1] = sl_sum_all[i] + CntW'(tap_w_valid[i]);
    assign sl_tag_ok[i] = !sl_p[i] || tap_w_mem[i*WinW +: DEPTH_BITS] ==
        DEPTH_BITS'(CntW'(ret_p_q + pl_older_p[NPipe] + sl_older_p[i]));
  end

  // I, then S (younger than I: it fills only while I is held).
  logic            i_p, s_p;
  logic [CntW-1:0] before_i_p, before_s_p, inflight_p, inflight_all;
  assign i_p          = tap_i_valid && tap_i_addr == pix;
  assign s_p          = tap_s_valid && tap_s_addr == pix;
  assign before_i_p   = pl_older_p[NPipe] + sl_sum_p[WINDOW];
  assign before_s_p   = before_i_p + CntW'(i_p);
  assign inflight_p   = before_s_p + CntW'(s_p);
  assign inflight_all = pl_older_all[NPipe] + sl_sum_all[WINDOW] + CntW'(tap_i_valid) +
                        CntW'(tap_s_valid);

  always_comb begin
    if (rst_ni) begin
      SkidBehindI: assert (!tap_s_valid || tap_i_valid);
      CountPixel: assert (acc_p_q == CntW'(ret_p_q + inflight_p));
      CountAll: assert (acc_all_q == CntW'(ret_all_q + inflight_all));
      TagPipe: assert (&pl_tag_ok);
      TagSlot: assert (&sl_tag_ok);
      TagI: assert (!i_p || tap_i_z == DEPTH_BITS'(CntW'(ret_p_q + before_i_p)));
      TagS: assert (!s_p || tap_s_z == DEPTH_BITS'(CntW'(ret_p_q + before_s_p)));
    end
  end
endmodule
