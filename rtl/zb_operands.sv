// zb_operands: the fragment side of the blend (docs/rtl.md "Pipeline"), X1..X6, beside the depth
// side: m(s, a) (zb_premul, X1 -> X5), the coverage weight's terms w s (X4 -> X6), then per
// blend mode zb_blend's operands k, 3k, the addend and q (X6 -> X7; zb_blend's header), and
// the accumulate blend's p_c (X5).
// The fragment's colour and 3a travel X1..X6 in arrays indexed by stage.
module zb_operands #(
  parameter int COV_SAMPLES = 16
) (
  input  logic                               clk_i,
  input  zb_pkg::blend_mode_e                blend_i,
  input  logic [31:0]                        m_rgba_i,     // M's fragment: into X1 at E0
  input  logic [9:0]                         m_a3_i,       // its 3 a
  input  logic [$clog2(COV_SAMPLES+1)-1:0]   x4_weight_i,  // X4: coverage weight w
  output logic [31:0]                        x7_k_o,       // X7: zb_blend's operands
  output logic [39:0]                        x7_k3_o,
  output logic [31:0]                        x7_add_o,
  output logic [4*(8+$clog2(COV_SAMPLES+1))-1:0] x7_q_o,
  output logic [31:0]                        x5_p_o        // X5: p_c = m(s, a), p_A = a
);

  localparam int CovW = $clog2(COV_SAMPLES + 1);
  localparam int QW   = 8 + CovW;  // coverage blend addend w*s + N/2 (zb_blend)
  localparam logic [CovW-1:0] Full = CovW'(COV_SAMPLES);
  localparam logic [QW-1:0]   Half = QW'(COV_SAMPLES / 2);

  // The fragment's colour and 3 a in X1..X6.
  logic [31:0] x_rgba_q [1:6];
  logic [9:0]  x_a3_q [1:6];

  always_ff @(posedge clk_i) begin
    x_rgba_q[1] <= m_rgba_i;
    x_a3_q[1]   <= m_a3_i;
    for (int unsigned k = 2; k <= 6; k++) begin
      x_rgba_q[k] <= x_rgba_q[k-1];
      x_a3_q[k]   <= x_a3_q[k-1];
    end
  end

  // ---------------------------------------------------------------------------------------
  // X1..X5: m(s, a); 3 s for the weight terms.
  // ---------------------------------------------------------------------------------------
  logic [31:0] x5_ms;
  logic [39:0] x2_s3_q, x3_s3_q, x4_s3_q;   // 3 s per channel

  zb_premul u_premul (
    .clk_i (clk_i),
    .rgba_i(x_rgba_q[1]),
    .a3_i  (x_a3_q[1]),
    .ms_o  (x5_ms)
  );

  always_ff @(posedge clk_i) begin
    for (int unsigned c = 0; c < 4; c++) begin
      x2_s3_q[10*c +: 10] <= {2'b00, x_rgba_q[1][8*c +: 8]} + {1'b0, x_rgba_q[1][8*c +: 8], 1'b0};
    end
    x3_s3_q <= x2_s3_q;
    x4_s3_q <= x3_s3_q;
  end

  // ---------------------------------------------------------------------------------------
  // X4: the coverage k = N - w and the weight terms, w s = sel(w[1:0]) s + 4 sel(w[3:2]) s +
  // 16 w[4] s.
  // ---------------------------------------------------------------------------------------
  logic [4*12-1:0] x4_wsa, x4_wsb, x5_wsa_q, x5_wsb_q;
  logic [CovW-1:0] x4_kc;
  logic [7:0]      x5_kc_q;
  assign x4_kc = Full - x4_weight_i;
  for (genvar c = 0; c < 4; c++) begin : g_weight
    logic [7:0] s;
    logic [9:0] s3;
    logic [9:0] sel_lo, sel_hi;
    logic [4:0] w5;                 // w <= N <= 16: bits above 4 are zero
    assign s  = x_rgba_q[4][8*c +: 8];
    assign s3 = x4_s3_q[10*c +: 10];
    assign w5 = 5'(x4_weight_i);
    always_comb begin
      unique case (w5[1:0])
        2'd0:    sel_lo = '0;
        2'd1:    sel_lo = {2'b00, s};
        2'd2:    sel_lo = {1'b0, s, 1'b0};
        default: sel_lo = s3;
      endcase
      unique case (w5[3:2])
        2'd0:    sel_hi = '0;
        2'd1:    sel_hi = {2'b00, s};
        2'd2:    sel_hi = {1'b0, s, 1'b0};
        default: sel_hi = s3;
      endcase
    end
    assign x4_wsa[12*c +: 12] = {2'b00, sel_lo} + {sel_hi, 2'b00};
    assign x4_wsb[12*c +: 12] = w5[4] ? {s, 4'h0} : 12'h000;
  end

  always_ff @(posedge clk_i) begin
    x5_kc_q  <= 8'(x4_kc);
    x5_wsa_q <= x4_wsa;
    x5_wsb_q <= x4_wsb;
  end

  // ---------------------------------------------------------------------------------------
  // X5: 3 k, q = w s + N/2, 3 m(s, a), 3 (255 - a).
  // ---------------------------------------------------------------------------------------
  logic [31:0]     x6_ms_q;
  logic [39:0]     x6_ms3_q;
  logic [9:0]      x6_ia3_q;
  logic [7:0]      x6_kc_q;
  logic [9:0]      x6_kc3_q;
  logic [4*QW-1:0] x6_q_q;

  always_ff @(posedge clk_i) begin
    x6_kc_q  <= x5_kc_q;
    x6_kc3_q <= {2'b00, x5_kc_q} + {1'b0, x5_kc_q, 1'b0};
    for (int unsigned c = 0; c < 4; c++) begin
      x6_q_q[QW*c +: QW]   <= QW'(x5_wsa_q[12*c +: 12]) + QW'(x5_wsb_q[12*c +: 12]) + Half;
      x6_ms3_q[10*c +: 10] <= {2'b00, x5_ms[8*c +: 8]} + {1'b0, x5_ms[8*c +: 8], 1'b0};
    end
    x6_ms_q  <= x5_ms;
    x6_ia3_q <= 10'd765 - x_a3_q[5];
  end

  // ---------------------------------------------------------------------------------------
  // X6: per mode, k, 3k and the addend.
  // ---------------------------------------------------------------------------------------
  logic [31:0] x6_k, x6_add;
  logic [39:0] x6_k3;
  logic [7:0]  x6_a;
  assign x6_a = x_rgba_q[6][31:24];

  for (genvar c = 0; c < 4; c++) begin : g_operands
    logic [7:0] s;
    assign s = x_rgba_q[6][8*c +: 8];
    always_comb begin
      x6_k[8*c +: 8]    = 8'h00;                    // replace: m(0) + s = s
      x6_k3[10*c +: 10] = 10'h000;
      x6_add[8*c +: 8]  = s;
      unique case (blend_i)
        zb_pkg::BlendAlpha: begin
          x6_k[8*c +: 8]    = ~x6_a;
          x6_k3[10*c +: 10] = x6_ia3_q;
          x6_add[8*c +: 8]  = x6_ms_q[8*c +: 8];
        end
        zb_pkg::BlendAdditive: begin  // m(d, 255) = d
          x6_k[8*c +: 8]    = 8'hff;
          x6_k3[10*c +: 10] = 10'd765;
          x6_add[8*c +: 8]  = x6_ms_q[8*c +: 8];
        end
        zb_pkg::BlendCoverage: begin
          x6_k[8*c +: 8]    = x6_kc_q;
          x6_k3[10*c +: 10] = x6_kc3_q;
          x6_add[8*c +: 8]  = 8'h00;
        end
        zb_pkg::BlendUnder: begin     // RGB scale m(s, a), alpha a
          x6_k[8*c +: 8]    = (c == 3) ? x6_a : x6_ms_q[8*c +: 8];
          x6_k3[10*c +: 10] = (c == 3) ? x_a3_q[6] : x6_ms3_q[10*c +: 10];
          x6_add[8*c +: 8]  = 8'h00;
        end
        default: ;
      endcase
    end
  end

  // The accumulate blend's p (zb_blend multiplies it by zb_weight's w in accumulate mode).
  assign x5_p_o = {x_rgba_q[5][31:24], x5_ms[23:0]};

  always_ff @(posedge clk_i) begin
    x7_k_o   <= x6_k;
    x7_k3_o  <= x6_k3;
    x7_add_o <= x6_add;
    x7_q_o   <= x6_q_q;
  end

endmodule
