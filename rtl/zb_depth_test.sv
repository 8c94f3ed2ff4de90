// zb_depth_test: the depth comparison of docs/datapath.md "1. Depth test", from the
// comparison's two flags (z < stored, z == stored; zb_rop registers them a stage earlier).
// Combinational. pass_o = (z <func> stored), unsigned, with GL's function codes
// (GL_NEVER + code). The depth_test enable is applied by the caller.
module zb_depth_test (
  input  logic [2:0] func_i,  // 0 never .. 7 always
  input  logic       lt_i,    // fragment depth < stored depth
  input  logic       eq_i,    // fragment depth == stored depth
  output logic       pass_o
);

  always_comb begin
    pass_o = 1'b0;
    unique case (func_i)
      3'd0:    pass_o = 1'b0;            // never
      3'd1:    pass_o = lt_i;            // less
      3'd2:    pass_o = eq_i;            // equal
      3'd3:    pass_o = lt_i | eq_i;     // lequal
      3'd4:    pass_o = ~(lt_i | eq_i);  // greater
      3'd5:    pass_o = ~eq_i;           // notequal
      3'd6:    pass_o = ~lt_i;           // gequal
      3'd7:    pass_o = 1'b1;            // always
      default: pass_o = 1'b0;
    endcase
  end

endmodule
