// zb_depth_test: the depth comparison of docs/datapath.md "1. Depth test".
// Combinational. pass_o = (z_i <func> stored_i), unsigned, with GL's function codes
// (GL_NEVER + code). The depth_test enable is applied by the caller.
module zb_depth_test #(
  parameter int unsigned DEPTH_BITS = 24
) (
  input  logic [2:0]            func_i,    // 0 never .. 7 always
  input  logic [DEPTH_BITS-1:0] z_i,       // fragment depth (left operand)
  input  logic [DEPTH_BITS-1:0] stored_i,  // stored depth (right operand)
  output logic                  pass_o
);

  logic lt, eq;

  assign lt = z_i < stored_i;
  assign eq = z_i == stored_i;

  always_comb begin
    pass_o = 1'b0;
    unique case (func_i)
      3'd0:    pass_o = 1'b0;        // never
      3'd1:    pass_o = lt;          // less
      3'd2:    pass_o = eq;          // equal
      3'd3:    pass_o = lt | eq;     // lequal
      3'd4:    pass_o = ~(lt | eq);  // greater
      3'd5:    pass_o = ~eq;         // notequal
      3'd6:    pass_o = ~lt;         // gequal
      3'd7:    pass_o = 1'b1;        // always
      default: pass_o = 1'b0;
    endcase
  end

endmodule
