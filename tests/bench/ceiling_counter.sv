// The smallest clocked model: a 32-bit counter. make bench runs it under the RTL driver's
// clocking (two evaluations a cycle) for Verilator's ceiling, the cycles per second of a model
// that does almost nothing, beside zb_rop's.
module ceiling_counter (
  input  logic        clk_i,
  input  logic        en_i,
  output logic [31:0] cnt_o
);
  always_ff @(posedge clk_i) begin
    if (en_i) cnt_o <= cnt_o + 32'd1;
  end
endmodule
