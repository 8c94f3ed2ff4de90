// zb_accum: the accumulation side of the pipeline (docs/datapath.md "7. Accumulate blend"),
// X5..X11 beside zb_color, with the colour plane's timing. Its plane holds per pixel the word
// {r, acc_A, acc_B, acc_G, acc_R} (acc_R at bit 0): read at E5 (X5's address), registered in
// X6, the pixel's newest word in X7 (zb_forward: forwarding and bypass as the colour's),
// written at E11 in accumulate mode when the fragment passed and the mask is not 0.
//   X7   the word from zb_forward, registered
//   X8   per channel acc + term (term_c = (p_c * w) >> S of zb_blend's products, A + 1 bits);
//        zb_mul8: r * t, stage 1
//   X9   acc' = min(2^A - 1, acc + term); r * t, stage 2
//   X10  r' = (r * t + 128) >> 8: the product's top bits plus its bit 7
//   X11  the word's flops drive the write data (and zb_forward's bypass), no logic after them
module zb_accum #(
  parameter int WORDS    = 4096,
  parameter int BEAT     = 8,
  parameter int ACC_BITS = 16,  // A
  parameter int REV_BITS = 8,   // R
  parameter int WEIGHT_BITS = 4,  // W
  localparam int PW = 16 + (WEIGHT_BITS > 0 ? WEIGHT_BITS : 1)  // p * w (zb_weight's w: 8 + W bits)
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  input  logic                                acc_mode_i,    // blend = accumulate
  input  logic [3:0]                          color_mask_i,
  // Tile port of the accumulation plane (zb_plane).
  input  logic                                tile_req_i,
  input  logic                                tile_we_i,
  input  logic                                tile_clear_i,
  input  logic                                tile_en_i,
  input  logic [$clog2(WORDS / BEAT)-1:0]     tile_addr_i,
  input  logic [BEAT*(4*ACC_BITS+REV_BITS)-1:0] tile_wacc_i,
  output logic [BEAT*(4*ACC_BITS+REV_BITS)-1:0] tile_racc_o,
  // The pipeline: valid bits, addresses and pass bits of the stages this side uses.
  input  logic                                x5_valid_i,
  input  logic                                x6_valid_i,
  input  logic                                x10_valid_i,
  input  logic                                x11_valid_i,
  input  logic [$clog2(WORDS)-1:0]            x5_addr_i,
  input  logic [$clog2(WORDS)-1:0]            x6_addr_i,
  input  logic [$clog2(WORDS)-1:0]            x10_addr_i,
  input  logic [$clog2(WORDS)-1:0]            x11_addr_i,
  input  logic                                x10_pass_i,
  input  logic                                x11_pass_i,
  // X8: the fragment side: the products p_c * w (zb_blend's multipliers), t and 3t (zb_weight).
  input  logic [4*PW-1:0]                     x8_prod_i,
  input  logic [8:0]                          x8_t_i,
  input  logic [10:0]                         x8_t3_i,
  // X11's write as the plane takes it, for zb_rop's retire port.
  output logic                                x11_awe_o,
  output logic [4*ACC_BITS+REV_BITS-1:0]      x11_wacc_o
);

  localparam int A  = ACC_BITS;
  localparam int R  = REV_BITS;
  localparam int AW = 4 * A + R;
  localparam int Shift = WEIGHT_BITS + 20 > A ? WEIGHT_BITS + 20 - A : 0;
  // A term's bits: at most A - 3, so acc + term fits A + 1 bits.
  localparam int TermW = PW - Shift;

  logic [AW-1:0] amem_rdata, x7_word, x11_word;
  logic          acc_on, x10_awe, x11_awe;

  assign acc_on  = acc_mode_i & (color_mask_i != 4'h0);
  assign x10_awe = x10_valid_i & x10_pass_i & acc_on;
  assign x11_awe = x11_valid_i & x11_pass_i & acc_on;

  zb_plane #(
    .WIDTH    (AW),
    .WORDS    (WORDS),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_accum_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_en_i),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wacc_i),
    .tile_rdata_o(tile_racc_o),
    .pipe_re_i   (x5_valid_i),
    .pipe_raddr_i(x5_addr_i),
    .pipe_we_i   (x11_awe),
    .pipe_waddr_i(x11_addr_i),
    .pipe_wdata_i(x11_word),
    .rdata_o     (amem_rdata)
  );

