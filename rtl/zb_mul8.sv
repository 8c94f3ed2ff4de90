// zb_mul8: t = k * v, 8 x 8 -> 16 bits unsigned, in two pipeline stages (latency 2: inputs in
// cycle c, t_o in cycle c + 2). Radix 4: v's four 2-bit digits each select 0, k, 2k or 3k
// (k3_i = 3k, computed by the caller a stage or more earlier, off this path); stage 1 adds
// the selected multiples in pairs, stage 2 adds the pairs. Each stage is one carry chain behind
// a 2-LUT-level select, short enough for 100 MHz in iCE40 fabric. No reset (data only).
module zb_mul8 (
  input  logic        clk_i,
  input  logic [7:0]  k_i,
  input  logic [9:0]  k3_i,   // 3 * k_i
  input  logic [7:0]  v_i,
  output logic [15:0] t_o
);

  logic [39:0] pp;   // the four selected multiples, 10 bits each
  logic [11:0] s01_d, s23_d, s01_q, s23_q;
  logic [15:0] t_d, t_q;

  for (genvar j = 0; j < 4; j++) begin : g_pp
    always_comb begin
      unique case (v_i[2*j +: 2])
        2'd0:    pp[10*j +: 10] = '0;
        2'd1:    pp[10*j +: 10] = {2'b00, k_i};
        2'd2:    pp[10*j +: 10] = {1'b0, k_i, 1'b0};
        default: pp[10*j +: 10] = k3_i;
      endcase
    end
  end

  assign s01_d = {2'b00, pp[9:0]} + {pp[19:10], 2'b00};
  assign s23_d = {2'b00, pp[29:20]} + {pp[39:30], 2'b00};
  assign t_d   = {4'h0, s01_q} + {s23_q, 4'h0};

  always_ff @(posedge clk_i) begin
    s01_q <= s01_d;
    s23_q <= s23_d;
    t_q   <= t_d;
  end

  assign t_o = t_q;

endmodule
