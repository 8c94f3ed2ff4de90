// zb_plane: one plane of the resident tile (colour, depth, coverage or peel), in BEAT banks so
// the tile port moves BEAT pixels a clock. Pixel p lies in bank p % BEAT at beat p / BEAT: a
// beat is BEAT neighbours in a row.
// Fast clear: each word carries a generation bit beside its WIDTH bits, the plane an epoch. A
// word whose bit is not the epoch is fresh: reads of it (pipeline and tile port) return the
// clear value. Loads and pipeline writes store the epoch, so a fast clear only flips it; that
// needs every word at the epoch, so a tile read (the store) writes each fresh word back, two
// cycles after the read (W1 notes which words were fresh, W2 writes them: the RAM's read data
// reaches no write enable in the cycle it appears). A write-back carries the epoch of its read:
// a fast clear in between makes it a fresh word, as the clear wants. A load at W2's edge takes
// the port (it writes the whole plane).
// GEN_BITS wide generations and epoch (renamed copies, docs/rtl.md "Renamed copies"): a fast
// clear steps the epoch, so a written plane takes 2^GEN_BITS - 1 of them between reads of every
// beat before a word of an old epoch could read current again.
// A READ_ONLY plane's words are all loaded or all fresh: a flag for the plane replaces the
// generation bits. The driver fast-clears a plane whole, loads it whole and stores every plane
// a pass writes;
// FastClearWhole checks it. After reset the words are unknown: one read of every beat (the
// driver's first sweep) puts them at the epoch before the first fast clear (FastClearAfterSweep).
// The tile port takes both RAM ports while active; zb_rop uses it only while no fragment is in
// flight, so the pipeline's and the port's accesses never meet and tile_req_i alone selects.
module zb_plane #(
  parameter int WIDTH     = 32,
  parameter int WORDS     = 1024,
  parameter int BEAT      = 8,     // pixels per tile-port beat: a power of two
  parameter bit FORWARDED = 1'b0,  // the user replaces a read that meets a write
  parameter bit READ_ONLY = 1'b0,  // no pipeline writes (peel): one fresh flag a plane
  parameter int GEN_BITS  = 1      // a word's generation (not READ_ONLY)
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
  // Pipeline: one pixel read, one pixel write a clock.
  input  logic                     pipe_re_i,
  input  logic [$clog2(WORDS)-1:0] pipe_raddr_i,
  input  logic                     pipe_we_i,
  input  logic [$clog2(WORDS)-1:0] pipe_waddr_i,
  input  logic [WIDTH-1:0]         pipe_wdata_i,
  output logic [WIDTH-1:0]         rdata_o          // the pixel read at the last pipeline read
);

  localparam int LogBeat = $clog2(BEAT);
  localparam int BankW  = BEAT > 1 ? LogBeat : 1;  // BEAT 1: one bank, its index 0
  localparam int Beats  = WORDS / BEAT;
  localparam int BeatAW = $clog2(Beats);

`ifndef SYNTHESIS
  if (BEAT < 1 || BEAT != (1 << LogBeat) || BEAT > WORDS) begin : g_bad_beat
    `ZB_PARAM_ERROR("zb_plane: BEAT must be a power of two, 1..WORDS");
  end