`ifdef ZB_INJECT_ACCUM_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_accum: the bypass is never
  // taken, so a fragment issued Span cycles after one to its pixel adds to the word before it.
  logic bug_on, x10_awe_fwd;
  initial bug_on = $test$plusargs("zb_bug_accum") != 0;
  assign x10_awe_fwd = x10_awe & ~bug_on;
`endif

  zb_forward #(
    .WIDTH (AW),
    .ADDR_W($clog2(WORDS))
  ) u_forward (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .x5_valid_i (x5_valid_i),
    .x6_valid_i (x6_valid_i),
    .x5_addr_i  (x5_addr_i),
    .x6_addr_i  (x6_addr_i),
    .x10_addr_i (x10_addr_i),
    .x11_addr_i (x11_addr_i),
`ifdef ZB_INJECT_ACCUM_BUG
    .x10_we_i   (x10_awe_fwd),
`else
    .x10_we_i   (x10_awe),
`endif
    .x11_we_i   (x11_awe),
    .x11_wdata_i(x11_word),
    .x6_rdata_i (amem_rdata),
    .x7_word_o  (x7_word)
  );

  // ---------------------------------------------------------------------------------------
  // The accumulation: X8 adds, X9 saturates.
  // ---------------------------------------------------------------------------------------
  logic [AW-1:0] x8_word_q;
  always_ff @(posedge clk_i) begin
    x8_word_q <= x7_word;
  end

  // term_c = (p_c * w) >> S, S = max(0, W + 20 - A): wiring only.
  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic [A-1:0] term;
    logic [A:0]   x9_sum_q;
    logic [Shift > 0 ? Shift - 1 : 0 : 0] unused_low;
    assign term = A'(x8_prod_i[PW*c + Shift +: TermW]);
    if (Shift > 0) begin : g_low
      assign unused_low = x8_prod_i[PW*c +: Shift];
    end else begin : g_nolow
      assign unused_low = 1'b0;
    end
    logic [A-1:0] x10_acc_q, x11_acc_q;
    always_ff @(posedge clk_i) begin
      x9_sum_q  <= {1'b0, x8_word_q[A*c +: A]} + {1'b0, term};
      x10_acc_q <= x9_sum_q[A] ? '1 : x9_sum_q[A-1:0];
      x11_acc_q <= x10_acc_q;
    end
    assign x11_word[A*c +: A] = x11_acc_q;
  end

  // ---------------------------------------------------------------------------------------
  // The revealage: X8, X9 r * t; X10 the rounding.
  // ---------------------------------------------------------------------------------------
  logic [R+8:0] x10_rt;
  logic [R-1:0] x11_r_q;
  logic [7:0]   unused_rt;

  zb_mul8 #(
    .K_W(9),
    .V_W(R)
  ) u_reveal (
    .clk_i(clk_i),
    .k_i  (x8_t_i),
    .k3_i (x8_t3_i),
    .v_i  (x8_word_q[4*A +: R]),
    .t_o  (x10_rt)
  );

  // r * t <= r * 256, so (r * t + 128) >> 8 <= r: R bits.
  assign unused_rt = {x10_rt[R+8], x10_rt[6:0]};
  always_ff @(posedge clk_i) begin
    x11_r_q <= x10_rt[R+7:8] + R'(x10_rt[7]);
  end
  assign x11_word[4*A +: R] = x11_r_q;

  assign x11_awe_o  = x11_awe;
  assign x11_wacc_o = x11_word;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // The revealage never grows (t <= 256).
  RevealNeverGrows: assert property (@(posedge clk_i) disable iff (!rst_ni)
      x11_awe |-> (x11_r_q <= $past(x8_word_q[4*A +: R], 3)));
`endif
`endif

endmodule
