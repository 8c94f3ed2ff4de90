// zb_blend: the blend unit of docs/datapath.md "3. Blend" and the write mask, all four channels,
// pipelined over four stages (latency 4: dst_i in cycle c, color_o in cycle c + 4, not
// registered: it drives the colour write). Every mode is one form,
//   c' = min(255, m(k * v) + add),  m(t) = (t + (t >> 8) + 0x80) >> 8
// with k and add from the fragment side (zb_rop selects them per mode before the colour read,
// with k3 = 3k for the radix-4 multiplier) and v from the stored colour:
//   replace:  k = 0,      add = s              -> s
//   alpha:    k = 255-a,  add = m(s, a), v = d -> min(255, m(s, a) + m(d, 255 - a))
//   additive: k = 255,    add = m(s, a), v = d -> min(255, m(s, a) + d)   (m(d, 255) = d)
//   under:    k = m(s, a) (alpha channel: a), v = 255 - A_d, add = d
//             -> min(255, d + m(m(s, a), 255 - A_d)), alpha min(255, A_d + m(a, 255 - A_d))
// and coverage, c' = (k * d + q) >> log2 N with k = N - w and q = w*s + N/2 from the fragment
// side (no m, no saturation: the sum is below 256 N).
// Accumulate mode writes no colour: its multipliers form zb_accum's products p_c * w instead
// (k = w, K_W bits, from zb_weight; v = p_c). Their operands come two cycles early (X5, where
// the colour path's come in X7), so the products are out at c+1 (X8): the mode holds while
// fragments are in flight (zb_rop's StateWriteIdle), so nothing else is in these stages.
//   c     v = under ? 255 - A_d : d; add = under ? d : add_i
//   c+1   zb_mul8 stage 1;           c+2   zb_mul8 stage 2: t = k * v
//   c+3   lo = (t[7:0] + t[15:8] + 0x80) >> 8 (0..2) completes m = t[15:8] + lo; so
//         r_j = min(255, t[15:8] + add + j) for j = 0, 1, 2 in parallel (add + j formed a
//         cycle earlier: each r_j is one carry chain); the coverage result, and the write
//         mask's alternative alt = mask ? coverage : d
//   c+4   r = r_lo; colour = (mask && !coverage) ? r : alt  (no carry chain here: it
//         drives the RAM's write data)
module zb_blend
#(
  parameter int COV_SAMPLES = 16,  // N: 1, 2, 4, 8 or 16
  parameter int K_W         = 8,   // k's width: 8, or the accumulate blend's w (zb_weight)
  localparam int CovW       = $clog2(COV_SAMPLES + 1),
  localparam int QW         = 8 + CovW  // w*s + N/2 < 2^(8 + log2 N + 1)
) (
  input  logic            clk_i,
  input  zb_pkg::blend_mode_e mode_i,
  input  logic [3:0]      mask_i,   // write mask, bit c for channel c
  input  logic [31:0]     dst_i,    // stored colour, cycle c: r [7:0], g, b, a [31:24]
  input  logic [31:0]     k_i,      // per channel, cycle c
  input  logic [39:0]     k3_i,     // per channel 3 * k, 10 bits each
  input  logic [31:0]     add_i,    // per channel (not used in under mode)
  input  logic [4*QW-1:0] q_i,      // per channel, coverage mode
  input  logic [K_W-1:0]  w_i,      // accumulate mode, cycle c - 2: k of every channel
  input  logic [K_W+1:0]  w3_i,     // 3 w
  input  logic [31:0]     p_i,      // accumulate mode, cycle c - 2: v per channel
  output logic [31:0]     color_o,  // cycle c + 4: blended and masked
  output logic [4*(K_W+8)-1:0] prod_o  // accumulate mode, cycle c + 1: per channel w * p
);

  localparam int CovLog = $clog2(COV_SAMPLES);

  logic under, cov, acc;
  assign under = mode_i == zb_pkg::BlendUnder;
  assign cov   = mode_i == zb_pkg::BlendCoverage;
  assign acc   = mode_i == zb_pkg::BlendAccumulate;

  // The write mask's alternative to r, formed a cycle early: coverage result or stored colour.
  logic [31:0] cov3, d3, alt_d;

  zb_color_mask u_alt (
    .mask_i   (mask_i),
    .blended_i(cov3),
    .dst_i    (d3),
    .color_o  (alt_d)
  );

  for (genvar c = 0; c < 4; c++) begin : g_chan
    // c -> c+1
    logic [7:0]    v1_q, add1_q, d1_q;
    logic [K_W-1:0] k1_q;
    logic [K_W+1:0] k31_q;
    logic [QW-1:0] q1_q;
    // c+1 .. c+3: the multiplier's two stages; add, d and q ride along
    logic [7:0]    add2_q, d2_q, d3_q;
    logic [26:0]   add3_q;         // add + j at [9*j +: 9], j = 0, 1, 2: one adder per sum
    logic [QW-1:0] q2_q, q3_q;
    logic [K_W+7:0] t;
    // c+3 -> c+4
    logic [8:0]    u;
    logic [1:0]    lo;             // (t[7:0] + t[15:8] + 0x80) >> 8
    logic [1:0]    carry4_q;
    logic [QW-1:0] cs_d;
    logic [7:0]    alt4_q;
    logic [23:0]   r_d, r4_q;      // r_j at [8*j +: 8]
    logic [7:0]    r;
    logic [6:0]    unused_u;
    logic [QW-9:0] unused_cs;

    always_ff @(posedge clk_i) begin
      v1_q     <= acc ? p_i[8*c +: 8] : (under ? ~dst_i[31:24] : dst_i[8*c +: 8]);
      add1_q   <= under ? dst_i[8*c +: 8] : add_i[8*c +: 8];
      k1_q     <= acc ? w_i : K_W'(k_i[8*c +: 8]);
      k31_q    <= acc ? w3_i : (K_W+2)'(k3_i[10*c +: 10]);
      d1_q     <= dst_i[8*c +: 8];
      q1_q     <= q_i[QW*c +: QW];
      add2_q   <= add1_q;
      for (int unsigned j = 0; j < 3; j++) begin
        add3_q[9*j +: 9] <= {1'b0, add2_q} + 9'(j);
      end
      d2_q     <= d1_q;
      d3_q     <= d2_q;
      q2_q     <= q1_q;
      q3_q     <= q2_q;
      carry4_q <= lo;
      alt4_q   <= alt_d[8*c +: 8];
      r4_q     <= r_d;
    end

    zb_mul8 #(
      .K_W(K_W),
      .V_W(8)
    ) u_mul (
      .clk_i(clk_i),
      .k_i  (k1_q),
      .k3_i (k31_q),
      .v_i  (v1_q),
      .t_o  (t)
    );

    // (u + 0x80) >> 8 for u < 512 is 0, 1, 1, 2 as u[8:7] is 0, 1, 2, 3: one 8-bit adder.
    assign u        = {1'b0, t[7:0]} + {1'b0, t[15:8]};
    assign lo       = {u[8] & u[7], u[8] ^ u[7]};
    assign unused_u = u[6:0];
    // m(k v) + add = t[15:8] + add + lo <= 255 + 255 + 2: saturate on bit 8 or 9.
    for (genvar j = 0; j < 3; j++) begin : g_sum
      logic [9:0] h;
      assign h      = {2'b00, t[15:8]} + {1'b0, add3_q[9*j +: 9]};
      assign r_d[8*j +: 8] = (h[9] | h[8]) ? 8'hff : h[7:0];
    end
    assign cs_d      = (QW'(t) + q3_q) >> CovLog;
    assign prod_o[(K_W+8)*c +: K_W+8] = t;
    assign unused_cs = cs_d[QW-1:8];

    assign cov3[8*c +: 8] = cs_d[7:0];
    assign d3[8*c +: 8]   = d3_q;

    always_comb begin
      unique case (carry4_q)
        2'd0:    r = r4_q[7:0];
        2'd1:    r = r4_q[15:8];
        default: r = r4_q[23:16];
      endcase
    end

`ifdef ZB_INJECT_BLEND_BUG
    // Deliberate defect for checker tests: alpha blend, odd source alpha (k = 255 - a even),
    // red bit 0 flipped. The flag rides the pipeline with the fragment. On unless a plusarg
    // picks another defect: +zb_bug_window, +zb_bug_accum, +zb_bug_copy or +zb_bug_resolve
    // (zb_issue_window, zb_accum, zb_depth, zb_resolve).
    if (c == 0) begin : g_bug
      logic [4:1] bug_q;
      logic       bug_on;
      initial bug_on = $test$plusargs("zb_bug_window") == 0
                       && $test$plusargs("zb_bug_accum") == 0
                       && $test$plusargs("zb_bug_copy") == 0
                       && $test$plusargs("zb_bug_resolve") == 0;
      always_ff @(posedge clk_i) begin
        bug_q <= {bug_q[3:1], bug_on && mode_i == zb_pkg::BlendAlpha && !k_i[0]};
      end
      assign color_o[8*c +: 8] = (mask_i[c] && !cov) ? {r[7:1], r[0] ^ bug_q[4]} : alt4_q;
    end else begin : g_nobug
      assign color_o[8*c +: 8] = (mask_i[c] && !cov) ? r : alt4_q;
    end
`else
    assign color_o[8*c +: 8] = (mask_i[c] && !cov) ? r : alt4_q;
`endif
  end

endmodule
