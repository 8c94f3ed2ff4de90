// zb_mul8: t = k * v, K_W x V_W bits unsigned (8 x 8 by default), in two pipeline stages
// (latency 2: inputs in cycle c, t_o in cycle c + 2). Radix 4: v's 2-bit digits each select
// 0, k, 2k or 3k (k3_i = 3k, computed by the caller a stage or more earlier, off this path);
// stage 1 adds the selected multiples in pairs, stage 2 adds the pairs. Up to four digits
// (V_W <= 8) each stage is one carry chain behind a 2-LUT-level select, short enough for
// 100 MHz in iCE40 fabric; a wider v chains one more adder in stage 2 per further pair.
// No reset (data only).
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
  localparam int PpW    = K_W + 2;   // a selected multiple, below 4k
  localparam int PairW  = K_W + 4;   // a pair, pp[2i] + 4 pp[2i+1], below 16k
  localparam int TW     = K_W + V_W;

  logic [2*Digits-1:0]   v;          // v with a zero digit on top when V_W is odd
  logic [Digits*PpW-1:0] pp;         // the selected multiples
  logic [Pairs*PairW-1:0] pair_d, pair_q;
  logic [TW-1:0]         t_d, t_q;

  assign v = (2*Digits)'(v_i);

  for (genvar j = 0; j < Digits; j++) begin : g_pp
    always_comb begin
      unique case (v[2*j +: 2])
        2'd0:    pp[PpW*j +: PpW] = '0;
        2'd1:    pp[PpW*j +: PpW] = PpW'(k_i);
        2'd2:    pp[PpW*j +: PpW] = PpW'({k_i, 1'b0});
        default: pp[PpW*j +: PpW] = k3_i;
      endcase
    end
  end

  for (genvar i = 0; i < Pairs; i++) begin : g_pair
    if (2*i + 1 < Digits) begin : g_two
      assign pair_d[PairW*i +: PairW] = PairW'(pp[PpW*(2*i) +: PpW])
                                      + {pp[PpW*(2*i+1) +: PpW], 2'b00};
    end else begin : g_one
      assign pair_d[PairW*i +: PairW] = PairW'(pp[PpW*(2*i) +: PpW]);
    end
  end

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
