// zb_mul8, simulation view (docs/rtl.md "Two builds, two views"): rtl/zb_mul8.sv is the
// synthesis view and the specification. Every Verilated model reads this file instead: each pair
// of v's digits is one K_W x 4 multiply, which Verilator evaluates without the digit selects'
// branches. The registers (pair_q, t_q) and the final sum are the synthesis view's, and
// scripts/equiv.py proves the two views equal.
module zb_mul8 #(
  parameter int K_W = 8,
  parameter int V_W = 8
) (
  input  logic               clk_i,
  input  logic [K_W-1:0]     k_i,
  input  logic [K_W+1:0]     k3_i,   // 3 * k_i
  input  logic [V_W-1:0]     v_i,
  output logic [K_W+V_W-1:0] t_o
);

  localparam int Digits = (V_W + 1) / 2;
  localparam int Pairs  = (Digits + 1) / 2;
  localparam int PairW  = K_W + 4;   // a pair, pp[2i] + 4 pp[2i+1], below 16k
  localparam int TW     = K_W + V_W;

  logic [2*Digits-1:0]   v;          // v with a zero digit on top when V_W is odd
  logic [Pairs*PairW-1:0] pair_d, pair_q;
  logic [TW-1:0]         t_d, t_q;

  assign v = (2*Digits)'(v_i);

  // Pair i is k times v's bits [4i, 4i + 4) (two digits; one on top when Digits is odd).
  for (genvar i = 0; i < Pairs; i++) begin : g_pair
    localparam int NibW = 2*i + 1 < Digits ? 4 : 2;
    assign pair_d[PairW*i +: PairW] = PairW'(k_i) * PairW'(v[4*i +: NibW]);
  end
  logic unused_k3;  // 3k serves the synthesis view's digit selects
  assign unused_k3 = ^k3_i;

  always_comb begin
    t_d = '0;
    for (int unsigned i = 0; i < Pairs; i++) begin
      t_d = t_d + (TW'(pair_q[PairW*i +: PairW]) << (4*i));
    end
  end

  always_ff @(posedge clk_i) begin
    pair_q <= pair_d;
    t_q    <= t_d;
  end

  assign t_o = t_q;

endmodule
