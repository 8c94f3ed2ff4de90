// zb_mul8 as zb_rop drives it, for the proof that its two views are equal (scripts/equiv.py):
// k3_i is 3k, as every caller computes it.
module zb_mul8_views #(
  parameter int K_W = 8,
  parameter int V_W = 8
) (
  input  logic               clk_i,
  input  logic [K_W-1:0]     k_i,
  input  logic [V_W-1:0]     v_i,
  output logic [K_W+V_W-1:0] t_o
);
  zb_mul8 #(.K_W(K_W), .V_W(V_W)) u_mul (
    .clk_i(clk_i),
    .k_i  (k_i),
    .k3_i ((K_W + 2)'(3 * k_i)),
    .v_i  (v_i),
    .t_o  (t_o)
  );
endmodule
