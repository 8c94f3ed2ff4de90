// zb_weight: the fragment side of the accumulate blend (docs/datapath.md "7. Accumulate
// blend"), M..X8, beside zb_operands. It depends on the fragment alone, so it runs while the
// fragment is in the depth stages, and its results wait in X8 for zb_accum's adds:
//   M       u = (ZMAX - z) >> (DEPTH_BITS - 8), the top 8 bits of ~z; F = max(1, u^3 >> (24 - W))
//           from a ROM over u, built at elaboration (LUT logic, no multiplier)
//   X1, X2  zb_mul8: w = a * F (digits of F, multiples of a: 3a comes with the fragment)
//   X3..X5  w waits for m(s, a); X5 forms 3w
//   X6, X7  zb_mul8 per channel: p_c * w, p_c = m(s, a) (zb_premul, X6) for R, G, B, p_A = a
//   X8      term_c = (p_c * w) >> S, S = max(0, W + 20 - A): wiring only
// and, for the revealage, t = k + (k >> 7) with k = 255 - a (X6), 3t (X7), both in X8.
module zb_weight #(
  parameter int ACC_BITS    = 16,  // A
  parameter int WEIGHT_BITS = 4    // W
) (
  input  logic                    clk_i,
  input  logic [7:0]              m_zhi_i,    // M's fragment: the top 8 bits of its depth
  input  logic [7:0]              m_a_i,
  input  logic [9:0]              m_a3_i,     // its 3 a
  input  logic [31:0]             x6_ms_i,    // X6: m(s, a) per channel (zb_operands)
  output logic [4*ACC_BITS-1:0]   x8_term_o,  // X8: term_c at [c*A +: A], R first
  output logic [8:0]              x8_t_o,     // X8: 1 - a on 0..256
  output logic [10:0]             x8_t3_o     // X8: 3 t
);

  localparam int FW    = WEIGHT_BITS > 0 ? WEIGHT_BITS : 1;  // F's width (W = 0: F = 1)
  localparam int WW    = 8 + FW;                              // w = a * F
  localparam int PW    = 8 + WW;                              // p * w
  localparam int Shift = WEIGHT_BITS + 20 > ACC_BITS ? WEIGHT_BITS + 20 - ACC_BITS : 0;
  // A term's bits: at most A - 3, so acc + term fits A + 1 bits (zb_accum).
  localparam int TermW = PW - Shift;

  // The depth weight of u, the paper's 3e3 (1 - d)^3 scaled to 2^W, floored at 1.
  function automatic logic [FW-1:0] depth_weight(input int u);
    int f;
    f = (u * u * u) >> (24 - WEIGHT_BITS);
    depth_weight = f == 0 ? 1 : f[FW-1:0];
  endfunction

  // ---------------------------------------------------------------------------------------
  // M: the ROM.
  // ---------------------------------------------------------------------------------------
  logic [256*FW-1:0] rom;
  logic [7:0]        u;
  for (genvar i = 0; i < 256; i++) begin : g_rom
    assign rom[i*FW +: FW] = depth_weight(i);
  end
  assign u = ~m_zhi_i;

  logic [FW-1:0] x1_f_q;
  logic [7:0]    x_a_q [1:6];   // a in X1..X6
  logic [9:0]    x1_a3_q;

  always_ff @(posedge clk_i) begin
    x1_f_q  <= rom[u*FW +: FW];
    x1_a3_q <= m_a3_i;
    x_a_q[1] <= m_a_i;
    for (int unsigned k = 2; k <= 6; k++) begin
      x_a_q[k] <= x_a_q[k-1];
    end
  end

  // ---------------------------------------------------------------------------------------
  // X1..X5: w = a * F; 3w.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0]   x3_w, x4_w_q, x5_w_q, x6_w_q;
  logic [WW+1:0]   x6_w3_q;

  zb_mul8 #(
    .K_W(8),
    .V_W(FW)
  ) u_weight (
    .clk_i(clk_i),
    .k_i  (x_a_q[1]),
    .k3_i (x1_a3_q),
    .v_i  (x1_f_q),
    .t_o  (x3_w)
  );

  always_ff @(posedge clk_i) begin
    x4_w_q  <= x3_w;
    x5_w_q  <= x4_w_q;
    x6_w_q  <= x5_w_q;
    x6_w3_q <= (WW+2)'(x5_w_q) + (WW+2)'({x5_w_q, 1'b0});
  end

  // ---------------------------------------------------------------------------------------
  // X6, X7: the products p_c * w; X8: the terms.
  // ---------------------------------------------------------------------------------------
  for (genvar c = 0; c < 4; c++) begin : g_term
    logic [7:0]    p;   // p_c
    logic [PW-1:0] prod;
    logic [Shift > 0 ? Shift - 1 : 0 : 0] unused_low;
    assign p = c == 3 ? x_a_q[6] : x6_ms_i[8*c +: 8];

    zb_mul8 #(
      .K_W(WW),
      .V_W(8)
    ) u_mul (
      .clk_i(clk_i),
      .k_i  (x6_w_q),
      .k3_i (x6_w3_q),
      .v_i  (p),
      .t_o  (prod)
    );

    assign x8_term_o[ACC_BITS*c +: ACC_BITS] = ACC_BITS'(prod[PW-1 -: TermW]);
    if (Shift > 0) begin : g_low
      assign unused_low = prod[Shift-1:0];
    end else begin : g_nolow
      assign unused_low = 1'b0;
    end
  end

  // ---------------------------------------------------------------------------------------
  // X6, X7: the revealage's factor t = k + (k >> 7), k = 255 - a, and 3t.
  // ---------------------------------------------------------------------------------------
  logic [8:0]  x7_t_q, x8_t_q;
  logic [10:0] x8_t3_q;
  logic [7:0]  unused_ms_a;
  assign unused_ms_a = x6_ms_i[31:24];  // m(a, a): the alpha term uses a itself

  always_ff @(posedge clk_i) begin
    x7_t_q  <= {1'b0, ~x_a_q[6]} + {8'h00, ~x_a_q[6][7]};
    x8_t_q  <= x7_t_q;
    x8_t3_q <= 11'(x7_t_q) + {1'b0, x7_t_q, 1'b0};
  end

  assign x8_t_o  = x8_t_q;
  assign x8_t3_o = x8_t3_q;

endmodule
