// zb_depth_test: the depth comparison of docs/datapath.md "1. Depth test", from the
// comparison's two flags (z < stored, z == stored; zb_rop registers them a stage earlier).
// Combinational. pass_o = (z <func> stored), unsigned, with GL's function codes
// (GL_NEVER + code). The depth_test enable is applied by the caller.
module zb_depth_test
(
  input  zb_pkg::depth_func_e func_i,
  input  logic        lt_i,    // fragment depth < stored depth
  input  logic        eq_i,    // fragment depth == stored depth
  output logic        pass_o
);

  always_comb begin
    pass_o = 1'b0;
    unique case (func_i)
      zb_pkg::DepthNever:     pass_o = 1'b0;
      zb_pkg::DepthLess:      pass_o = lt_i;
      zb_pkg::DepthEqual:     pass_o = eq_i;
      zb_pkg::DepthLequal:    pass_o = lt_i | eq_i;
      zb_pkg::DepthGreater:   pass_o = ~(lt_i | eq_i);
      zb_pkg::DepthNotequal:  pass_o = ~eq_i;
      zb_pkg::DepthGequal:    pass_o = ~lt_i;
      zb_pkg::DepthAlways:    pass_o = 1'b1;
      default:                pass_o = 1'b0;
    endcase
  end

endmodule
