// zb_forward: the newest word of a pixel for a plane read at E5 (X5's address) and written at
// E11 (docs/rtl.md "Same-pixel distance"), in X7. The colour plane and the accumulation word
// each have one. The RAM's word for a read at the edge of a write to it is undefined
// (no_rw_check), and a write at E5 or E6 is newer than the word read: the forwarding registers
// catch either. A write at E7 (the fragment in X11 as this one is in X7) is bypassed into X7:
// the newest word of the pixel, it takes precedence over the forwarded one.
module zb_forward #(
  parameter int WIDTH  = 32,
  parameter int ADDR_W = 12
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              x5_valid_i,
  input  logic              x6_valid_i,
  input  logic [ADDR_W-1:0] x5_addr_i,
  input  logic [ADDR_W-1:0] x6_addr_i,
  input  logic [ADDR_W-1:0] x10_addr_i,
  input  logic [ADDR_W-1:0] x11_addr_i,
  input  logic              x10_we_i,     // the fragment in X10 will write at E11
  input  logic              x11_we_i,     // the plane's write at this edge
  input  logic [WIDTH-1:0]  x11_wdata_i,
  input  logic [WIDTH-1:0]  x6_rdata_i,   // the plane's word for X5's read (zb_plane rdata_o)
  output logic [WIDTH-1:0]  x7_word_o
);

  logic             fwd5_hit, fwd6_hit;  // X5's read meets X11's write at E5; X6 meets it at E6
  logic             byp_hit_d;           // X6 meets X10: its write lands at X7's edge
  logic             fwd6_hit_q;          // X6: X5's read met a write of its pixel at E5
  logic [WIDTH-1:0] fwd6_word_q;         // the word written at that edge
  logic             fwd_hit_q;           // X7: a write of its pixel at E5 or E6
  logic [WIDTH-1:0] fwd_word_q;          // that word
  logic             byp_hit_q;           // X7: the fragment now in X11 writes X7's pixel now
  logic [WIDTH-1:0] x7_mem_q;

  assign fwd5_hit  = x5_valid_i & x11_we_i & (x5_addr_i == x11_addr_i);
  assign fwd6_hit  = x6_valid_i & x11_we_i & (x6_addr_i == x11_addr_i);
  assign byp_hit_d = x6_valid_i & x10_we_i & (x6_addr_i == x10_addr_i);

  always_ff @(posedge clk_i) begin
    x7_mem_q    <= x6_rdata_i;
    fwd6_hit_q  <= fwd5_hit;
    fwd6_word_q <= x11_wdata_i;
    fwd_hit_q   <= fwd6_hit | fwd6_hit_q;
    fwd_word_q  <= fwd6_hit ? x11_wdata_i : fwd6_word_q;
    byp_hit_q   <= byp_hit_d;
  end

  assign x7_word_o = byp_hit_q ? x11_wdata_i : (fwd_hit_q ? fwd_word_q : x7_mem_q);

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // A write of the pixel at the read edge (X5 meets X11) or the next (X6 meets X11) reaches X7
  // as the forwarded word; one at E7 (X6 meets X10) as the bypass.
  ForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit |=> fwd_hit_q);
  ReadEdgeForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd5_hit |=> fwd6_hit_q);
  ForwardHeld: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit_q |=> fwd_hit_q);
  BypassCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      byp_hit_d |=> (byp_hit_q && x11_we_i));
  ForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd6_hit);
  ReadEdgeForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd5_hit);
  BypassPath: cover property (@(posedge clk_i) disable iff (!rst_ni) byp_hit_d);
`endif
`endif

endmodule
