// zb_blend: the blend unit of docs/datapath.md "3. Blend", all four channels, combinational.
//   m(x, y)   = (t + (t >> 8) + 0x80) >> 8, t = x * y   (llvmpipe's unorm8 multiply)
//   replace:  c' = s
//   alpha:    c' = min(255, m(s, a) + m(d, 255 - a))
//   additive: c' = min(255, d + m(s, a))
//   coverage: c' = (w * s + (N - w) * d + N/2) >> log2(N), w = weight_i (zb_coverage_composite)
//   under:    t = 255 - A_d (destination alpha, dst_i[31:24]), premultiplied destination;
//             RGB c' = min(255, d + m(m(s, a), t)), alpha A' = min(255, A_d + m(a, t))
// a is the source alpha (src_i[31:24]) for every channel, alpha included. The coverage blend
// treats alpha as a fourth channel, weighted by coverage like R, G and B.
module zb_blend #(
  parameter int unsigned COV_SAMPLES = 16,  // N: 1, 2, 4, 8 or 16
  localparam int unsigned CovW       = $clog2(COV_SAMPLES + 1)
) (
  input  logic [2:0]      mode_i,    // 0 replace, 1 alpha, 2 additive, 3 coverage, 4 under
  input  logic [31:0]     src_i,     // fragment colour: r [7:0], g [15:8], b [23:16], a [31:24]
  input  logic [31:0]     dst_i,     // stored colour, same packing
  input  logic [CovW-1:0] weight_i,  // coverage: samples of src_i, 0..N
  output logic [31:0]     color_o
);

  localparam int unsigned CovLog = $clog2(COV_SAMPLES);
  // w * s + (N - w) * d + N/2 <= 255 N + N/2 < 2^(8 + CovLog): AccW = 8 + CovW bits hold it.
  localparam int unsigned AccW = 8 + CovW;
  localparam logic [CovW-1:0] Full = CovW'(COV_SAMPLES);
  localparam logic [AccW-1:0] Half = AccW'(COV_SAMPLES / 2);

  // m(x, y). t + (t >> 8) + 0x80 <= 65025 + 254 + 128 = 65407 fits 16 bits; m is its upper
  // byte (the lower byte is the discarded fraction).
  function automatic logic [7:0] mul_unorm8(logic [7:0] x, logic [7:0] y);
    logic [15:0] t;
    logic [7:0]  m;
    logic [7:0]  unused_frac;
    t = {8'h00, x} * {8'h00, y};
    {m, unused_frac} = t + {8'h00, t[15:8]} + 16'h0080;
    mul_unorm8 = m;
  endfunction

  function automatic logic [7:0] sat_add8(logic [7:0] x, logic [7:0] y);
    logic [8:0] sum;
    sum = {1'b0, x} + {1'b0, y};
    sat_add8 = sum[8] ? 8'hff : sum[7:0];
  endfunction

  logic [7:0] alpha, inv_alpha;
  logic [31:0] alpha_blend, add_blend, cov_blend, under_blend;
  logic [7:0]  dst_alpha, inv_dst_alpha;

  assign dst_alpha     = dst_i[31:24];
  assign inv_dst_alpha = 8'hff - dst_alpha;
  logic [CovW-1:0] inv_weight;

  assign alpha     = src_i[31:24];
  assign inv_alpha = 8'hff - alpha;
  assign inv_weight = Full - weight_i;

  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic [7:0] s, d, ms;
    assign s  = src_i[8*c +: 8];
    assign d  = dst_i[8*c +: 8];
    assign ms = mul_unorm8(s, alpha);
    assign alpha_blend[8*c +: 8] = sat_add8(ms, mul_unorm8(d, inv_alpha));
    assign add_blend[8*c +: 8]   = sat_add8(d, ms);
    // Under: RGB scale the premultiplied source m(s, a); alpha scales a itself (m(a, a) would
    // square it). c = 3 is alpha: s = a there, so the source term is m(a, t).
    if (c < 3) begin : g_under_rgb
      assign under_blend[8*c +: 8] = sat_add8(d, mul_unorm8(ms, inv_dst_alpha));
    end else begin : g_under_a
      assign under_blend[8*c +: 8] = sat_add8(d, mul_unorm8(s, inv_dst_alpha));
    end

    // Coverage: the sum, shifted right by log2(N); its bits above 7 are always zero.
    logic [AccW-1:0] acc, shifted;
    logic            unused_hi;
    assign acc     = AccW'(s) * AccW'(weight_i) + AccW'(d) * AccW'(inv_weight) + Half;
    assign shifted = acc >> CovLog;
    assign cov_blend[8*c +: 8] = shifted[7:0];
    assign unused_hi = ^shifted[AccW-1:8];
  end

  always_comb begin
    color_o = src_i;
    unique case (mode_i)
      3'd0:    color_o = src_i;        // replace
      3'd1:    color_o = alpha_blend;  // alpha
      3'd2:    color_o = add_blend;    // additive
      3'd3:    color_o = cov_blend;    // coverage
      3'd4:    color_o = under_blend;  // under
      default: color_o = src_i;
    endcase
`ifdef ZB_INJECT_BLEND_BUG
    // Deliberate defect for checker tests: alpha blend, odd source alpha, red bit 0 flipped.
    if (mode_i == 3'd1 && alpha[0]) begin
      color_o[0] = ~color_o[0];
    end
`endif
  end

endmodule
