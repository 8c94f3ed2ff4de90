// zb_resolve_layers: mlab-K's resolve (docs/datapath.md "8. Layers") applied to a tile read's
// colour on its way out of the port (docs/rtl.md "Tile operations"): per lane, the layers read
// with the beat (zb_layers' plane, {z, A, R, G, B} a slot) under one another front to back from
// (0, 0, 0, 0), acc_c = min(255, acc_c + m(p_c, 255 - acc_A)) for R, G, B and A, then over the
// colour o: min(255, acc_c + m(o_c, 255 - acc_A)). An empty slot (A = 0, colour 0) adds
// nothing. Combinational, one view for Verilator and synthesis; evaluated only under en_i (a
// store's beats), not on every cycle the port's read data is.
module zb_resolve_layers #(
  parameter int BEAT       = 8,
  parameter int DEPTH_BITS = 24,
  parameter int LAYERS     = 4,
  localparam int LW        = DEPTH_BITS + 32,
  localparam int WW        = LAYERS * LW
) (
  input  logic                 en_i,      // resolve this beat (else it passes unchanged)
  input  logic [BEAT*32-1:0]   color_i,   // o, r | g << 8 | b << 16 | a << 24 a lane
  input  logic [BEAT*WW-1:0]   layers_i,
  output logic [BEAT*32-1:0]   color_o
);

  // m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x * y: t[15:8] + ((t[7:0] + t[15:8] + 0x80) >> 8).
  function automatic logic [7:0] m(logic [7:0] x, logic [7:0] y);
    m = 8'((18'(x) * 18'(y) + ((18'(x) * 18'(y)) >> 8) + 18'h80) >> 8);
  endfunction

  function automatic logic [7:0] sat_add(logic [7:0] x, logic [7:0] y);
    logic [8:0] s;
    s = 9'(x) + 9'(y);
    sat_add = s[8] ? 8'hff : s[7:0];
  endfunction

`ifdef ZB_INJECT_TILEOP_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_resolve_layers: the layers
  // composited back to front (the resolve's order reversed).
  logic bug_order;
  initial bug_order = $test$plusargs("zb_bug_resolve_layers") != 0;
`else
  logic bug_order;
  assign bug_order = 1'b0;
`endif

  for (genvar l = 0; l < BEAT; l++) begin : g_lane
    for (genvar j = 0; j < LAYERS; j++) begin : g_layer
      // acc_in: the nearer j layers composited, r | g << 8 | b << 16 | a << 24; acc: with this one.
      logic [31:0] acc_in, acc, near, far, p;
      logic [7:0]  inv;
      if (j == 0) begin : g_first
        assign acc_in = '0;
      end else begin : g_next
        assign acc_in = g_layer[j-1].acc;
      end
      assign near = layers_i[l*WW + j*LW +: 32];
      assign far  = layers_i[l*WW + (LAYERS-1-j)*LW +: 32];
      assign p    = bug_order ? {far[31:24], far[7:0], far[15:8], far[23:16]}
                              : {near[31:24], near[7:0], near[15:8], near[23:16]};
      assign inv  = 8'hff - acc_in[31:24];
      for (genvar c = 0; c < 4; c++) begin : g_ch
        assign acc[c*8 +: 8] = sat_add(acc_in[c*8 +: 8], m(p[c*8 +: 8], inv));
      end
      logic unused_z;
      assign unused_z = ^layers_i[l*WW + j*LW + 32 +: DEPTH_BITS];
    end
    logic [31:0] acc;
    logic [7:0]  inv;
    assign acc = g_layer[LAYERS-1].acc;
    assign inv = 8'hff - acc[31:24];
    for (genvar c = 0; c < 4; c++) begin : g_out
      assign color_o[l*32 + c*8 +: 8] = !en_i ? color_i[l*32 + c*8 +: 8]
                                        : sat_add(acc[c*8 +: 8], m(color_i[l*32 + c*8 +: 8], inv));
    end
  end

endmodule
