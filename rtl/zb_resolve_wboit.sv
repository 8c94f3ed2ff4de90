// zb_resolve_wboit: the accumulate blend's resolve (docs/datapath.md "Resolve (frame operation
// 4)") applied to a tile read's colour on its way out of the port (docs/rtl.md "Tile
// operations"): per lane and channel, the weighted average of the accumulation over the opaque
// colour C0 by the revealage r, with one = 2^REV_BITS - 1:
//   avg = acc_A == 0 ? 0 : min(255, (acc * 255 + acc_A / 2) / acc_A)   (alpha: acc = acc_A)
//   c'  = (avg * (one - r) + C0 * r + one / 2) / one
// for every input word (acc <= acc_A, which the datapath keeps, is not assumed: the min pins
// the others). Combinational, one view for Verilator and synthesis: a divider for avg, a
// shifted sum for the division by one; evaluated only under en_i (a few beats a frame, at the
// store), not on every cycle the port's read data is.
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

  localparam int NumW = ACC_BITS + 8;                      // acc * 255 + acc_A / 2
  localparam logic [REV_BITS-1:0] One = REV_BITS'((1 << REV_BITS) - 1);  // not '1: Yosys 0.23

`ifdef ZB_INJECT_TILEOP_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_resolve_wboit: the final
  // division truncates (no one / 2).
  logic bug_wboit;
  initial bug_wboit = $test$plusargs("zb_bug_resolve_wboit") != 0;
`endif

  // Restoring division with 8 quotient bits, n / d for n < d * 256 (the high part n >> 8 is
  // the first remainder): avg's, once the min keeps it at most 255. Not `/`, which Yosys builds
  // at twice the dividend's width on every step.
  function automatic logic [7:0] div8(logic [NumW-1:0] n, logic [ACC_BITS-1:0] d);
    logic [ACC_BITS:0] r;
    r = {1'b0, n[NumW-1:8]};
    for (int i = 7; i >= 0; i--) begin
      r = {r[ACC_BITS-1:0], n[i]};
      div8[i] = r >= {1'b0, d};
      if (div8[i]) r = r - {1'b0, d};
    end
  endfunction

  localparam int MixW = REV_BITS + 8;  // avg * (one - r) + C0 * r + one / 2 < 256 * one

  function automatic logic [7:0] channel(logic [ACC_BITS-1:0] acc, logic [ACC_BITS-1:0] acc_a,
                                         logic [7:0] c0, logic [REV_BITS-1:0] r, logic trunc);
    logic [ACC_BITS-1:0] half_a;
    logic [NumW-1:0]     n;
    logic [MixW-1:0]     mix, q;
    logic [REV_BITS-1:0] inv_r, half_one;
    logic [7:0]          avg;
    half_a   = acc_a >> 1;
    n        = NumW'(acc) * NumW'(255) + NumW'(half_a);
    inv_r    = One - r;
    half_one = trunc ? '0 : One >> 1;
    if (acc_a == '0)               avg = '0;
    else if (n[NumW-1:8] >= acc_a) avg = 8'd255;  // the min: only for acc > acc_A
    else                           avg = div8(n, acc_a);
    mix = MixW'(avg) * MixW'(inv_r) + MixW'(c0) * MixW'(r) + MixW'(half_one);
    // mix / one for mix < 256 * one, one = 2^R - 1: (mix + 1 + (mix >> R)) >> R, exact there for
    // every R of 8..16 (tests/rtl/test_rtl_tile.cpp checks every mix).
    q = mix + MixW'(1) + (mix >> REV_BITS);
    channel = 8'(q >> REV_BITS);
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
