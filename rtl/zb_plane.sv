// zb_plane: one plane of the resident tile (colour, depth, coverage or peel), in BEAT banks so
// the tile port moves BEAT pixels a clock. Pixel p lies in bank p % BEAT at beat p / BEAT: a
// beat is BEAT neighbours in a row.
// Fast clear: tile_clear_i marks every beat fresh and keeps the clear value. A fresh beat's RAM
// words are stale; reads of it (pipeline and tile port) return the clear value. The first
// pipeline write to a fresh beat writes every bank of it (the clear value beside the written
// pixel), so one flag per beat is enough. A load beat clears its flag.
// The tile port takes both RAM ports while active; zb_rop uses it only while no fragment is in
// flight, so the pipeline's and the port's accesses never meet and tile_req_i alone selects.
module zb_plane #(
  parameter int unsigned WIDTH = 32,
  parameter int unsigned WORDS = 1024,
  parameter int unsigned BEAT  = 8,         // pixels per tile-port beat: a power of two >= 2
  parameter bit          FORWARDED = 1'b0   // the user replaces a read that meets a write
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  // Tile port: a load (tile_we_i) or read of one beat, or a fast clear (tile_clear_i, value in
  // lane 0 of tile_wdata_i). tile_en_i selects this plane for loads and clears.
  input  logic                     tile_req_i,
  input  logic                     tile_we_i,
  input  logic                     tile_en_i,
  input  logic                     tile_clear_i,
  input  logic [$clog2(WORDS/BEAT)-1:0] tile_addr_i,
  input  logic [BEAT*WIDTH-1:0]    tile_wdata_i,
  output logic [BEAT*WIDTH-1:0]    tile_rdata_o,    // the beat read at the last edge
  // Pipeline: one pixel read, one pixel write a clock. pipe_wnext_i is the address of the
  // stage before the writer: its fresh flag is looked up a clock ahead of its write.
  input  logic                     pipe_re_i,
  input  logic [$clog2(WORDS)-1:0] pipe_raddr_i,
  input  logic                     pipe_we_i,
  input  logic [$clog2(WORDS)-1:0] pipe_waddr_i,
  input  logic [WIDTH-1:0]         pipe_wdata_i,
  input  logic [$clog2(WORDS)-1:0] pipe_wnext_i,
  output logic [WIDTH-1:0]         rdata_o          // the pixel read at the last pipeline read
);

  localparam int unsigned AddrW  = $clog2(WORDS);
  localparam int unsigned BankW  = $clog2(BEAT);
  localparam int unsigned Beats  = WORDS / BEAT;
  localparam int unsigned BeatAW = $clog2(Beats);

`ifndef SYNTHESIS
  if (BEAT < 2 || BEAT != (1 << BankW) || BEAT > WORDS) begin : g_bad_beat
    $error("zb_plane: BEAT must be a power of two, 2..WORDS");
  end
`endif

  logic [BeatAW-1:0] rbeat, wbeat, nbeat;
  logic [BankW-1:0]  rbank, wbank;
  assign rbeat = pipe_raddr_i[AddrW-1:BankW];
  assign rbank = pipe_raddr_i[BankW-1:0];
  assign wbeat = pipe_waddr_i[AddrW-1:BankW];
  assign wbank = pipe_waddr_i[BankW-1:0];
  assign nbeat = pipe_wnext_i[AddrW-1:BankW];
  logic unused_wnext_bank;  // the lookup is per beat
  assign unused_wnext_bank = ^pipe_wnext_i[BankW-1:0];

  logic tile_load, tile_read, tile_clear;
  assign tile_load  = tile_req_i & tile_we_i & tile_en_i;
  assign tile_read  = tile_req_i & ~tile_we_i;
  assign tile_clear = tile_clear_i & tile_en_i;

  // Fresh flags, the clear value, and the lookups a clock ahead of their use: the read's (of
  // the pipeline or the port) for the mux after the RAM; the writer's for its write enables.
  logic [Beats-1:0] fresh_d, fresh_q;
  logic [WIDTH-1:0] clear_q;
  logic             rfresh_q, tfresh_q, wfresh_q;
  logic [BankW-1:0] rbank_q;

  always_comb begin
    fresh_d = fresh_q;
    if (tile_clear) begin
      fresh_d = '1;
    end else if (tile_load) begin
      fresh_d[tile_addr_i] = 1'b0;
    end else if (pipe_we_i) begin
      fresh_d[wbeat] = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fresh_q <= '0;
    end else begin
      fresh_q <= fresh_d;
    end
  end

  always_ff @(posedge clk_i) begin
    if (tile_clear) begin
      clear_q <= tile_wdata_i[WIDTH-1:0];
    end
    if (pipe_re_i) begin
      rfresh_q <= fresh_q[rbeat];
      rbank_q  <= rbank;
    end
    if (tile_read) begin
      tfresh_q <= fresh_q[tile_addr_i];
    end
    // The write at this edge clears the flag the next write would see.
    wfresh_q <= fresh_q[nbeat] & ~(pipe_we_i && wbeat == nbeat);
  end

  // The banks.
  logic [BEAT*WIDTH-1:0] bank_rdata;
  for (genvar b = 0; b < BEAT; b++) begin : g_bank
    logic              we;
    logic [WIDTH-1:0]  wdata;
    logic              own;
    assign own   = wbank == BankW'(b);
    assign we    = tile_load | (pipe_we_i & (own | wfresh_q));
    assign wdata = tile_req_i ? tile_wdata_i[b*WIDTH +: WIDTH] : (own ? pipe_wdata_i : clear_q);

    zb_tile_mem #(
      .WIDTH(WIDTH),
      .WORDS(Beats)
    ) u_mem (
      .clk_i  (clk_i),
      .re_i   (pipe_re_i | tile_read),
      .raddr_i(tile_req_i ? tile_addr_i : rbeat),
      .rdata_o(bank_rdata[b*WIDTH +: WIDTH]),
      .we_i   (we),
      .waddr_i(tile_req_i ? tile_addr_i : wbeat),
      .wdata_i(wdata)
    );

    assign tile_rdata_o[b*WIDTH +: WIDTH] = tfresh_q ? clear_q : bank_rdata[b*WIDTH +: WIDTH];
  end

  assign rdata_o = rfresh_q ? clear_q : bank_rdata[rbank_q*WIDTH +: WIDTH];

`ifndef SYNTHESIS
  // The RAM's read-during-write result is undefined in hardware (no_rw_check): a pipeline read
  // never meets a write of its word at one edge (zb_rop's interlock) unless the plane's user
  // forwards the written word instead, nor does the tile port meet the pipeline.
  if (!FORWARDED) begin : g_no_collision
    NoReadWriteCollision: assert property (@(posedge clk_i) disable iff (!rst_ni)
        !(pipe_re_i && pipe_we_i && rbeat == wbeat));
  end
  PortsApart: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_req_i || tile_clear_i) |-> !(pipe_re_i || pipe_we_i));
  // The writer's flag, looked up a clock ahead, is the flag of its beat now.
  WriteFreshExact: assert property (@(posedge clk_i) disable iff (!rst_ni)
      pipe_we_i |-> (wfresh_q == fresh_q[wbeat]));
  // The first write to a fresh beat (fills its other pixels with the clear value).
  FreshBeatWritten: cover property (@(posedge clk_i) disable iff (!rst_ni)
      pipe_we_i && wfresh_q);
`endif

endmodule
