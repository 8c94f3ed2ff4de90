// zb_color_mask: docs/datapath.md "4. Colour write mask". Combinational, per channel:
// mask bit c set ? blended : stored. Bit 0 R [7:0], 1 G [15:8], 2 B [23:16], 3 A [31:24].
module zb_color_mask (
  input  logic [3:0]  mask_i,
  input  logic [31:0] blended_i,
  input  logic [31:0] dst_i,
  output logic [31:0] color_o
);

  for (genvar c = 0; c < 4; c++) begin : g_chan
    assign color_o[8*c +: 8] = mask_i[c] ? blended_i[8*c +: 8] : dst_i[8*c +: 8];
  end

endmodule
