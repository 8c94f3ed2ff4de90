// Formal (docs/formal.md, group resolve): zb_resolve's channel CHAN of every lane equals the
// resolve under the background of docs/datapath.md ("Frame operations", 3):
// min(255, c + m(bg_c, 255 - a)), m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x * y, and passes
// the colour unchanged when en_i is low, for every input. Combinational: one step proves it.
// ZB_FORMAL_DEFECT_RESOLVE drops the saturation from the specification: the proof must fail.
module zb_resolve_check #(
  parameter int unsigned BEAT = 1,
  parameter int unsigned CHAN = 0  // the channel checked, 0..3: one multiplier a lane a job
) (
  input logic                  clk_i,  // the flow's clock; the check itself is combinational
  input logic                  en_i,
  input logic [31:0]           bg_i,
  input logic [BEAT*32-1:0]    color_i
);
  logic [BEAT*32-1:0] color_o;

  zb_resolve #(.BEAT(BEAT)) dut (
    .en_i   (en_i),
    .bg_i   (bg_i),
    .color_i(color_i),
    .color_o(color_o)
  );

  logic [BEAT-1:0] ok;  // per lane; one assertion over them (yosys names a label once)
  for (genvar l = 0; l < BEAT; l++) begin : g_lane
    logic [7:0]  c, a, spec;
    logic [16:0] t, m;
    logic [8:0]  v;
    assign c = color_i[l*32 + 8*CHAN +: 8];
    assign a = color_i[l*32 + 24 +: 8];
    assign t = 17'(16'(bg_i[8*CHAN +: 8]) * 16'(8'd255 - a));  // exact: 8 x 8 bits fit 16
    assign m = (t + (t >> 8) + 17'h80) >> 8;
    assign v = 9'(c) + 9'(m[7:0]);
`ifdef ZB_FORMAL_DEFECT_RESOLVE
    assign spec = v[7:0];
`else
    assign spec = v[8] ? 8'hff : v[7:0];
`endif
    assign ok[l] = color_o[l*32 + 8*CHAN +: 8] == (en_i ? spec : c);
  end
  always_comb begin
    ResolveIsSpec: assert (&ok);
  end

  logic unused;
  assign unused = clk_i;
endmodule
