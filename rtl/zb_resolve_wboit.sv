// zb_resolve_wboit: the accumulate blend's resolve (docs/datapath.md "Resolve (frame operation
// 4)") applied to a tile read's colour on its way out of the port (docs/rtl.md "Tile
// operations"): per lane and channel, the weighted average of the accumulation over the opaque
// colour C0 by the revealage r, with one = 2^REV_BITS - 1:
//   avg = acc_A == 0 ? 0 : (acc * 255 + acc_A / 2) / acc_A     (alpha: acc = acc_A)
//   c'  = (avg * (one - r) + C0 * r + one / 2) / one, its low 8 bits
// at full width, so every input word gives the golden model's bits (acc <= acc_A, which the
// datapath keeps, is not assumed). Combinational, one view for Verilator and synthesis: the
// dividers are evaluated only under en_i (a few beats a frame, at the store), not on every
// cycle the port's read data is.
module zb_resolve_wboit #(
  parameter int BEAT     = 8,
  parameter int ACC_BITS = 16,
  parameter int REV_BITS = 8,
  localparam int AccW    = 4 * ACC_BITS + REV_BITS  // {r, acc_A, acc_B, acc_G, acc_R}
) (
  input  logic               en_i,     // resolve this beat (else it passes unchanged)
  input  logic [BEAT*32-1:0]   color_i,  // C0, r | g << 8 | b << 16 | a << 24 a lane
  input  logic [BEAT*AccW-1:0] acc_i,
  output logic [BEAT*32-1:0]   color_o
);

  localparam int AvgW = ACC_BITS + 8;             // avg <= acc * 255 (acc_A = 1)
  localparam int NumW = AvgW + REV_BITS + 1;      // avg * (one - r) + C0 * r + one / 2
  localparam logic [REV_BITS-1:0] One = REV_BITS'((1 << REV_BITS) - 1);  // not '1: Yosys 0.23

`ifdef ZB_INJECT_TILEOP_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_resolve_wboit: the final
  // division truncates (no one / 2).
  logic bug_wboit;
  initial bug_wboit = $test$plusargs("zb_bug_resolve_wboit") != 0;
`endif

  // Restoring division, a quotient bit a step (n / d, d > 0), each at its own widths: Yosys's
  // `/` builds every step at twice the dividend's width, which the lab configuration's 64
  // dividers do not afford.
  function automatic logic [AvgW-1:0] div_acc(logic [AvgW-1:0] n, logic [ACC_BITS-1:0] d);
    logic [ACC_BITS:0] r;
    r = '0;
    for (int i = AvgW - 1; i >= 0; i--) begin
      r = {r[ACC_BITS-1:0], n[i]};
      div_acc[i] = r >= {1'b0, d};
      if (div_acc[i]) r = r - {1'b0, d};
    end
  endfunction

  function automatic logic [NumW-1:0] div_one(logic [NumW-1:0] n);
    logic [REV_BITS:0] r;
    r = '0;
    for (int i = NumW - 1; i >= 0; i--) begin
      r = {r[REV_BITS-1:0], n[i]};
      div_one[i] = r >= {1'b0, One};
      if (div_one[i]) r = r - {1'b0, One};
    end
  endfunction

  function automatic logic [7:0] channel(logic [ACC_BITS-1:0] acc, logic [ACC_BITS-1:0] acc_a,
                                         logic [7:0] c0, logic [REV_BITS-1:0] r, logic trunc);
    logic [ACC_BITS-1:0] half_a;
    logic [REV_BITS-1:0] inv_r, half_one;
    logic [AvgW-1:0]     avg;
    logic [NumW-1:0]     num;
    half_a   = acc_a >> 1;
    inv_r    = One - r;
    half_one = trunc ? '0 : One >> 1;
    avg = acc_a == '0 ? '0 : div_acc(AvgW'(acc) * AvgW'(255) + AvgW'(half_a), acc_a);
    num = NumW'(avg) * NumW'(inv_r) + NumW'(c0) * NumW'(r) + NumW'(half_one);
    channel = 8'(div_one(num));
  endfunction

  logic trunc;
`ifdef ZB_INJECT_TILEOP_BUG
  assign trunc = bug_wboit;
`else
  assign trunc = 1'b0;
`endif

  always_comb begin
    color_o = color_i;
    if (en_i) begin
      for (int l = 0; l < BEAT; l++) begin
        for (int c = 0; c < 4; c++) begin
          color_o[l*32 + c*8 +: 8] = channel(acc_i[l*AccW + c*ACC_BITS +: ACC_BITS],
                                             acc_i[l*AccW + 3*ACC_BITS +: ACC_BITS],
                                             color_i[l*32 + c*8 +: 8],
                                             acc_i[l*AccW + 4*ACC_BITS +: REV_BITS], trunc);
        end
      end
    end
  end

endmodule
