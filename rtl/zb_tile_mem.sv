// zb_tile_mem: one tile memory of WORDS x WIDTH bits. One synchronous read port, one write
// port, read-first: a read and a write of the same address in one cycle return the old data.
// The read data register only loads when re_i is set, so rdata_o holds the last word read.
// Written in the shape Yosys infers as block RAM (no reset on the array or the read register).
module zb_tile_mem #(
  parameter int unsigned WIDTH = 32,
  parameter int unsigned WORDS = 4096,
  localparam int unsigned AddrW = $clog2(WORDS)
) (
  input  logic             clk_i,
  input  logic             re_i,
  input  logic [AddrW-1:0] raddr_i,
  output logic [WIDTH-1:0] rdata_o,
  input  logic             we_i,
  input  logic [AddrW-1:0] waddr_i,
  input  logic [WIDTH-1:0] wdata_i
);

  logic [WIDTH-1:0] mem_q [WORDS];
  logic [WIDTH-1:0] rdata_q;

  // Memory: write and registered read in one block (the RAM template); non-blocking
  // assignments make the read see the array before this edge's write (read-first).
  always_ff @(posedge clk_i) begin
    if (we_i) begin
      mem_q[waddr_i] <= wdata_i;
    end
    if (re_i) begin
      rdata_q <= mem_q[raddr_i];
    end
  end

  assign rdata_o = rdata_q;

endmodule
