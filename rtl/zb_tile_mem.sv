// zb_tile_mem: one tile memory of WORDS x WIDTH bits. One synchronous read port with read
// enable, one write port. The read data register only loads when re_i is set, so rdata_o holds
// the last word read. Written in the shape Yosys infers as block RAM (no reset on the array or
// the read register).
// A read and a write of one address at one edge: the simulation returns the old word, but
// no_rw_check tells Yosys the design never relies on it, so no bypass logic is added around the
// iCE40 RAM. zb_rop guarantees it (its interlock; the assertion NoReadWriteCollision in
// zb_plane).
module zb_tile_mem #(
  parameter int WIDTH = 32,
  parameter int WORDS = 4096,
  localparam int AddrW = $clog2(WORDS)
) (
  input  logic             clk_i,
  input  logic             re_i,
  input  logic [AddrW-1:0] raddr_i,
  output logic [WIDTH-1:0] rdata_o,
  input  logic             we_i,
  input  logic [AddrW-1:0] waddr_i,
  input  logic [WIDTH-1:0] wdata_i
);

  (* no_rw_check *) logic [WIDTH-1:0] mem_q [WORDS];
  logic [WIDTH-1:0] rdata_q;

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
