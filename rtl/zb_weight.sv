// zb_weight: the fragment side of the accumulate blend (docs/datapath.md "7. Accumulate
// blend"), M..X8, beside zb_operands. It depends on the fragment alone, so it runs while the
// fragment is in the depth stages:
//   M       u = (ZMAX - z) >> (DEPTH_BITS - 8), the top 8 bits of ~z; F = max(1, u^3 >> (24 - W))
//           from a ROM over u, built at elaboration (LUT logic, no multiplier)
//   X2, X3  zb_mul8: w = a * F (digits of F, multiples of a: 3a comes with the fragment)
//   X4      3w
//   X5      w and 3w: zb_blend's multipliers, idle in accumulate mode, form the terms' products
//           p_c * w from them (zb_blend's header)
// and, for the revealage, t = k + (k >> 7) with k = 255 - a (X6), 3t (X7), both in X8.
module zb_weight #(
  parameter int WEIGHT_BITS = 4,                                 // W
  localparam int FW         = WEIGHT_BITS > 0 ? WEIGHT_BITS : 1,  // F's width (W = 0: F = 1)
  localparam int WW         = 8 + FW                              // w = a * F
) (
  input  logic          clk_i,
  input  logic [7:0]    m_zhi_i,    // M's fragment: the top 8 bits of its depth
  input  logic [7:0]    m_a_i,
  input  logic [9:0]    m_a3_i,     // its 3 a
  output logic [WW-1:0] x5_w_o,     // X5: w = a * F
  output logic [WW+1:0] x5_w3_o,    // X5: 3 w
  output logic [8:0]    x8_t_o,     // X8: 1 - a on 0..256
  output logic [10:0]   x8_t3_o     // X8: 3 t
);

  // The depth weight of u, the paper's 3e3 (1 - d)^3 scaled to 2^W, floored at 1.
  function automatic logic [FW-1:0] depth_weight(input int u);
    int f;
    f = (u * u * u) >> (24 - WEIGHT_BITS);
    depth_weight = f == 0 ? 1 : f[FW-1:0];
  endfunction

  // ---------------------------------------------------------------------------------------
  // M: the ROM; F, a and 3a wait for the multiplier in X2 (a's and 3a's flops are
  // zb_operands' too: synthesis merges them).
  // ---------------------------------------------------------------------------------------
  logic [256*FW-1:0] rom;
  logic [7:0]        u;
  for (genvar i = 0; i < 256; i++) begin : g_rom
    assign rom[i*FW +: FW] = depth_weight(i);
  end
  assign u = ~m_zhi_i;

  logic [FW-1:0] x_f_q  [1:2];
  logic [7:0]    x_a_q  [1:6];   // a in X1..X6
  logic [9:0]    x_a3_q [1:2];

  always_ff @(posedge clk_i) begin
    x_f_q[1]  <= rom[u*FW +: FW];
    x_a_q[1]  <= m_a_i;
    x_a3_q[1] <= m_a3_i;
    x_f_q[2]  <= x_f_q[1];
    x_a3_q[2] <= x_a3_q[1];
    for (int unsigned k = 2; k <= 6; k++) begin
      x_a_q[k] <= x_a_q[k-1];
    end
  end

  // ---------------------------------------------------------------------------------------
  // X2, X3: w = a * F; X4: 3w.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x4_w;
  logic [WW-1:0] x5_w_q;
  logic [WW+1:0] x5_w3_q;

  zb_mul8 #(
    .K_W(8),
    .V_W(FW)
  ) u_weight (
    .clk_i(clk_i),
    .k_i  (x_a_q[2]),
    .k3_i (x_a3_q[2]),
    .v_i  (x_f_q[2]),
    .t_o  (x4_w)
  );

  always_ff @(posedge clk_i) begin
    x5_w_q  <= x4_w;
    x5_w3_q <= (WW+2)'(x4_w) + (WW+2)'({x4_w, 1'b0});
  end

  assign x5_w_o  = x5_w_q;
  assign x5_w3_o = x5_w3_q;

  // ---------------------------------------------------------------------------------------
  // X6, X7: the revealage's factor t = k + (k >> 7), k = 255 - a, and 3t.
  // ---------------------------------------------------------------------------------------
  logic [8:0]  x7_t_q, x8_t_q;
  logic [10:0] x8_t3_q;

  always_ff @(posedge clk_i) begin
    x7_t_q  <= {1'b0, ~x_a_q[6]} + {8'h00, ~x_a_q[6][7]};
    x8_t_q  <= x7_t_q;
    x8_t3_q <= 11'(x7_t_q) + {1'b0, x7_t_q, 1'b0};
  end

  assign x8_t_o  = x8_t_q;
  assign x8_t3_o = x8_t3_q;

endmodule
