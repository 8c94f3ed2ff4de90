// zb_input: stage I and its skid register S (docs/rtl.md "Pipeline"). An accepted fragment goes
// into I, or into S when I's fragment does not leave at that edge; S empties into I first.
// frag_ready_o is a flop ("S empty") gated by the inputs that stop the stream, so it is not at
// the end of the issue window's logic. Here the fragment gets its tile-local address and 3a
// (for the premultiply, zb_premul).
module zb_input #(
  parameter int DEPTH_BITS  = 24,
  parameter int TILE_W      = 64,
  parameter int TILE_H      = 64,
  parameter int COV_SAMPLES = 16
) (
  input  logic                                 clk_i,
  input  logic                                 rst_ni,
  input  logic                                 frag_valid_i,
  output logic                                 frag_ready_o,
  input  logic [15:0]                          frag_x_i,
  input  logic [15:0]                          frag_y_i,
  input  logic [DEPTH_BITS-1:0]                frag_z_i,
  input  logic [31:0]                          frag_rgba_i,
  input  logic [$clog2(COV_SAMPLES + 1)-1:0]   frag_cov_i,
  input  logic [15:0]                          tile_x0_i,
  input  logic [15:0]                          tile_y0_i,
  input  logic                                 hold_i,   // no fragment accepted this cycle
  input  logic                                 take_i,   // the window takes I's fragment
  output logic                                 i_valid_o,
  output logic [$clog2(TILE_W * TILE_H)-1:0]   i_addr_o,
  output logic [9:0]                           i_a3_o,   // 3 a
  output logic [DEPTH_BITS-1:0]                i_z_o,
  output logic [31:0]                          i_rgba_o,
  output logic [$clog2(COV_SAMPLES + 1)-1:0]   i_cov_o,
  output logic                                 busy_o    // I or S holds a fragment
);

  localparam int AddrW = $clog2(TILE_W * TILE_H);
  localparam int XW    = $clog2(TILE_W);
  localparam int YW    = $clog2(TILE_H);
  localparam int CovW  = $clog2(COV_SAMPLES + 1);

  logic                  accept, in_ready_d, in_ready_q;
  logic [15:0]           dx, dy;
  logic [AddrW-1:0]      in_addr;
  logic                  i_valid_d, i_valid_q, s_valid_d, s_valid_q;
  logic [AddrW-1:0]      i_addr_d, i_addr_q, s_addr_d, s_addr_q;
  logic [DEPTH_BITS-1:0] i_z_d, i_z_q, s_z_d, s_z_q;
  logic [31:0]           i_rgba_d, i_rgba_q, s_rgba_d, s_rgba_q;
  logic [CovW-1:0]       i_cov_d, i_cov_q, s_cov_d, s_cov_q;
  logic                  i_free;       // I's fragment leaves (or I is empty) at this edge

  assign frag_ready_o = in_ready_q & ~hold_i;
  assign accept       = frag_valid_i & frag_ready_o;
  assign dx           = frag_x_i - tile_x0_i;
  assign dy           = frag_y_i - tile_y0_i;
  assign in_addr      = {dy[YW-1:0], dx[XW-1:0]};   // y_local * TILE_W + x_local
  assign i_free       = ~i_valid_q | take_i;

  always_comb begin
    i_valid_d = i_valid_q;
    i_addr_d  = i_addr_q;
    i_z_d     = i_z_q;
    i_rgba_d  = i_rgba_q;
    i_cov_d   = i_cov_q;
    s_valid_d = s_valid_q;
    s_addr_d  = s_addr_q;
    s_z_d     = s_z_q;
    s_rgba_d  = s_rgba_q;
    s_cov_d   = s_cov_q;
    if (i_free) begin
      if (s_valid_q) begin          // (no accept: frag_ready_o is low while S is full)
        i_valid_d = 1'b1;
        i_addr_d  = s_addr_q;
        i_z_d     = s_z_q;
        i_rgba_d  = s_rgba_q;
        i_cov_d   = s_cov_q;
        s_valid_d = 1'b0;
      end else begin
        i_valid_d = accept;
        if (accept) begin
          i_addr_d = in_addr;
          i_z_d    = frag_z_i;
          i_rgba_d = frag_rgba_i;
          i_cov_d  = frag_cov_i;
        end
      end
    end else if (accept) begin
      s_valid_d = 1'b1;
      s_addr_d  = in_addr;
      s_z_d     = frag_z_i;
      s_rgba_d  = frag_rgba_i;
      s_cov_d   = frag_cov_i;
    end
  end
  assign in_ready_d = ~s_valid_d;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      in_ready_q <= 1'b1;
      i_valid_q  <= 1'b0;
      s_valid_q  <= 1'b0;
    end else begin
      in_ready_q <= in_ready_d;
      i_valid_q  <= i_valid_d;
      s_valid_q  <= s_valid_d;
    end
  end

  always_ff @(posedge clk_i) begin
    i_addr_q <= i_addr_d;
    i_z_q    <= i_z_d;
    i_rgba_q <= i_rgba_d;
    i_cov_q  <= i_cov_d;
    s_addr_q <= s_addr_d;
    s_z_q    <= s_z_d;
    s_rgba_q <= s_rgba_d;
    s_cov_q  <= s_cov_d;
  end

  assign i_valid_o = i_valid_q;
  assign i_addr_o  = i_addr_q;
  assign i_a3_o    = {2'b00, i_rgba_q[31:24]} + {1'b0, i_rgba_q[31:24], 1'b0};
  assign i_z_o     = i_z_q;
  assign i_rgba_o  = i_rgba_q;
  assign i_cov_o   = i_cov_q;
  assign busy_o    = i_valid_q | s_valid_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // An accepted fragment lies inside the resident tile.
  FragInTile: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
  // A fragment covers at most the N samples of a pixel.
  FragCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (frag_cov_i <= CovW'(COV_SAMPLES)));
  // frag_ready_o's flop is "S empty": it never drops for another reason.
  ReadyIsSkidEmpty: assert property (@(posedge clk_i) disable iff (!rst_ni)
      in_ready_q == !s_valid_q);
  // The skid register takes a fragment (I held by a full window).
  SkidTaken: cover property (@(posedge clk_i) disable iff (!rst_ni) accept && !i_free);
`endif
`endif

endmodule
