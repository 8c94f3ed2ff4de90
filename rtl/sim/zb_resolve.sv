// zb_resolve, simulation view (docs/rtl.md "Two builds, two views"): rtl/zb_resolve.sv is the
// synthesis view and the specification. Every Verilated model reads this file instead: the
// lanes' products are computed only when en_i resolves the beat, which is a few beats a frame,
// not on every cycle the colour port's read data is evaluated. scripts/equiv.py proves the two
// views equal.
module zb_resolve #(
  parameter int BEAT = 8
) (
  input  logic              en_i,
  input  logic [31:0]       bg_i,
  input  logic [BEAT*32-1:0] color_i,
  output logic [BEAT*32-1:0] color_o
);

`ifdef ZB_INJECT_TILEOP_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_resolve: no saturation
  // (the sum wraps).
  logic bug_resolve;
  initial bug_resolve = $test$plusargs("zb_bug_resolve") != 0;
`endif

  // One channel: min(255, c + m(bg, 255 - a)), as the synthesis view's g_channel.
  function automatic logic [7:0] resolve8(logic [7:0] c, logic [7:0] bg, logic [7:0] a,
                                          logic wrap);
    logic [15:0] t;
    logic [7:0]  m;
    logic [8:0]  sum;
    logic [7:0]  inv_a;
    inv_a = 8'd255 - a;
    t   = 16'(bg) * 16'(inv_a);
    m   = 8'((17'(t) + 17'(t[15:8]) + 17'h80) >> 8);
    sum = 9'(c) + 9'(m);
    resolve8 = sum[8] && !wrap ? 8'hff : sum[7:0];
  endfunction

  logic wrap;
`ifdef ZB_INJECT_TILEOP_BUG
  assign wrap = bug_resolve;
`else
  assign wrap = 1'b0;
`endif

  always_comb begin
    color_o = color_i;
    if (en_i) begin
      for (int l = 0; l < BEAT; l++) begin
        for (int c = 0; c < 4; c++) begin
          color_o[l*32 + c*8 +: 8] = resolve8(color_i[l*32 + c*8 +: 8], bg_i[c*8 +: 8],
                                              color_i[l*32 + 24 +: 8], wrap);
        end
      end
    end
  end

endmodule
