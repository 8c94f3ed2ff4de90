// Formal (docs/formal.md, group raw): per-pixel read-after-write through zb_rop, by
// k-induction, with the shadow-word technique: for an arbitrary pixel P ($anyconst) the harness keeps
// the last depth, coverage, colour and accumulation word written to P (from the retire port's
// writes, in retire order). What a fragment to P reads (depth and coverage after X1's
// forwarding mux, colour and the accumulation word after X7's forwarding and bypass muxes)
// must equal that word once every older fragment has written, i.e. when the reader itself
// retires (X4 for depth and coverage, X11 for the others; P's fragments retire in issue order). The tile port is idle, so P's word before its first write
// is the RAM's (constant): the first read of P defines it.
// Strengthened for induction (below, and zb_window_inv.svh): the planes hold P's shadow words,
// and every read of P in flight holds P's plane word.
module zb_raw_check
`include "zb_rop_dut.svh"
`include "zb_window_inv.svh"

  // The read side, after flattening (docs/formal.md "Taps").
  // formal-tap: tap_x1_zs dut.u_depth.x1_zs
  // formal-tap: tap_x1_cs dut.u_depth.x1_cs
  // formal-tap: tap_x7_dst dut.u_color.x7_dst
  // formal-tap: tap_x7_acc dut.u_accum.x7_word
  logic [DEPTH_BITS-1:0] tap_x1_zs;
  logic [CovW-1:0]       tap_x1_cs;
  logic [31:0]           tap_x7_dst;
  logic [AccW-1:0]       tap_x7_acc;

  // ---------------------------------------------------------------------------------------
  // The driver's contract; the tile port stays idle (P's word comes from the RAM).
  // ---------------------------------------------------------------------------------------
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
    TilePortUnused: assume (!tile_req_i && !tile_clear_i);
    FragInTile: assume (!accept || (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
    FragCoverageInRange: assume (!accept || frag_cov_i <= CovW'(COV_SAMPLES));
  end

  (* anyconst *) logic [AddrW-1:0] pix;   // P

  // ---------------------------------------------------------------------------------------
  // What each fragment read, carried to its retire stage: depth and coverage X1 -> X4, colour
  // X7 -> X11 (the stages advance every cycle, so the word read in X1 three cycles ago is the
  // read of the fragment now in X4, and so on).
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] rz2_q, rz3_q, rz4_q;
  logic [CovW-1:0]       rc2_q, rc3_q, rc4_q;
  logic [31:0]           rk8_q, rk9_q, rk10_q, rk11_q;
  logic [AccW-1:0]       ra8_q, ra9_q, ra10_q, ra11_q;

  always_ff @(posedge clk_i) begin
    rz2_q  <= tap_x1_zs;
    rz3_q  <= rz2_q;
    rz4_q  <= rz3_q;
    rc2_q  <= tap_x1_cs;
    rc3_q  <= rc2_q;
    rc4_q  <= rc3_q;
    rk8_q  <= tap_x7_dst;
    rk9_q  <= rk8_q;
    rk10_q <= rk9_q;
    rk11_q <= rk10_q;
    ra8_q  <= tap_x7_acc;
    ra9_q  <= ra8_q;
    ra10_q <= ra9_q;
    ra11_q <= ra10_q;
  end

  // ---------------------------------------------------------------------------------------
  // The shadow words of P: the last value written, or (before any write) the first read.
  // ---------------------------------------------------------------------------------------
  logic                  x4_p, x11_p;
  logic                  sz_valid_q, sc_valid_q, sk_valid_q;
  logic [DEPTH_BITS-1:0] sz_q;
  logic [CovW-1:0]       sc_q;
  logic [31:0]           sk_q;
  logic [AccW-1:0]       sa_q;
  assign x4_p  = mon_x4_valid && mon_x4_addr == pix;
  assign x11_p = mon_x11_valid && mon_x11_addr == pix;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      sz_valid_q <= 1'b0;
      sc_valid_q <= 1'b0;
      sk_valid_q <= 1'b0;
    end else begin
      if (x4_p) begin
        sz_valid_q <= 1'b1;
        sc_valid_q <= 1'b1;
      end
      if (x11_p) sk_valid_q <= 1'b1;
    end
  end
  always_ff @(posedge clk_i) begin
    // A retiring fragment that does not write leaves the word it read (which, once the
    // shadow is valid, the assertions below hold equal to it).
    if (x4_p)  sz_q <= mon_dwe ? mon_wdepth : rz4_q;
    if (x4_p)  sc_q <= mon_vwe ? mon_wcov : rc4_q;
    if (x11_p) sk_q <= mon_cwe ? mon_wcolor : rk11_q;
    if (x11_p) sa_q <= mon_awe ? mon_wacc : ra11_q;
  end

  always_comb begin
    if (rst_ni) begin
      // A fragment reads the last word its pixel's older fragments wrote.
      DepthReadAfterWrite: assert (!(x4_p && sz_valid_q) || rz4_q == sz_q);
      CovReadAfterWrite: assert (!(x4_p && sc_valid_q) || rc4_q == sc_q);
      ColorReadAfterWrite: assert (!(x11_p && sk_valid_q) || rk11_q == sk_q);
      AccumReadAfterWrite: assert (!(x11_p && sk_valid_q) || ra11_q == sa_q);
    end
  end

  // ---------------------------------------------------------------------------------------
  // Induction strengthening. (1) Fragments to one pixel are at least Span = 4 stages apart in
  // K, M, X1..X11 (the window's interlock). So a fragment to P in X1..X4 has no older one
  // left to write depth (those are past X4), and one in X8..X11 none left to write colour;
  // one in X7 only the one in X11, whose write the bypass hands it. (2) Hence every read of
  // P in flight, carried or in the forwarding muxes, equals P's plane word as it is now
  // (after this edge's write, in X7). (3) The retire port writes the plane and the shadow
  // together, so a valid shadow word is P's plane word. The tile port stays idle: no
  // write-back (wback_q, wb2_q) and a fixed epoch and clear value, so P's word is the RAM
  // word, or the clear value when its generation bit is not the epoch.
  // ---------------------------------------------------------------------------------------
  // formal-tap: tap_m_valid dut.m_valid_q
  // formal-tap: tap_m_addr dut.m_addr_q
  // formal-tap: tap_x_valid dut.x_valid_q
  // formal-tap: tap_x1_addr dut.x_addr_q[1]
  // formal-tap: tap_x2_addr dut.x_addr_q[2]
  // formal-tap: tap_x3_addr dut.x_addr_q[3]
  // formal-tap: tap_x4_addr dut.x_addr_q[4]
  // formal-tap: tap_x5_addr dut.x_addr_q[5]
  // formal-tap: tap_x6_addr dut.x_addr_q[6]
  // formal-tap: tap_x7_addr dut.x_addr_q[7]
  // formal-tap: tap_x8_addr dut.x_addr_q[8]
  // formal-tap: tap_x9_addr dut.x_addr_q[9]
  // formal-tap: tap_x10_addr dut.x_addr_q[10]
  // The planes (two banks each: BEAT = 2, as the jobs run it). Depth is the first of zb_depth's
  // two depth banks (renamed copies): no renamed copy comes with the tile port idle, so its
  // role stays the reset's (tap_role, asserted below).
  // formal-tap: tap_zmem0 dut.u_depth.g_renamed.g_bank[0].u_plane.g_bank[0].u_mem.mem_q[*]
  // formal-tap: tap_zmem1 dut.u_depth.g_renamed.g_bank[0].u_plane.g_bank[1].u_mem.mem_q[*]
  // formal-tap: tap_z_epoch dut.u_depth.g_renamed.g_bank[0].u_plane.epoch_q
  // formal-tap: tap_z_clear dut.u_depth.g_renamed.g_bank[0].u_plane.clear_q
  // formal-tap: tap_z_wb dut.u_depth.g_renamed.g_bank[0].u_plane.wback_q
  // formal-tap: tap_z_wb2 dut.u_depth.g_renamed.g_bank[0].u_plane.wb2_q
  // formal-tap: tap_role dut.u_depth.g_renamed.role_q
  // formal-tap: tap_rd_role dut.u_depth.g_renamed.rd_role_q
  // formal-tap: tap_cmem0 dut.u_depth.u_cov_plane.g_bank[0].u_mem.mem_q[*]
  // formal-tap: tap_cmem1 dut.u_depth.u_cov_plane.g_bank[1].u_mem.mem_q[*]
  // formal-tap: tap_c_epoch dut.u_depth.u_cov_plane.epoch_q
  // formal-tap: tap_c_clear dut.u_depth.u_cov_plane.clear_q
  // formal-tap: tap_c_wb dut.u_depth.u_cov_plane.wback_q
  // formal-tap: tap_c_wb2 dut.u_depth.u_cov_plane.wb2_q
  // formal-tap: tap_kmem0 dut.u_color.u_color_plane.g_bank[0].u_mem.mem_q[*]
  // formal-tap: tap_kmem1 dut.u_color.u_color_plane.g_bank[1].u_mem.mem_q[*]
  // formal-tap: tap_k_epoch dut.u_color.u_color_plane.epoch_q
  // formal-tap: tap_k_clear dut.u_color.u_color_plane.clear_q
  // formal-tap: tap_k_wb dut.u_color.u_color_plane.wback_q
  // formal-tap: tap_k_wb2 dut.u_color.u_color_plane.wb2_q
  // formal-tap: tap_amem0 dut.u_accum.u_accum_plane.g_bank[0].u_mem.mem_q[*]
  // formal-tap: tap_amem1 dut.u_accum.u_accum_plane.g_bank[1].u_mem.mem_q[*]
  // formal-tap: tap_a_epoch dut.u_accum.u_accum_plane.epoch_q
  // formal-tap: tap_a_clear dut.u_accum.u_accum_plane.clear_q
  // formal-tap: tap_a_wb dut.u_accum.u_accum_plane.wback_q
  // formal-tap: tap_a_wb2 dut.u_accum.u_accum_plane.wb2_q
  localparam int unsigned Beats = TILE_W * TILE_H / 2;
  logic                  tap_m_valid;
  logic [AddrW-1:0]      tap_m_addr;
  logic [11:1]           tap_x_valid;
  logic [AddrW-1:0]      tap_x1_addr, tap_x2_addr, tap_x3_addr, tap_x4_addr, tap_x5_addr;
  logic [AddrW-1:0]      tap_x6_addr, tap_x7_addr, tap_x8_addr, tap_x9_addr, tap_x10_addr;
  // keep: connected after memory_map, whole.
  (* keep *) logic [Beats*(DEPTH_BITS+DEPTH_GEN)-1:0] tap_zmem0, tap_zmem1;
  (* keep *) logic [Beats*(CovW+1)-1:0]       tap_cmem0, tap_cmem1;
  (* keep *) logic [Beats*33-1:0]             tap_kmem0, tap_kmem1;
  (* keep *) logic [Beats*(AccW+1)-1:0]       tap_amem0, tap_amem1;
  logic [DEPTH_GEN-1:0]  tap_z_epoch;
  logic                  tap_c_epoch, tap_k_epoch, tap_a_epoch, tap_role, tap_rd_role;
  logic                  tap_z_wb, tap_c_wb, tap_k_wb, tap_a_wb;
  logic                  tap_z_wb2, tap_c_wb2, tap_k_wb2, tap_a_wb2;
  logic [DEPTH_BITS-1:0] tap_z_clear;
  logic [CovW-1:0]       tap_c_clear;
  logic [31:0]           tap_k_clear;
  logic [AccW-1:0]       tap_a_clear;

  // P's word of each plane: bank pix[0], beat pix >> 1; the clear value when fresh.
  logic [AddrW-2:0]      beat;
  logic [DEPTH_BITS+DEPTH_GEN-1:0] zw;
  logic [CovW:0]         cw;
  logic [32:0]           kw;
  logic [AccW:0]         aw;
  logic [DEPTH_BITS-1:0] z_p;
  logic [CovW-1:0]       c_p;
  logic [31:0]           k_p;
  logic [AccW-1:0]       a_p;
  assign beat = pix[AddrW-1:1];
  assign zw  = pix[0] ? tap_zmem1[beat*(DEPTH_BITS+DEPTH_GEN) +: DEPTH_BITS+DEPTH_GEN]
                      : tap_zmem0[beat*(DEPTH_BITS+DEPTH_GEN) +: DEPTH_BITS+DEPTH_GEN];
  assign cw  = pix[0] ? tap_cmem1[beat*(CovW+1) +: CovW+1] : tap_cmem0[beat*(CovW+1) +: CovW+1];
  assign kw  = pix[0] ? tap_kmem1[beat*33 +: 33] : tap_kmem0[beat*33 +: 33];
  assign aw  = pix[0] ? tap_amem1[beat*(AccW+1) +: AccW+1] : tap_amem0[beat*(AccW+1) +: AccW+1];
  assign z_p = zw[DEPTH_BITS +: DEPTH_GEN] != tap_z_epoch ? tap_z_clear : zw[DEPTH_BITS-1:0];
  assign c_p = cw[CovW] != tap_c_epoch ? tap_c_clear : cw[CovW-1:0];
  assign k_p = kw[32] != tap_k_epoch ? tap_k_clear : kw[31:0];
  assign a_p = aw[AccW] != tap_a_epoch ? tap_a_clear : aw[AccW-1:0];

  // The places K, M, X1..X11 (index 0..12) and the pairs closer than Span.
  localparam int unsigned NPos = 13;
  logic [NPos-1:0]  pos_v, pos_p;
  logic [AddrW-1:0] pos_a [NPos];
  assign pos_v = {tap_x_valid, tap_m_valid, |tap_w_pick_q};
  assign pos_a[0]  = tap_k_addr;
  assign pos_a[1]  = tap_m_addr;
  assign pos_a[2]  = tap_x1_addr;
  assign pos_a[3]  = tap_x2_addr;
  assign pos_a[4]  = tap_x3_addr;
  assign pos_a[5]  = tap_x4_addr;
  assign pos_a[6]  = tap_x5_addr;
  assign pos_a[7]  = tap_x6_addr;
  assign pos_a[8]  = tap_x7_addr;
  assign pos_a[9]  = tap_x8_addr;
  assign pos_a[10] = tap_x9_addr;
  assign pos_a[11] = tap_x10_addr;
  assign pos_a[12] = mon_x11_addr;
  logic [NPos*3-1:0] spaced_ok;
  for (genvar a = 0; a < NPos; a++) begin : g_pos
    assign pos_p[a] = pos_v[a] && pos_a[a] == pix;
    for (genvar d = 1; d <= 3; d++) begin : g_d
      if (a + d < NPos) begin : g_in
        assign spaced_ok[a*3 + d - 1] = !(pos_v[a] && pos_v[a+d] && pos_a[a] == pos_a[a+d]);
      end else begin : g_out
        assign spaced_ok[a*3 + d - 1] = 1'b1;
      end
    end
  end

  // X7's word: P's word after this edge's write (the one in X11 may write P now).
  logic [31:0]     k_next;
  logic [AccW-1:0] a_next;
  assign k_next = x11_p && mon_cwe ? mon_wcolor : k_p;
  assign a_next = x11_p && mon_awe ? mon_wacc : a_p;

  always_comb begin
    if (rst_ni) begin
      PixelSpan: assert (&spaced_ok);
      TilePortQuiet: assert (!(tap_z_wb || tap_z_wb2 || tap_c_wb || tap_c_wb2 || tap_k_wb ||
                               tap_k_wb2 || tap_a_wb || tap_a_wb2 || tap_role || tap_rd_role));
      ShadowIsPlane: assert ((!sz_valid_q || sz_q == z_p) && (!sc_valid_q || sc_q == c_p) &&
                             (!sk_valid_q || (sk_q == k_p && sa_q == a_p)));
      DepthReadsInFlight: assert ((!pos_p[2] || (tap_x1_zs == z_p && tap_x1_cs == c_p)) &&
                                  (!pos_p[3] || (rz2_q == z_p && rc2_q == c_p)) &&
                                  (!pos_p[4] || (rz3_q == z_p && rc3_q == c_p)) &&
                                  (!pos_p[5] || (rz4_q == z_p && rc4_q == c_p)));
      ColorReadsInFlight: assert ((!pos_p[8] || (tap_x7_dst == k_next && tap_x7_acc == a_next)) &&
                                  (!pos_p[9] || (rk8_q == k_p && ra8_q == a_p)) &&
                                  (!pos_p[10] || (rk9_q == k_p && ra9_q == a_p)) &&
                                  (!pos_p[11] || (rk10_q == k_p && ra10_q == a_p)) &&
                                  (!pos_p[12] || (rk11_q == k_p && ra11_q == a_p)));
    end
  end
endmodule
