// Formal (docs/formal.md, group blend): zb_blend equals the blend of docs/datapath.md
// "3. Blend" and the write mask, for every stored colour and operands, in every mode, four
// cycles later. The pass state (mode, mask) is a constant, as zb_rop keeps it while fragments
// are in flight; k3 = 3k is made here. Coverage mode's operands are those zb_operands makes
// (k = N - w <= N, q <= w * 255 + N/2). Proven by k-induction (no feedback).
// Accumulate mode writes no colour: with ACC, the products w * p_c are checked instead, three
// cycles after their operands, w 8 bits wide (zb_mul8_check proves the multiplier at 12 bits).
// One mode set a job: both in one query take z3 far longer than the two apart.
// ZB_FORMAL_DEFECT_BLEND rounds the specification with 0x7f, ZB_FORMAL_DEFECT_PRODUCT takes its
// product of p_c with bit 0 flipped: either proof must fail.
module zb_blend_check #(
  parameter int unsigned COV_SAMPLES = 16,
  parameter int unsigned CHAN        = 4,   // the channel checked: 0..3, or 4 for all
  parameter int unsigned K_W         = 8,
  parameter bit          ACC         = 1'b0  // accumulate mode alone (job blend_acc), else the others
) (
  input logic           clk_i,
  input logic [31:0]    dst_i,
  input logic [31:0]    k_i,
  input logic [31:0]    add_i,
  input logic [51:0]    q_i,    // 4 x QW, QW = 8 + CovW = 13 for N = 16
  input logic [K_W-1:0] w_i,
  input logic [31:0]    p_i
);
  localparam int unsigned CovW   = $clog2(COV_SAMPLES + 1);
  localparam int unsigned QW     = 8 + CovW;
  localparam int unsigned CovLog = $clog2(COV_SAMPLES);
  // One channel per job keeps each solver query to one multiplier (four at once take far more
  // than four times as long); the flow runs the four.
  localparam logic [31:0] Checked = CHAN > 3 ? 32'hffff_ffff : 32'hff << (8 * CHAN);
  localparam int unsigned ChanLo = CHAN > 3 ? 0 : CHAN;  // the products checked: ChanN from ChanLo
  localparam int unsigned ChanN  = CHAN > 3 ? 4 : 1;

`ifdef ZB_FORMAL_DEFECT_BLEND
  localparam logic [16:0] Round = 17'h7f;
`else
  localparam logic [16:0] Round = 17'h80;
`endif

  (* anyconst *) logic [2:0] mode;
  (* anyconst *) logic [3:0] mask;

  logic [39:0]     k3;
  logic [4*QW-1:0] q;
  logic [31:0]     color, spec_d;
  logic [31:0]     spec1_q, spec2_q, spec3_q, spec4_q;
  logic [2:0]      filled_q = 3'd0;  // cycles since the start, up to the latency
  logic            under, cov, acc;
  logic [K_W+1:0]  w3;
  logic [4*(K_W+8)-1:0] prod, prod_d, prod1_q, prod2_q, prod3_q;
  logic [3:0]      operands_ok;  // per channel: coverage operands zb_operands can make

  assign q     = q_i[4*QW-1:0];
  assign under = mode == 3'(zb_pkg::BlendUnder);
  assign cov   = mode == 3'(zb_pkg::BlendCoverage);
  assign acc   = mode == 3'(zb_pkg::BlendAccumulate);
  assign w3    = (K_W+2)'(w_i) * (K_W+2)'(3);

  zb_blend #(
    .COV_SAMPLES(COV_SAMPLES),
    .K_W        (K_W)
  ) dut (
    .clk_i  (clk_i),
    .mode_i (mode),
    .mask_i (mask),
    .dst_i  (dst_i),
    .k_i    (k_i),
    .k3_i   (k3),
    .add_i  (add_i),
    .q_i    (q),
    .w_i    (w_i),
    .w3_i   (w3),
    .p_i    (p_i),
    .color_o(color),
    .prod_o (prod)
  );

  always_comb begin
    ModeIsABlendMode: assume (ACC ? mode == 3'(zb_pkg::BlendAccumulate)
                                  : mode <= 3'(zb_pkg::BlendUnder));
    CoverageOperands: assume (&operands_ok);
  end

  // The specification, per channel: min(255, m(k * v) + add), or coverage (k d + q) >> log2 N,
  // then the write mask.
  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic [7:0]  k, d, v, a;
    logic [16:0] t, m, r;
    logic [24:0] cs;
    assign k  = k_i[8*c +: 8];
    assign d  = dst_i[8*c +: 8];
    assign v  = under ? 8'd255 - dst_i[31:24] : d;
    assign a  = under ? d : add_i[8*c +: 8];
    assign t  = 17'(16'(k) * 16'(v));  // exact: 8 x 8 bits fit 16
    assign m  = (t + (t >> 8) + Round) >> 8;
    assign r  = m + 17'(a);
    assign cs = (25'(k) * 25'(d) + 25'(q[QW*c +: QW])) >> CovLog;
    assign k3[10*c +: 10] = 10'(3 * k);
`ifdef ZB_FORMAL_DEFECT_PRODUCT
    assign prod_d[(K_W+8)*c +: K_W+8] = (K_W+8)'(w_i) * (K_W+8)'(p_i[8*c +: 8] ^ 8'h01);
`else
    assign prod_d[(K_W+8)*c +: K_W+8] = (K_W+8)'(w_i) * (K_W+8)'(p_i[8*c +: 8]);
`endif
    assign spec_d[8*c +: 8] = !mask[c] ? d : (cov ? 8'(cs) : (r > 17'd255 ? 8'd255 : 8'(r)));

    assign operands_ok[c] = !cov || (k <= 8'(COV_SAMPLES) &&
        25'(q[QW*c +: QW]) <= 25'(COV_SAMPLES - 32'(k)) * 25'd255 + 25'(COV_SAMPLES / 2));
  end

  always_ff @(posedge clk_i) begin
    spec1_q <= spec_d;
    spec2_q <= spec1_q;
    spec3_q <= spec2_q;
    spec4_q <= spec3_q;
    prod1_q <= prod_d;
    prod2_q <= prod1_q;
    prod3_q <= prod2_q;
    if (filled_q != 3'd4) filled_q <= filled_q + 3'd1;
  end

  always_comb begin
    if (filled_q == 3'd4 && !acc) BlendIsSpec: assert ((color & Checked) == (spec4_q & Checked));
    if (filled_q >= 3'd3 && acc) ProductIsSpec: assert (prod[(K_W+8)*ChanLo +: (K_W+8)*ChanN]
                                                     == prod3_q[(K_W+8)*ChanLo +: (K_W+8)*ChanN]);
  end
endmodule
