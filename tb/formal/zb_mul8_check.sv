// Formal (docs/formal.md, group mul8): zb_mul8 equals k * v for every (k, v), two cycles later,
// at its default 8 x 8 bits and (jobs mul_pairs, mul_wide) at other widths: five digits of v
// (three pairs, an odd V_W padded), a 12-bit k (the accumulate blend's shapes, scaled to z3).
// The caller's contract, k3_i = 3k, is made here; nothing else is assumed. Proven by
// k-induction: the unit is a pipeline without feedback, so two steps determine its state.
// ZB_FORMAL_DEFECT_MUL8 breaks the contract (k3 = 2k): the proof must fail.
module zb_mul8_check #(
  parameter int unsigned K_W = 8,
  parameter int unsigned V_W = 8
) (
  input logic           clk_i,
  input logic [K_W-1:0] k_i,
  input logic [V_W-1:0] v_i
);
  logic [K_W+V_W-1:0] t, spec1_q, spec2_q;
  logic [K_W+1:0]     k3;
  logic [1:0]         filled_q = 2'd0;  // cycles since the start, up to the latency

`ifdef ZB_FORMAL_DEFECT_MUL8
  assign k3 = {1'b0, k_i, 1'b0};
`else
  assign k3 = (K_W+2)'(k_i) + {1'b0, k_i, 1'b0};
`endif

  zb_mul8 #(
    .K_W(K_W),
    .V_W(V_W)
  ) dut (
    .clk_i(clk_i),
    .k_i  (k_i),
    .k3_i (k3),
    .v_i  (v_i),
    .t_o  (t)
  );

  // The specification: the product, delayed by the latency.
  always_ff @(posedge clk_i) begin
    spec1_q <= (K_W+V_W)'(k_i) * (K_W+V_W)'(v_i);
    spec2_q <= spec1_q;
    if (filled_q != 2'd2) filled_q <= filled_q + 2'd1;
  end

  always_comb begin
    if (filled_q == 2'd2) ProductIsKTimesV: assert (t == spec2_q);
  end
endmodule
