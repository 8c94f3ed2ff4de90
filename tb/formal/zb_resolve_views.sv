// zb_resolve as zb_rop drives it, for the proof that its two views are equal
// (scripts/equiv.py): every input free, the beat compared whether resolved or not.
module zb_resolve_views #(
  parameter int BEAT = 8
) (
  input  logic               en_i,
  input  logic [31:0]        bg_i,
  input  logic [BEAT*32-1:0] color_i,
  output logic [BEAT*32-1:0] color_o
);
  zb_resolve #(.BEAT(BEAT)) u_res (
    .en_i   (en_i),
    .bg_i   (bg_i),
    .color_i(color_i),
    .color_o(color_o)
  );
endmodule
