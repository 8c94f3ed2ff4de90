// Formal (docs/formal.md, group raw): per-pixel read-after-write through zb_rop, bounded model
// check, with the shadow-word technique: for an arbitrary pixel P ($anyconst) the harness keeps
// the last depth, coverage, colour and accumulation word written to P (from the retire port's
// writes, in retire order). What a fragment to P reads (depth and coverage after X1's
// forwarding mux, colour and the accumulation word after X7's forwarding and bypass muxes)
// must equal that word once every older fragment has written, i.e. when the reader itself
// retires (X4 for depth and coverage, X11 for the others; P's fragments retire in issue order). The tile port is idle, so P's word before its first write
// is the RAM's (constant): the first read of P defines it.
module zb_raw_check
`include "zb_rop_dut.svh"

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
endmodule
