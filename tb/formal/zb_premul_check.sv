// Formal (docs/formal.md, group premul): zb_premul's every channel equals
// m(s, a) = (t + (t >> 8) + 0x80) >> 8, t = s * a (docs/datapath.md), for every colour, four
// cycles later. The caller's a3 = 3a is made here. Proven by k-induction (no feedback).
// ZB_FORMAL_DEFECT_PREMUL rounds the specification with 0x7f: the proof must fail.
module zb_premul_check #(
  parameter int unsigned CHAN = 4  // the channel checked: 0..3, or 4 for all
) (
  input logic        clk_i,
  input logic [31:0] rgba_i
);
  logic [31:0] ms, spec_d;
  logic [31:0] spec1_q, spec2_q, spec3_q, spec4_q;
  logic [2:0]  filled_q = 3'd0;  // cycles since the start, up to the latency
  // One channel per job keeps each solver query to one multiplier (four at once take far more
  // than four times as long); the flow runs the four.
  localparam logic [31:0] Checked = CHAN > 3 ? 32'hffff_ffff : 32'hff << (8 * CHAN);

`ifdef ZB_FORMAL_DEFECT_PREMUL
  localparam logic [16:0] Round = 17'h7f;
`else
  localparam logic [16:0] Round = 17'h80;
`endif

  zb_premul dut (
    .clk_i (clk_i),
    .rgba_i(rgba_i),
    .a3_i  (10'(3 * rgba_i[31:24])),
    .ms_o  (ms)
  );

  // The specification, per channel, in 17 bits (t + (t >> 8) + 0x80 < 2^17).
  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic [16:0] t;
    assign t = 17'(16'(rgba_i[8*c +: 8]) * 16'(rgba_i[31:24]));  // exact: 8 x 8 bits fit 16
    assign spec_d[8*c +: 8] = 8'((t + (t >> 8) + Round) >> 8);
  end

  always_ff @(posedge clk_i) begin
    spec1_q <= spec_d;
    spec2_q <= spec1_q;
    spec3_q <= spec2_q;
    spec4_q <= spec3_q;
    if (filled_q != 3'd4) filled_q <= filled_q + 3'd1;
  end

  always_comb begin
    if (filled_q == 3'd4) PremulIsM: assert ((ms & Checked) == (spec4_q & Checked));
  end
endmodule