`endif

  logic [BeatAW-1:0] rbeat, wbeat;
  logic [BankW-1:0]  rbank, wbank;
  assign rbeat = BeatAW'(pipe_raddr_i >> LogBeat);
  assign rbank = BEAT > 1 ? BankW'(pipe_raddr_i) : '0;
  assign wbeat = BeatAW'(pipe_waddr_i >> LogBeat);
  assign wbank = BEAT > 1 ? BankW'(pipe_waddr_i) : '0;

  logic tile_load, tile_read, tile_clear;
  assign tile_load  = tile_req_i & tile_we_i & tile_en_i;
  assign tile_read  = tile_req_i & ~tile_we_i;
  assign tile_clear = tile_clear_i & tile_en_i;

  // Epoch and clear value. all_fresh_q: no word current since the fast clear, so a second fast
  // clear keeps the epoch (flipping it would make fresh words current). wback_q (W1): the beat
  // read last edge is in the read register; wb2_q (W2): its fresh words are written back this
  // edge. all_fresh falls at W1 already, so a clear between W1 and W2 flips the epoch.
  logic [GEN_BITS-1:0] epoch_d, epoch_q, wb2_epoch_q, epoch_step;
  logic             all_fresh_d, all_fresh_q, wback_q, wb2_q;
  logic             wb2_current;  // W2 writes at the plane's epoch (no clear since its read)
  logic [WIDTH-1:0] clear_q;
  logic [BeatAW-1:0] wback_addr_q, wb2_addr_q;
  logic [BankW-1:0] rbank_q;
  assign wb2_current = wb2_q & (wb2_epoch_q == epoch_q);
  if (GEN_BITS == 1) begin : g_epoch_flip
    assign epoch_step = ~epoch_q;
  end else begin : g_epoch_count
    assign epoch_step = epoch_q + GEN_BITS'(1);
  end

  always_comb begin
    epoch_d     = epoch_q;
    all_fresh_d = all_fresh_q;
    if (tile_clear) begin
      epoch_d     = all_fresh_q ? epoch_q : epoch_step;
      all_fresh_d = 1'b1;
    end else if (tile_load || pipe_we_i || wback_q || wb2_current) begin
      all_fresh_d = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      epoch_q     <= '0;
      all_fresh_q <= 1'b0;
      wback_q     <= 1'b0;
      wb2_q       <= 1'b0;
    end else begin
      epoch_q     <= epoch_d;
      all_fresh_q <= all_fresh_d;
      wback_q     <= tile_read;
      wb2_q       <= wback_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (tile_clear) begin
      clear_q <= tile_wdata_i[WIDTH-1:0];
    end
    if (pipe_re_i) begin
      rbank_q <= rbank;
    end
    wback_addr_q <= tile_addr_i;
    wb2_addr_q   <= wback_addr_q;
    wb2_epoch_q  <= epoch_q;
  end

  // The banks: words of {generation, value}. The write-back rewrites only the fresh words (as
  // the clear value); the others are at the epoch already.
  localparam int GenW = READ_ONLY ? 0 : GEN_BITS;
  logic [BEAT*WIDTH-1:0] lane;       // each bank's last read word, resolved
  logic [WIDTH-1:0]      wdata_one;  // a bank's write data but for a load
  logic                  plane_fresh_q;
  assign wdata_one = wb2_q ? clear_q : pipe_wdata_i;
  for (genvar b = 0; b < BEAT; b++) begin : g_bank
    logic                  we, fresh;
    logic [BeatAW-1:0]     waddr;
    logic [WIDTH+GenW-1:0] wdata, rdata;
    if (READ_ONLY) begin : g_ro
      assign fresh = plane_fresh_q;
      assign we    = tile_load;
      assign waddr = tile_addr_i;
      assign wdata = tile_wdata_i[b*WIDTH +: WIDTH];
    end else begin : g_rw
      logic fresh2_q;  // W2: this bank's word was fresh at W1
      assign fresh = rdata[WIDTH +: GEN_BITS] != epoch_q;
      assign we    = tile_load | (wb2_q & fresh2_q) | (pipe_we_i & wbank == BankW'(b));
      assign waddr = tile_load ? tile_addr_i : (wb2_q ? wb2_addr_q : wbeat);
      assign wdata = {tile_load | ~wb2_q ? epoch_q : wb2_epoch_q,
                      tile_load ? tile_wdata_i[b*WIDTH +: WIDTH] : wdata_one};
      always_ff @(posedge clk_i) begin
        fresh2_q <= fresh;
      end
    end

    zb_tile_mem #(
      .WIDTH(WIDTH + GenW),
      .WORDS(Beats)
    ) u_mem (
      .clk_i  (clk_i),
      .re_i   (pipe_re_i | tile_read),
      .raddr_i(tile_req_i ? tile_addr_i : rbeat),
      .rdata_o(rdata),
      .we_i   (we),
      .waddr_i(waddr),
      .wdata_i(wdata)
    );

    assign lane[b*WIDTH +: WIDTH] = fresh ? clear_q : rdata[WIDTH-1:0];
  end

  // Each form leaves the other's signals unread.
  if (READ_ONLY) begin : g_unused_rw
    logic unused_rw;
    assign unused_rw = ^{wbeat, wbank, wb2_addr_q, wdata_one};
  end else begin : g_unused_ro
    logic unused_ro;
    assign unused_ro = plane_fresh_q;
  end

  // READ_ONLY: fresh from a fast clear to the next load.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      plane_fresh_q <= 1'b0;
    end else if (tile_clear) begin
      plane_fresh_q <= 1'b1;
    end else if (tile_load) begin
      plane_fresh_q <= 1'b0;
    end
  end

  assign tile_rdata_o = lane;
  if (BEAT > 1) begin : g_bank_sel
    assign rdata_o = lane[rbank_q*WIDTH +: WIDTH];
  end else begin : g_one_bank
    logic unused_rbank;
    assign unused_rbank = rbank_q;
    assign rdata_o = lane;
  end

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // The RAM's read-during-write result is undefined in hardware (no_rw_check): a pipeline read
  // never meets a write of its word at one edge (zb_rop's interlock) unless the plane's user
  // forwards the written word instead, nor does the tile port meet the pipeline.
  if (!FORWARDED) begin : g_no_collision
    NoReadWriteCollision: assert property (@(posedge clk_i) disable iff (!rst_ni)
        !(pipe_re_i && pipe_we_i && pipe_raddr_i == pipe_waddr_i));
  end
  PortsApart: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_req_i || tile_clear_i || wback_q || wb2_q) |-> !(pipe_re_i || pipe_we_i));
  // A write-back at the epoch meeting a fast clear that keeps the epoch would leave its word
  // current with the old clear value: the driver never clears twice in a row (one setup cycle).
  WriteBackBeforeClear: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_clear && wb2_current) |-> !all_fresh_q);
  // The write-back of a read beat's fresh words lands two edges after the read (W2): a load of
  // that beat in the cycle between (W1) would be overwritten by it. The driver never loads
  // right after a read (a setup cycle comes between); the contract forbids it.
  LoadAfterReadOfBeat: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_load && wback_q) |-> tile_addr_i != wback_addr_q);
  // Written since a fast clear and not stored since: some words fresh, some current. Each fast
  // clear that steps the epoch then brings the oldest fresh words' generation nearer: after
  // 2^GEN_BITS - 1 steps since a read of every beat (the driver stores every plane a pass
  // writes, or sweeps) another would make them current.
  localparam int Steps = READ_ONLY ? 1 : (1 << GEN_BITS) - 1;
  logic [GEN_BITS:0] steps_q;  // the epoch's steps since the last tile read or load
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      steps_q <= '0;
    end else if (tile_load || tile_read) begin
      steps_q <= '0;
    end else if (tile_clear && !all_fresh_q && steps_q <= (GEN_BITS+1)'(Steps)) begin
      steps_q <= steps_q + 1'b1;
    end
  end
  FastClearWhole: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_clear && !all_fresh_q) |-> steps_q < (GEN_BITS+1)'(Steps));
  logic swept_q;  // a tile read of the last beat since reset (the driver sweeps in order)
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      swept_q <= 1'b0;
    end else if (tile_read && tile_addr_i == BeatAW'(Beats - 1)) begin
      swept_q <= 1'b1;
    end
  end
  FastClearAfterSweep: assert property (@(posedge clk_i) disable iff (!rst_ni)
      tile_clear |-> swept_q);
  // A pixel read fresh: its clear value stands in for the word.
  FreshWordRead: cover property (@(posedge clk_i) disable iff (!rst_ni)
      $past(pipe_re_i) && g_bank[0].fresh);
  if (READ_ONLY) begin : g_read_only
    PipeNeverWrites: assert property (@(posedge clk_i) disable iff (!rst_ni) !pipe_we_i);
  end
`endif
`endif

endmodule
