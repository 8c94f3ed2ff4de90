// zb_plane: one plane of the resident tile (colour, depth, coverage or peel): a zb_tile_mem
// shared by the pipeline and the tile port. The tile port (tile_req_i) takes both ports while
// it is active; zb_rop uses it only while no fragment is in flight, so the pipeline's and the
// port's accesses never meet and tile_req_i alone selects.
module zb_plane #(
  parameter int unsigned WIDTH = 32,
  parameter int unsigned WORDS = 1024,
  parameter bit          FORWARDED = 1'b0,  // the user replaces a read that meets a write
  localparam int unsigned AddrW = $clog2(WORDS)
) (
  input  logic             clk_i,
  input  logic             rst_ni,        // assertions only
  input  logic             tile_req_i,
  input  logic             tile_we_i,
  input  logic [AddrW-1:0] tile_addr_i,
  input  logic [WIDTH-1:0] tile_wdata_i,
  input  logic             pipe_re_i,
  input  logic [AddrW-1:0] pipe_raddr_i,
  input  logic             pipe_we_i,
  input  logic [AddrW-1:0] pipe_waddr_i,
  input  logic [WIDTH-1:0] pipe_wdata_i,
  output logic [WIDTH-1:0] rdata_o
);

  logic             re, we;
  logic [AddrW-1:0] raddr, waddr;
  logic [WIDTH-1:0] wdata;

  assign re    = pipe_re_i | (tile_req_i & ~tile_we_i);
  assign raddr = tile_req_i ? tile_addr_i : pipe_raddr_i;
  assign we    = pipe_we_i | (tile_req_i & tile_we_i);
  assign waddr = tile_req_i ? tile_addr_i : pipe_waddr_i;
  assign wdata = tile_req_i ? tile_wdata_i : pipe_wdata_i;

  zb_tile_mem #(
    .WIDTH(WIDTH),
    .WORDS(WORDS)
  ) u_mem (
    .clk_i  (clk_i),
    .re_i   (re),
    .raddr_i(raddr),
    .rdata_o(rdata_o),
    .we_i   (we),
    .waddr_i(waddr),
    .wdata_i(wdata)
  );

`ifndef SYNTHESIS
  // The RAM's read-during-write result is undefined in hardware (no_rw_check): a pipeline read
  // never meets a write of its address at one edge (zb_rop's interlock) unless the plane's
  // user forwards the written word instead, nor does the tile port meet the pipeline.
  if (!FORWARDED) begin : g_no_collision
    NoReadWriteCollision: assert property (@(posedge clk_i) disable iff (!rst_ni)
        !(pipe_re_i && we && raddr == waddr));
  end
  PortsApart: assert property (@(posedge clk_i) disable iff (!rst_ni)
      tile_req_i |-> !(pipe_re_i || pipe_we_i));
`endif

endmodule
