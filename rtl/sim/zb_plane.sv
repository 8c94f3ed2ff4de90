// zb_plane, simulation view (docs/rtl.md "Two builds, two views"): rtl/zb_plane.sv is the
// synthesis view and the specification (its header explains the banks, the fast clear and the
// write-back); every Verilated model reads this file instead. The assertions are the synthesis
// view's; the control computes the same next state in its flop blocks, and the banks are one
// array (below). scripts/equiv.py proves the two views equal wherever zb_rop looks, which pins
// both to the synthesis view.
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

  logic [BeatAW-1:0] rbeat;
  logic [BankW-1:0]  rbank, wbank;
  assign rbeat = BeatAW'(pipe_raddr_i >> LogBeat);
  assign rbank = BEAT > 1 ? BankW'(pipe_raddr_i) : '0;
  assign wbank = BEAT > 1 ? BankW'(pipe_waddr_i) : '0;

  logic tile_load, tile_read, tile_clear;
  assign tile_load  = tile_req_i & tile_we_i & tile_en_i;
  assign tile_read  = tile_req_i & ~tile_we_i;
  assign tile_clear = tile_clear_i & tile_en_i;

  // Epoch and clear value. all_fresh_q: no word current since the fast clear, so a second fast
  // clear keeps the epoch (flipping it would make fresh words current). wback_q (W1): the beat
  // read last edge is in the read register; wb2_q (W2): its fresh words are written back this
  // edge. all_fresh falls at W1 already, so a clear between W1 and W2 flips the epoch.
  logic [GEN_BITS-1:0] epoch_q, wb2_epoch_q, epoch_step;
  logic             all_fresh_q, wback_q, wb2_q;
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

  // The next state is computed in the flop blocks, from the tile port's inputs themselves: logic
  // on the model's inputs outside them would be evaluated at both evaluations of every cycle.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      epoch_q       <= '0;
      all_fresh_q   <= 1'b0;
      wback_q       <= 1'b0;
      wb2_q         <= 1'b0;
      plane_fresh_q <= 1'b0;
    end else begin
      if (tile_clear_i && tile_en_i) begin
        epoch_q       <= all_fresh_q ? epoch_q : epoch_step;
        all_fresh_q   <= 1'b1;
        plane_fresh_q <= 1'b1;
      end else begin
        if ((tile_req_i && tile_we_i && tile_en_i) || pipe_we_i || wback_q || wb2_current) begin
          all_fresh_q <= 1'b0;
        end
        if (tile_req_i && tile_we_i && tile_en_i) begin
          plane_fresh_q <= 1'b0;
        end
      end
      wback_q <= tile_req_i && !tile_we_i;
      wb2_q   <= wback_q;
    end
  end

  always_ff @(posedge clk_i) begin
    if (tile_clear_i && tile_en_i) begin
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
  localparam int GenW  = READ_ONLY ? 0 : GEN_BITS;
  localparam int GenLsb = READ_ONLY ? 0 : WIDTH;  // the generation's bits (unread when READ_ONLY)
  localparam int WordW = WIDTH + GenW;
  logic [WIDTH-1:0] wdata_one;  // a bank's write data but for a load
  logic             rd_fresh;   // rdata_o's word is fresh
  logic             plane_fresh_q;  // READ_ONLY: fresh from a fast clear to the next load
  assign wdata_one = wb2_q ? clear_q : pipe_wdata_i;

  // Each form leaves the other's signals unread.
  if (READ_ONLY) begin : g_unused_rw
    logic unused_rw;
    assign unused_rw = ^{wbank, wb2_addr_q, wdata_one};
  end else begin : g_unused_ro
    logic unused_ro;
    assign unused_ro = plane_fresh_q;
  end

  // The banks as one array, equal to them wherever zb_rop looks: pixel p at word p, so a
  // pipeline access touches one word. prd_q holds the word of rdata_o's bank, which every read
  // loads in the banks; the tile port's beat is resolved at its read (against the epoch and
  // clear value after that edge), since zb_rop takes it in the cycle after the read alone. mem_q
  // is this block's only, so its writes are blocking, after its reads: no delayed-write
  // bookkeeping, and a read meeting a write reads the old word.
  logic [WordW-1:0]      mem_q [WORDS];
  logic [WordW-1:0]      prd_q;
  logic [BEAT*WIDTH-1:0] tile_lane_q;
  logic [BEAT-1:0]       tile_fresh_q, fresh2_q;  // the beat's fresh words; at W2
  // Word b of a beat.
  localparam int AddrW = $clog2(WORDS);
  function automatic logic [AddrW-1:0] word(input logic [BeatAW-1:0] beat, input int b);
    word = AddrW'((32'(beat) << LogBeat) | 32'(b));
  endfunction
  /* verilator lint_off BLKSEQ */
  always_ff @(posedge clk_i) begin
    logic [WordW-1:0]  w;
    logic              f, load, read, clear, plane_fresh_d;
    logic [GEN_BITS-1:0] epoch_d;
    logic [WIDTH-1:0]  clear_d;
    logic [BeatAW-1:0] waddr;
    load          = tile_req_i && tile_we_i && tile_en_i;
    read          = tile_req_i && !tile_we_i;
    clear         = tile_clear_i && tile_en_i;
    epoch_d       = clear && !all_fresh_q ? epoch_step : epoch_q;
    plane_fresh_d = clear || (plane_fresh_q && !load);
    clear_d       = clear ? tile_wdata_i[WIDTH-1:0] : clear_q;
    if (pipe_re_i || read) begin
      prd_q <= mem_q[word(tile_req_i ? tile_addr_i : rbeat,
                          BEAT > 1 && !pipe_re_i ? 32'(rbank_q) : 32'(rbank))];
    end
    if (read) begin
      for (int b = 0; b < BEAT; b++) begin
        w = mem_q[word(tile_addr_i, b)];
        f = READ_ONLY ? plane_fresh_d : w[GenLsb +: GEN_BITS] != epoch_d;
        tile_fresh_q[b] <= f;
        tile_lane_q[b*WIDTH +: WIDTH] <= f ? clear_d : w[WIDTH-1:0];
      end
    end
    if (READ_ONLY) begin
      if (load) begin
        for (int b = 0; b < BEAT; b++) begin
          mem_q[word(tile_addr_i, b)] = WordW'(tile_wdata_i[b*WIDTH +: WIDTH]);
        end
      end
    end else if (load || wb2_q) begin
      waddr = load ? tile_addr_i : wb2_addr_q;
      for (int b = 0; b < BEAT; b++) begin
        if (load || fresh2_q[b] || (pipe_we_i && wbank == BankW'(b))) begin
          mem_q[word(waddr, b)] = WordW'({load ? epoch_q : wb2_epoch_q,
                                          load ? tile_wdata_i[b*WIDTH +: WIDTH] : wdata_one});
        end
      end
    end else if (pipe_we_i) begin
      mem_q[pipe_waddr_i] = WordW'({epoch_q, pipe_wdata_i});
    end
    fresh2_q <= tile_fresh_q;
  end
  /* verilator lint_on BLKSEQ */
  assign rd_fresh     = READ_ONLY ? plane_fresh_q : prd_q[GenLsb +: GEN_BITS] != epoch_q;
  assign rdata_o      = rd_fresh ? clear_q : prd_q[WIDTH-1:0];
  assign tile_rdata_o = tile_lane_q;

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
      $past(pipe_re_i) && rd_fresh);
  if (READ_ONLY) begin : g_read_only
    PipeNeverWrites: assert property (@(posedge clk_i) disable iff (!rst_ni) !pipe_we_i);
  end
`endif
`endif

endmodule
