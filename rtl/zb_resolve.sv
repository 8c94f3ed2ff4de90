// zb_resolve: the under blend's resolve over the background (docs/datapath.md "Depth peeling"),
// applied to a tile read's colour on its way out of the port (docs/rtl.md "Tile operations"):
// each channel of each lane min(255, c + m(bg, 255 - a)), m the rounded unorm8 product of
// zb_mul8's callers. Combinational: the read's beat still leaves the port a cycle after the read.
module zb_resolve #(
  parameter int BEAT = 8
) (
  input  logic              en_i,     // resolve this beat (else it passes unchanged)
  input  logic [31:0]       bg_i,     // the background, r | g << 8 | b << 16 | a << 24
  input  logic [BEAT*32-1:0] color_i,
  output logic [BEAT*32-1:0] color_o
);

  for (genvar l = 0; l < BEAT; l++) begin : g_lane
    logic [7:0] inv_a;
    assign inv_a = 8'd255 - color_i[l*32 + 24 +: 8];
    for (genvar c = 0; c < 4; c++) begin : g_channel
      logic [15:0] t;
      logic [16:0] r;
      logic [8:0]  sum;
      assign t   = bg_i[c*8 +: 8] * inv_a;
      assign r   = 17'(t) + 17'(t[15:8]) + 17'h80;
      assign sum = 9'(color_i[l*32 + c*8 +: 8]) + 9'(r[15:8]);
`ifdef ZB_INJECT_TILEOP_BUG
      // Deliberate defect for checker tests, on with the plusarg +zb_bug_resolve: no
      // saturation (the sum wraps).
      logic bug_resolve;
      initial bug_resolve = $test$plusargs("zb_bug_resolve") != 0;
      assign color_o[l*32 + c*8 +: 8] = !en_i ? color_i[l*32 + c*8 +: 8]
                                        : sum[8] && !bug_resolve ? 8'hff : sum[7:0];
`else
      assign color_o[l*32 + c*8 +: 8] = !en_i ? color_i[l*32 + c*8 +: 8]
                                        : sum[8] ? 8'hff : sum[7:0];
`endif
      logic unused_r;
      assign unused_r = ^{r[16], r[7:0]};
    end
  end

endmodule
