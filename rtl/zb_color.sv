// zb_color: the colour side of the pipeline (docs/rtl.md "Pipeline"), X5..X11. The colour plane
// is read at E5 (X5's address) and its word registered in X6 (the RAM's clock-to-out and the
// plane's resolve get a cycle of their own); zb_blend blends X7..X11; the colour is written at
// E11 when the fragment passed and the mask lets a channel through.
// A write of the pixel at E5 or E6 is newer than the word read: it reaches X7 through the
// forwarding registers. A write at E7 (the fragment in X11 as this one is in X7) is bypassed
// into X7 ("Same-pixel distance").
module zb_color #(
  parameter int WORDS       = 4096,
  parameter int BEAT        = 8,
  parameter int COV_SAMPLES = 16
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  zb_pkg::blend_mode_e               blend_i,
  input  logic [3:0]                        color_mask_i,
  // Tile port of the colour plane (zb_plane).
  input  logic                              tile_req_i,
  input  logic                              tile_we_i,
  input  logic                              tile_clear_i,
  input  logic                              tile_en_i,
  input  logic [$clog2(WORDS / BEAT)-1:0]   tile_addr_i,
  input  logic [BEAT*32-1:0]                tile_wcolor_i,
  output logic [BEAT*32-1:0]                tile_rcolor_o,
  // The pipeline: valid bits, addresses and pass bits of the stages this side uses.
  input  logic                              x5_valid_i,
  input  logic                              x6_valid_i,
  input  logic                              x10_valid_i,
  input  logic                              x11_valid_i,
  input  logic [$clog2(WORDS)-1:0]          x5_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x6_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x10_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x11_addr_i,
  input  logic                              x10_pass_i,
  input  logic                              x11_pass_i,
  // X7: zb_blend's operands (zb_operands).
  input  logic [31:0]                       x7_k_i,
  input  logic [39:0]                       x7_k3_i,
  input  logic [31:0]                       x7_add_i,
  input  logic [4*(8+$clog2(COV_SAMPLES+1))-1:0] x7_q_i,
  // X11's colour write as the plane takes it, for zb_rop's retire port.
  output logic                              x11_cwe_o,
  output logic [31:0]                       x11_wcolor_o
);

  logic [31:0] cmem_rdata, x7_mem_q, x11_color, x7_dst;
  logic        x10_cwe, x11_cwe;
  logic        fwd5_hit, fwd6_hit;    // X5's read meets X11's write at E5; X6 meets it at E6
  logic        fwd6_hit_q;            // X6: X5's read met a write of its pixel at E5
  logic [31:0] fwd6_color_q;          // the word written at that edge
  logic        fwd_hit_q;             // X7: a write of its pixel at E5 or E6
  logic [31:0] fwd_color_q;           // that word
  logic        byp_hit_q;             // X7: the fragment now in X11 writes X7's pixel now

  assign x10_cwe = x10_valid_i & x10_pass_i & (color_mask_i != 4'h0);
  assign x11_cwe = x11_valid_i & x11_pass_i & (color_mask_i != 4'h0);

  zb_plane #(
    .WIDTH    (32),
    .WORDS    (WORDS),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_color_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_en_i),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wcolor_i),
    .tile_rdata_o(tile_rcolor_o),
    .pipe_re_i   (x5_valid_i),
    .pipe_raddr_i(x5_addr_i),
    .pipe_we_i   (x11_cwe),
    .pipe_waddr_i(x11_addr_i),
    .pipe_wdata_i(x11_color),
    .rdata_o     (cmem_rdata)
  );

  // Forwarding: the RAM's word for a read at the edge of a write to it is undefined
  // (no_rw_check), and a write at E5 or E6 is newer than the word read. Bypass: the fragment
  // now in X11 writes X7's pixel at this edge, the newest word of the pixel; it takes
  // precedence over fwd_color_q.
  assign fwd5_hit = x5_valid_i & x11_cwe & (x5_addr_i == x11_addr_i);
  assign fwd6_hit = x6_valid_i & x11_cwe & (x6_addr_i == x11_addr_i);

  always_ff @(posedge clk_i) begin
    x7_mem_q     <= cmem_rdata;
    fwd6_hit_q   <= fwd5_hit;
    fwd6_color_q <= x11_color;
    fwd_hit_q    <= fwd6_hit | fwd6_hit_q;
    fwd_color_q  <= fwd6_hit ? x11_color : fwd6_color_q;
    byp_hit_q    <= x6_valid_i & x10_cwe & (x6_addr_i == x10_addr_i);
  end

  assign x11_cwe_o    = x11_cwe;
  assign x11_wcolor_o = x11_color;

  assign x7_dst = byp_hit_q ? x11_color : (fwd_hit_q ? fwd_color_q : x7_mem_q);

  zb_blend #(
    .COV_SAMPLES(COV_SAMPLES)
  ) u_blend (
    .clk_i  (clk_i),
    .mode_i (blend_i),
    .mask_i (color_mask_i),
    .dst_i  (x7_dst),
    .k_i    (x7_k_i),
    .k3_i   (x7_k3_i),
    .add_i  (x7_add_i),
    .q_i    (x7_q_i),
    .color_o(x11_color)
  );

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // A write of the pixel at the read edge (X5 meets X11) or the next (X6 meets X11) reaches X7
  // as the forwarded word; one at E7 (X6 meets X10) as the bypass.
  ColorForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit |=> fwd_hit_q);
  ColorReadEdgeForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd5_hit |=> fwd6_hit_q);
  ColorForwardHeld: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit_q |=> fwd_hit_q);
  ColorBypassCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x6_valid_i && x10_cwe && x6_addr_i == x10_addr_i) |=> (byp_hit_q && x11_cwe));
  ColorForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd6_hit);
  ColorReadEdgeForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd5_hit);
  ColorBypassPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x6_valid_i && x10_cwe && x6_addr_i == x10_addr_i);
`endif
`endif

endmodule
