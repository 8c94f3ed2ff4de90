// zb_premul: the fragment's premultiplied colour m(s, a) for its four channels (a the source
// alpha, every channel, alpha included), m(x, y) = (t + (t >> 8) + 0x80) >> 8 with t = x * y.
// It depends on the fragment alone, so zb_rop computes it while the fragment is in the depth
// stages, off the colour read-modify-write path. Latency 4: rgba_i and a3_i in cycle c, ms_o
// in cycle c + 4 (registered).
//   c, c+1  zb_mul8: t = s * a
//   c+2     lo = (t[7:0] + t[15:8] + 0x80) >> 8 (0..2); keep it and t[15:8]
//   c+3     m = t[15:8] + lo  (t + (t >> 8) + 0x80 = 256 t[15:8] + t[7:0] + t[15:8] + 0x80)
module zb_premul (
  input  logic        clk_i,
  input  logic [31:0] rgba_i,
  input  logic [9:0]  a3_i,    // 3 * rgba_i[31:24]
  output logic [31:0] ms_o
);

  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic [15:0] t;
    logic [8:0]  u;
    logic [1:0]  lo;    // (t[7:0] + t[15:8] + 0x80) >> 8
    logic [7:0]  hi_q, m_q;
    logic [1:0]  carry_q;
    logic [6:0]  unused_u;

    zb_mul8 u_mul (
      .clk_i(clk_i),
      .k_i  (rgba_i[31:24]),
      .k3_i (a3_i),
      .v_i  (rgba_i[8*c +: 8]),
      .t_o  (t)
    );

    // (u + 0x80) >> 8 for u < 512 is 0, 1, 1, 2 as u[8:7] is 0, 1, 2, 3: one 8-bit adder.
    assign u        = {1'b0, t[7:0]} + {1'b0, t[15:8]};
    assign lo       = {u[8] & u[7], u[8] ^ u[7]};
    assign unused_u = u[6:0];

    always_ff @(posedge clk_i) begin
      hi_q    <= t[15:8];
      carry_q <= lo;
      m_q     <= hi_q + {6'h00, carry_q};
    end

    assign ms_o[8*c +: 8] = m_q;
  end

endmodule
