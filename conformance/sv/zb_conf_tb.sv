// zb_conf_tb: the conformance testbench (docs/conformance.md). It needs no C++: it reads one
// test's command stream ($readmemh, conformance_spec in docs/conformance.md "The vectors"), keeps
// the frame's planes, and for every pass and every tile the pass touches loads the tile into
// the DUT, streams that tile's fragments, waits for the DUT to drain and stores the tile back;
// frame operations are the host's, done here on the frame (the resolve wboit among them), but
// for the resolve of mlab-K's layers, which live on the tile: the stores of the passes before
// it resolve them on their way out (st_resolve_i). At the end it writes the planes as signatures
// (got.<plane>.hex) for `zblend conformance check`, and after every pass a digest of the planes
// (got.passes.hex), so that what a later pass overwrites is still checked. A DUT whose adapter has no accumulation
// plane (planes_o[4] low) runs the other tests: a test that resolves from the plane is skipped
// (a "zb_conf: skip:" line, no files), and no got.accum.hex is written; so is a test keeping
// more layers a pixel than the DUT's layers_o.
//
// Plusargs: +stream=FILE (required) +out=DIR (existing; default .) +gap=P (percent of cycles
// with no fragment offered, default 0) +seed=N (the gaps' pattern) +dump=FILE (waves of the
// run: Verilator built with --trace-fst, or Icarus's vvp run with -fst) +dump_from=C (the waves
// start at cycle C: GTKWave opens a file at its first time) +watchdog=N (cycles without progress
// before the test fails, default 10000) +timing=N (0 tight, the default: each event at the first
// edge the port contract allows; 1 loose: a cycle more before each wait; 2 random: 0 to 3 cycles
// drawn from +seed) +resident=1 (passes between frame operations run on resident tiles: one
// load, each pass's state and fragments, one store; for a DUT whose profile has resident_tile).
// The DUT's ports are checked as the run goes: an output that is X or Z, planes_o changing, a
// store pixel offered outside a store, idle_o high inside one: each a "zb_conf: PROTOCOL:" line
// naming the port, the rule and the cycle. A DUT that stops making progress (no fragment, load
// beat or store pixel taken, no idle_o where it is awaited) for N cycles fails with a
// "zb_conf: WATCHDOG:" line and every port's state, never a silent hang.
// With ZB_CONF_LOCKSTEP defined, the golden model runs beside it through DPI-C
// (zb_conf_scoreboard.sv) and every write the DUT makes is compared at its cycle.
module zb_conf_tb #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 64,
  parameter int TILE_H      = 64,
  parameter int BEAT        = 8,
  parameter int ACC_BITS    = 16,       // the accumulation word's widths
  parameter int REV_BITS    = 8,
  parameter int WEIGHT_BITS = 4,
  parameter int MAX_WORDS   = 1 << 18,  // the longest command stream
  parameter int MAX_PIXELS  = 1 << 16,  // the largest frame
  parameter int MAX_GROUP   = 1024      // the most passes run on a resident tile at once
);

  localparam int Words = TILE_W * TILE_H;
  localparam int AccW  = 4 * ACC_BITS + REV_BITS;  // {r, acc_A, acc_B, acc_G, acc_R}

  localparam logic [7:0] OpFrame   = 8'h01;
  localparam logic [7:0] OpPass    = 8'h02;
  localparam logic [7:0] OpFrag    = 8'h03;
  localparam logic [7:0] OpEndPass = 8'h04;
  localparam logic [7:0] OpFrameOp = 8'h05;
  localparam logic [7:0] OpEnd     = 8'h06;

  // A 10 ns clock, as the waves of the C++ testbench.
  logic clk = 1'b0;
  logic rst_n = 1'b0;
  /* verilator lint_off BLKSEQ */  // a clock generator, not a flop
  always #5 clk = ~clk;
  /* verilator lint_on BLKSEQ */

  // ---------------------------------------------------------------------------------------
  // The DUT behind its adapter, and the signals the host drives.
  // ---------------------------------------------------------------------------------------
  logic        state_we = 1'b0;
  logic [12:0] state = '0;
  logic [2:0]  state_layers = '0;  // the pass state's [15:13]: K - 1
  logic [15:0] tile_x0 = '0, tile_y0 = '0;
  logic        ld_valid = 1'b0, ld_ready;
  logic [31:0] ld_color = '0, ld_depth = '0, ld_peel = '0;
  logic [7:0]  ld_cov = '0;
  logic [AccW-1:0] ld_acc = '0, st_acc, ret_wacc;
  logic [4:0]  planes;
  logic        ret_awe;
  logic        frag_valid = 1'b0, frag_ready;
  logic [15:0] frag_x = '0, frag_y = '0;
  logic [31:0] frag_z = '0, frag_rgba = '0;
  logic [7:0]  frag_cov = '0;
  logic        idle, st_start = 1'b0, st_resolve = 1'b0, st_valid;
  logic [3:0]  layers;  // the most layers a pixel the DUT keeps
  logic [31:0] st_color, st_depth, st_peel;
  logic [7:0]  st_cov;
  logic        ret_d_valid, ret_dwe, ret_vwe, ret_c_valid, ret_cwe;
  logic [31:0] ret_d_pixel, ret_wdepth, ret_c_pixel, ret_wcolor;
  logic [7:0]  ret_wcov;

  zb_conf_adapter #(
    .DEPTH_BITS (DEPTH_BITS),
    .COV_SAMPLES(COV_SAMPLES),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .BEAT       (BEAT),
    .ACC_BITS   (ACC_BITS),
    .REV_BITS   (REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS)
  ) u_dut (
    .clk_i        (clk),
    .rst_ni       (rst_n),
    .state_we_i   (state_we),
    .state_i      (state),
`ifndef ZB_CONF_ADAPTER_V6
    .state_layers_i(state_layers),
`endif
    .tile_x0_i    (tile_x0),
    .tile_y0_i    (tile_y0),
    .ld_valid_i   (ld_valid),
    .ld_ready_o   (ld_ready),
    .ld_color_i   (ld_color),
    .ld_depth_i   (ld_depth),
    .ld_cov_i     (ld_cov),
    .ld_peel_i    (ld_peel),
    .ld_acc_i     (ld_acc),
    .frag_valid_i (frag_valid),
    .frag_ready_o (frag_ready),
    .frag_x_i     (frag_x),
    .frag_y_i     (frag_y),
    .frag_z_i     (frag_z),
    .frag_rgba_i  (frag_rgba),
    .frag_cov_i   (frag_cov),
    .idle_o       (idle),
    .st_start_i   (st_start),
`ifndef ZB_CONF_ADAPTER_V6
    .st_resolve_i (st_resolve),
`endif
    .st_valid_o   (st_valid),
    .st_color_o   (st_color),
    .st_depth_o   (st_depth),
    .st_cov_o     (st_cov),
    .st_peel_o    (st_peel),
    .st_acc_o     (st_acc),
    .planes_o     (planes),
`ifndef ZB_CONF_ADAPTER_V6
    .layers_o     (layers),
`endif
    .ret_d_valid_o(ret_d_valid),
    .ret_d_pixel_o(ret_d_pixel),
    .ret_dwe_o    (ret_dwe),
    .ret_wdepth_o (ret_wdepth),
    .ret_vwe_o    (ret_vwe),
    .ret_wcov_o   (ret_wcov),
    .ret_c_valid_o(ret_c_valid),
    .ret_c_pixel_o(ret_c_pixel),
    .ret_cwe_o    (ret_cwe),
    .ret_wcolor_o (ret_wcolor),
    .ret_awe_o    (ret_awe),
    .ret_wacc_o   (ret_wacc)
  );
`ifdef ZB_CONF_ADAPTER_V6
  // An adapter of interface version 6 has no layers port: no layers (conformance.py marks the
  // layers tests NOT SUPPORTED for it; docs/conformance.md "Adapter versions").
  assign layers = 4'd0;
  logic unused_v6;
  assign unused_v6 = ^{state_layers, st_resolve};
`endif

  // The handshakes of the edge just past, read by the host at the falling edge after it: the
  // host drives at falling edges, so a flop's output never changes under its read.
  logic frag_took = 1'b0, ld_took = 1'b0;
  always @(posedge clk) begin
    frag_took <= frag_valid && frag_ready;
    ld_took   <= ld_valid && ld_ready;
  end

  // ---------------------------------------------------------------------------------------
  // Watchdog and protocol checks.
  // ---------------------------------------------------------------------------------------
  int unsigned cycle = 0;          // rising edges since time 0
  int unsigned last_progress = 0;  // the cycle of the last fragment, beat or pixel taken
  int unsigned watchdog_cycles;
  string       phase = "reset";    // what the host waits for, for the watchdog's line
  bit          storing = 1'b0;     // from the edge that takes st_start_i to the last pixel read
  bit          checking = 1'b0;    // after reset
  logic [4:0]  planes_at_reset;
  logic [3:0]  layers_at_reset;
  always @(posedge clk) cycle <= cycle + 1;

  function automatic void progress();
    last_progress = cycle;
  endfunction

  function automatic string port_states();
    return $sformatf("frag_valid_i=%b frag_ready_o=%b ld_valid_i=%b ld_ready_o=%b st_start_i=%b st_valid_o=%b idle_o=%b planes_o=%b",
                     frag_valid, frag_ready, ld_valid, ld_ready, st_start, st_valid, idle, planes);
  endfunction

  function automatic void protocol(input string port, input string rule);
    $display("zb_conf: PROTOCOL: cycle %0d: %s: %s (%s)", cycle, port, rule, port_states());
    fail($sformatf("protocol violation on %s at cycle %0d", port, cycle));
  endfunction

  // Sampled at the falling edge, as the host reads: the values the next rising edge will see.
  always @(negedge clk) begin
    if (checking) begin
      // One port at a time: Icarus 11's $isunknown of a concatenation is X for known bits.
      if ($isunknown(frag_ready)) protocol("frag_ready_o", "is X or Z after reset");
      if ($isunknown(ld_ready)) protocol("ld_ready_o", "is X or Z after reset");
      if ($isunknown(idle)) protocol("idle_o", "is X or Z after reset");
      if ($isunknown(st_valid)) protocol("st_valid_o", "is X or Z after reset");
      if (planes !== planes_at_reset)
        protocol("planes_o", $sformatf("changed from %05b after reset: it is a constant",
                                       planes_at_reset));
      if (layers !== layers_at_reset)
        protocol("layers_o", $sformatf("changed from %0d after reset: it is a constant",
                                       layers_at_reset));
      if (st_valid && !storing)
        protocol("st_valid_o", "high with no store under way (a store begins at the edge that takes st_start_i)");
      if (idle && storing)
        protocol("idle_o", "high while a store is under way (idle means no load or store under way)");
      if (cycle - last_progress > watchdog_cycles) begin
        $display("zb_conf: WATCHDOG: %0d cycles without progress at cycle %0d, %s (%s)",
                 watchdog_cycles, cycle, phase, port_states());
        fail($sformatf("no progress for %0d cycles (+watchdog=N to allow more)", watchdog_cycles));
      end
    end
  end

`ifdef ZB_CONF_LOCKSTEP
  zb_conf_scoreboard #(.TILE_W(TILE_W), .TILE_H(TILE_H), .ACC_BITS(ACC_BITS),
                       .REV_BITS(REV_BITS)) u_sb (
    .clk_i        (clk),
    .accum_i      (planes[4]),
    .ret_d_valid_i(ret_d_valid),
    .ret_d_pixel_i(ret_d_pixel),
    .ret_dwe_i    (ret_dwe),
    .ret_wdepth_i (ret_wdepth),
    .ret_vwe_i    (ret_vwe),
    .ret_wcov_i   (ret_wcov),
    .ret_c_valid_i(ret_c_valid),
    .ret_c_pixel_i(ret_c_pixel),
    .ret_cwe_i    (ret_cwe),
    .ret_wcolor_i (ret_wcolor),
    .ret_awe_i    (ret_awe),
    .ret_wacc_i   (ret_wacc)
  );
`endif

  // ---------------------------------------------------------------------------------------
  // The test: its stream and the frame.
  // ---------------------------------------------------------------------------------------
  logic [127:0] words [MAX_WORDS + 1];
  logic [31:0]  fb_color [MAX_PIXELS];
  logic [31:0]  fb_depth [MAX_PIXELS];
  logic [7:0]   fb_cov   [MAX_PIXELS];
  logic [31:0]  fb_peel  [MAX_PIXELS];
  logic [AccW-1:0] fb_acc [MAX_PIXELS];
  int unsigned  width, height, count;
  string        stream_path, out_dir;
  int           gap_pct, seed;
  int           timing;    // 0 tight (every event at the first edge the contract allows), 1 loose
                           // (a cycle more before each wait), 2 seeded random (0 to 3 cycles more)
  bit           resident;  // several passes on one resident tile: one load, their states and
                           // fragments, one store (a profile's resident_tile)
  int unsigned  n_passes, n_frags, n_tiles;
  int unsigned  pass_index;  // the pass being streamed: its place in the stream (the waves' pass)
  int unsigned  frag_index;  // the fragment offered: its index in the pass (the waves' marker)

  function automatic logic [7:0] opcode(input logic [127:0] w);
    return w[127:120];
  endfunction

  function automatic logic [31:0] depth_max();
    return DEPTH_BITS >= 32 ? 32'hffff_ffff : (32'h1 << DEPTH_BITS) - 32'h1;
  endfunction

  // docs/datapath.md "Numerics": m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x * y.
  function automatic logic [7:0] mul_unorm8(input logic [7:0] x, input logic [7:0] y);
    logic [16:0] t;
    t = 17'(x) * 17'(y);
    return 8'((t + (t >> 8) + 17'h80) >> 8);
  endfunction

  // Frame operation "resolve under" on one channel: min(255, c + m(bg, 255 - A)).
  function automatic logic [7:0] resolve_under(input logic [7:0] c, input logic [7:0] bg,
                                               input logic [7:0] a);
    logic [8:0] v;
    v = 9'(c) + 9'(mul_unorm8(bg, 8'd255 - a));
    return v > 9'd255 ? 8'd255 : v[7:0];
  endfunction

  // Frame operation "resolve wboit" on one channel (docs/datapath.md "Resolve (frame operation
  // 4)"), integer division: avg = acc_A == 0 ? 0 : min(255, (acc * 255 + acc_A / 2) / acc_A),
  // then (avg * (one - r) + c * r + one / 2) / one. The alpha channel passes acc = acc_A.
  function automatic logic [7:0] resolve_wboit(input logic [31:0] acc, input logic [31:0] acc_a,
                                               input logic [7:0] c, input logic [15:0] r);
    logic [63:0] avg, one, half, a, rv;
    a    = 64'(acc_a);
    rv   = 64'(r);
    one  = (64'd1 << REV_BITS) - 64'd1;
`ifdef ZB_CONF_INJECT_RESOLVE_BUG
    half = 64'd0;  // a defect for CTest conformance_sv_resolve_bug: the rounding left out
`else
    half = one / 64'd2;
`endif
    avg  = a == 64'd0 ? 64'd0 : (64'(acc) * 64'd255 + a / 64'd2) / a;
    if (avg > 64'd255) avg = 64'd255;
    return 8'((avg * (one - rv) + 64'(c) * rv + half) / one);
  endfunction

  // The cleared accumulation word: revealage 1.0 (all ones), nothing accumulated.
  function automatic logic [AccW-1:0] acc_clear();
    logic [AccW-1:0] w;
    w = '0;
    w[4*ACC_BITS +: REV_BITS] = '1;
    return w;
  endfunction

  // Field k of an accumulation word: channel k (R, G, B, A) for k < 4, the revealage for k = 4.
  function automatic logic [31:0] acc_field(input logic [AccW-1:0] w, input int k);
    return k < 4 ? 32'(w[k*ACC_BITS +: ACC_BITS]) : 32'(w[4*ACC_BITS +: REV_BITS]);
  endfunction

  function automatic void fail(input string what);
    $display("zb_conf: FAILED: %s: %s", stream_path, what);
    $fatal(1, "zb_conf: %s", what);
  endfunction

  // The host's rule of docs/datapath.md "Frame operations", on the whole frame.
  task automatic frame_op(input logic [127:0] w);
    logic [3:0]  kind;
    logic [31:0] value, depth, c, acc_a;
    logic [15:0] r;
    kind  = w[3:0];
    value = w[63:32];
    depth = w[95:64];
    for (int unsigned p = 0; p < width * height; p++) begin
      unique case (kind)
        4'd0: fb_color[p] = value;
        4'd1: fb_depth[p] = depth > depth_max() ? depth_max() : depth;
        4'd2: fb_peel[p]  = fb_depth[p];
        4'd3: begin
          c = fb_color[p];
          fb_color[p] = {resolve_under(c[31:24], value[31:24], c[31:24]),
                         resolve_under(c[23:16], value[23:16], c[31:24]),
                         resolve_under(c[15:8],  value[15:8],  c[31:24]),
                         resolve_under(c[7:0],   value[7:0],   c[31:24])};
        end
        4'd5: ;  // the layers are the DUT's: resolved by the stores before this (st_resolve_i)
        4'd4: begin
          c     = fb_color[p];
          acc_a = acc_field(fb_acc[p], 3);
          r     = 16'(acc_field(fb_acc[p], 4));
          fb_color[p] = {resolve_wboit(acc_a, acc_a, c[31:24], r),
                         resolve_wboit(acc_field(fb_acc[p], 2), acc_a, c[23:16], r),
                         resolve_wboit(acc_field(fb_acc[p], 1), acc_a, c[15:8], r),
                         resolve_wboit(acc_field(fb_acc[p], 0), acc_a, c[7:0], r)};
        end
        default: fail($sformatf("frame operation of unknown kind %0d", kind));
      endcase
    end
`ifdef ZB_CONF_LOCKSTEP
    u_sb.frame_op(kind, value, depth);
`endif
  endtask

  // The gaps' pattern: xorshift32, the same on every simulator.
  logic [31:0] rng;
  function automatic int chance_pct();
    rng = rng ^ (rng << 13);
    rng = rng ^ (rng >> 17);
    rng = rng ^ (rng << 5);
    return int'(rng % 32'd100);
  endfunction

  // The cycles a host waits before its next event: none when tight, one when loose, 0 to 3
  // drawn from the gaps' generator when random.
  task automatic slack;
    int unsigned k;
    k = timing == 0 ? 0 : timing == 1 ? 1 : 32'(chance_pct()) % 4;
    repeat (k) @(negedge clk);
  endtask

  function automatic bit in_tile(input logic [127:0] w, input int unsigned x0,
                                 input int unsigned y0);
    int unsigned x, y;
    x = 32'(w[15:0]);
    y = 32'(w[31:16]);
    return x >= x0 && x < x0 + TILE_W && y >= y0 && y < y0 + TILE_H;
  endfunction

  // Loads the frame's pixels of the tile at (x0, y0); pixels off the frame load as zero.
  task automatic load_tile(input int unsigned x0, input int unsigned y0);
    int unsigned x, y, p;
    for (int unsigned k = 0; k < Words; k++) begin
      x = x0 + k % TILE_W;
      y = y0 + k / TILE_W;
      p = y * width + x;
      ld_valid = 1'b1;
      if (x < width && y < height) begin
        ld_color = fb_color[p];
        ld_depth = fb_depth[p];
        ld_cov   = fb_cov[p];
        ld_peel  = fb_peel[p];
        ld_acc   = fb_acc[p];
      end else begin
        ld_color = '0;
        ld_depth = '0;
        ld_cov   = '0;
        ld_peel  = '0;
        ld_acc   = '0;
      end
      phase = $sformatf("loading tile (%0d, %0d), pixel %0d of %0d: waiting for ld_ready_o", x0, y0, k, Words);
      @(negedge clk);
      while (!ld_took) @(negedge clk);
      progress();
    end
    ld_valid = 1'b0;
  endtask

  // Offers the pass's fragments in [first, last) that fall in the tile, in stream order.
  task automatic stream_tile(input int unsigned first, input int unsigned last,
                             input int unsigned x0, input int unsigned y0);
    logic [127:0] w;
    for (int unsigned k = first; k < last; k++) begin
      w = words[k];
      if (in_tile(w, x0, y0)) begin
        while (gap_pct > 0 && chance_pct() < gap_pct) begin
        frag_valid = 1'b0;
        @(negedge clk);
        end
        frag_valid = 1'b1;
        frag_index = k - first;
        phase = $sformatf("pass %0d, tile (%0d, %0d), fragment %0d of the pass: waiting for frag_ready_o",
                          pass_index, x0, y0, frag_index);
        frag_x     = w[15:0];
        frag_y     = w[31:16];
        frag_z     = w[63:32];
        frag_rgba  = w[95:64];
        frag_cov   = w[103:96];
`ifdef ZB_CONF_LOCKSTEP
        u_sb.accept(frag_index, frag_x, frag_y, frag_z, frag_rgba, frag_cov);
`endif
        @(negedge clk);
        while (!frag_took) @(negedge clk);
        progress();
        n_frags++;
      end
    end
    frag_valid = 1'b0;
  endtask

  // Reads the tile back into the frame (its pixels on the frame).
  // A pixel is taken at each rising edge with st_valid_o high, from the first one after the edge
  // that takes st_start_i: read here at the falling edge before it.
  task automatic store_tile(input int unsigned x0, input int unsigned y0, input bit resolve);
    int unsigned k, x, y;
    st_start   = 1'b1;
    st_resolve = resolve;
    @(posedge clk);
    storing = 1'b1;
    @(negedge clk);
    st_start   = 1'b0;
    st_resolve = 1'b0;
    k = 0;
    while (k < Words) begin
      phase = $sformatf("storing tile (%0d, %0d), pixel %0d of %0d: waiting for st_valid_o", x0, y0, k, Words);
      if (k > 0 || !st_valid) @(negedge clk);
      if (st_valid) begin
        progress();
        x = x0 + k % TILE_W;
        y = y0 + k / TILE_W;
        if (x < width && y < height) begin
          fb_color[y * width + x] = st_color;
          fb_depth[y * width + x] = st_depth;
          fb_cov[y * width + x]   = st_cov;
          fb_peel[y * width + x]  = st_peel;
          if (planes[4]) fb_acc[y * width + x] = st_acc;
        end
        k++;
        if (k == Words) begin
          @(posedge clk);
          storing = 1'b0;
        end
      end
    end
    phase = $sformatf("after the store of tile (%0d, %0d): waiting for idle_o", x0, y0);
    @(negedge clk);
    while (!idle) @(negedge clk);
    progress();
  endtask

  // Waits for idle_o; tight, it is read at this very falling edge (the last fragment taken at
  // the edge before), so the next event goes at the first edge that allows it.
  task automatic wait_idle;
    phase = $sformatf("pass %0d, tile (%0d, %0d): the tile's fragments sent, waiting for idle_o",
                      pass_index, tile_x0, tile_y0);
    slack();
    while (!idle) @(negedge clk);
    progress();
  endtask

  // A pass state write: a one-cycle pulse while idle_o.
  task automatic write_state(input logic [15:0] pass_state);
    slack();
    phase = "before a pass state write: waiting for idle_o";
    while (!idle) @(negedge clk);
    state        = pass_state[12:0];
    state_layers = pass_state[15:13];
    state_we     = 1'b1;
    @(negedge clk);
    state_we = 1'b0;
  endtask

  function automatic bit pass_touches(input int unsigned first, input int unsigned last,
                                      input int unsigned x0, input int unsigned y0);
    for (int unsigned k = first; k < last; k++)
      if (in_tile(words[k], x0, y0)) return 1'b1;
    return 1'b0;
  endfunction

  // One pass: the fragments are words[first .. last - 1]; every tile with one of them is
  // loaded, streamed and stored (with resolve, its layers resolved on the way out).
  task automatic run_pass(input logic [15:0] pass_state, input int unsigned first,
                          input int unsigned last, input bit resolve);
    pass_index = n_passes;
`ifdef ZB_CONF_LOCKSTEP
    u_sb.begin_pass(pass_state, pass_index);
`endif
    for (int unsigned y0 = 0; y0 < height; y0 += TILE_H) begin
      for (int unsigned x0 = 0; x0 < width; x0 += TILE_W) begin
        if (pass_touches(first, last, x0, y0)) begin
          n_tiles++;
          tile_x0 = 16'(x0);
          tile_y0 = 16'(y0);
          write_state(pass_state);
`ifdef ZB_CONF_LOCKSTEP
          u_sb.begin_tile(x0, y0);
`endif
          load_tile(x0, y0);
          slack();
          stream_tile(first, last, x0, y0);
          wait_idle();
`ifdef ZB_CONF_LOCKSTEP
          u_sb.end_tile();
`endif
          store_tile(x0, y0, resolve);
        end
      end
    end
`ifdef ZB_CONF_LOCKSTEP
    u_sb.end_pass();
`endif
  endtask

  // Passes with no frame operation between them, on resident tiles (a tiled GPU's schedule):
  // for each tile any of them touches, one load, then each pass's state write and its fragments
  // for the tile, the state written at the first edge after the last pass drained, one store.
  // Per pixel the fragments keep the stream's order, so the planes are the pass-major run's.
  int unsigned group_state [MAX_GROUP];
  int unsigned group_first [MAX_GROUP];
  int unsigned group_last  [MAX_GROUP];
  task automatic run_resident(input int unsigned passes, input bit resolve);
    bit touched, loaded;
    for (int unsigned y0 = 0; y0 < height; y0 += TILE_H) begin
      for (int unsigned x0 = 0; x0 < width; x0 += TILE_W) begin
        touched = 1'b0;
        for (int unsigned g = 0; g < passes && !touched; g++)
          touched = pass_touches(group_first[g], group_last[g], x0, y0);
        if (touched) begin
          n_tiles++;
          tile_x0 = 16'(x0);
          tile_y0 = 16'(y0);
          loaded = 1'b0;
          for (int unsigned g = 0; g < passes; g++) begin
            if (pass_touches(group_first[g], group_last[g], x0, y0)) begin
              pass_index = n_passes + g;
              write_state(16'(group_state[g]));
              if (!loaded) load_tile(x0, y0);
              loaded = 1'b1;
`ifdef ZB_CONF_LOCKSTEP
              u_sb.begin_pass(16'(group_state[g]), pass_index);
              u_sb.begin_tile(x0, y0);
`endif
              stream_tile(group_first[g], group_last[g], x0, y0);
              wait_idle();
`ifdef ZB_CONF_LOCKSTEP
              u_sb.end_tile();
              u_sb.end_pass();
`endif
            end
          end
          store_tile(x0, y0, resolve);
        end
      end
    end
  endtask

  // One plane's signature: plane 0 colour, 1 depth, 2 coverage (2 hex digits), 3 peel, 4 the
  // accumulation word (all its digits).
  task automatic write_plane(input int plane);
    int fd;
    string name;
    logic [31:0] v;
    name = plane == 0 ? "color" : plane == 1 ? "depth" : plane == 2 ? "coverage" :
           plane == 3 ? "peel" : "accum";
    fd = $fopen({out_dir, "/got.", name, ".hex"}, "w");
    if (fd == 0) fail($sformatf("cannot write %s/got.%s.hex (does the folder exist?)", out_dir, name));
    for (int unsigned p = 0; p < width * height; p++) begin
      v = plane == 0 ? fb_color[p] : plane == 1 ? fb_depth[p] : plane == 2 ? 32'(fb_cov[p]) : fb_peel[p];
      if (plane == 4)      $fdisplay(fd, "%h", fb_acc[p]);
      else if (plane == 2) $fdisplay(fd, "%02x", v[7:0]);
      else                 $fdisplay(fd, "%08x", v);
    end
    $fclose(fd);
  endtask

  // The planes' digest after each pass, so that what a later pass overwrites is still seen
  // (docs/conformance.md "Every pass seen"): FNV-1a over 64 bits of the colour, depth, coverage
  // and peel words, plane after plane, each row-major, as the checker's frame_digest. A line
  // "<passes done> <16 hex digits>" of got.passes.hex after each pass (pass by pass) or group
  // (resident tiles); none after a group whose stores resolved the layers.
  int passes_fd = 0;
  function automatic logic [63:0] frame_digest();
    logic [63:0] h;
    h = 64'hcbf2_9ce4_8422_2325;
    for (int unsigned p = 0; p < width * height; p++) h = (h ^ 64'(fb_color[p])) * 64'h100_0000_01b3;
    for (int unsigned p = 0; p < width * height; p++) h = (h ^ 64'(fb_depth[p])) * 64'h100_0000_01b3;
    for (int unsigned p = 0; p < width * height; p++) h = (h ^ 64'(fb_cov[p])) * 64'h100_0000_01b3;
    for (int unsigned p = 0; p < width * height; p++) h = (h ^ 64'(fb_peel[p])) * 64'h100_0000_01b3;
    return h;
  endfunction

  initial begin : waves
    string path;
    int    from;
    if ($value$plusargs("dump=%s", path)) begin
      if (!$value$plusargs("dump_from=%d", from)) from = 0;
      $dumpfile(path);
      if (from > 0) #(from * 10);
      $dumpvars(0, zb_conf_tb);
    end
  end

  initial begin : run
    logic [127:0] w;
    int unsigned  pc, group;
    bit           needs_accum, layered, resolve;
    int unsigned  needs_layers;
    if (!$value$plusargs("stream=%s", stream_path))
      $fatal(1, "zb_conf: no +stream=FILE: name a test's stream.hex (docs/conformance.md)");
    if (!$value$plusargs("out=%s", out_dir)) out_dir = ".";
    if (!$value$plusargs("gap=%d", gap_pct)) gap_pct = 0;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    if (!$value$plusargs("watchdog=%d", watchdog_cycles)) watchdog_cycles = 10000;
    if (!$value$plusargs("timing=%d", timing)) timing = 0;
    if (!$value$plusargs("resident=%d", resident)) resident = 1'b0;
    if (timing < 0 || timing > 2) fail($sformatf("+timing=%0d: 0 tight, 1 loose, 2 random", timing));
    rng = 32'(seed) ^ 32'h9e37_79b9;
    if (rng == 0) rng = 32'h1;
    for (int unsigned k = 0; k <= MAX_WORDS; k++) words[k] = '0;
    // The count line first, then exactly the words it announces: no simulator warns of a short
    // file, and a stream longer than MAX_WORDS is refused before it is read.
    $readmemh(stream_path, words, 0, 0);
    count = words[0][31:0];
    if (count < 2 || count > MAX_WORDS)
      fail($sformatf("%0d command words (is the file a stream.hex?): a stream holds 2 to %0d (MAX_WORDS)",
                     count, MAX_WORDS));
    $readmemh(stream_path, words, 0, count);
    w = words[1];
    if (opcode(w) != OpFrame) fail("the first command is not FRAME");
    width  = 32'(w[15:0]);
    height = 32'(w[31:16]);
    if (w[39:32] != 8'(DEPTH_BITS) || w[47:40] != 8'(COV_SAMPLES))
      fail($sformatf("the test needs DEPTH_BITS=%0d COV_SAMPLES=%0d; this DUT has %0d and %0d",
                     w[39:32], w[47:40], DEPTH_BITS, COV_SAMPLES));
    if (w[103:96] != 8'(ACC_BITS) || w[111:104] != 8'(REV_BITS) || w[119:112] != 8'(WEIGHT_BITS))
      fail($sformatf("the test needs ACC_BITS=%0d REV_BITS=%0d WEIGHT_BITS=%0d; this DUT has %0d, %0d and %0d",
                     w[103:96], w[111:104], w[119:112], ACC_BITS, REV_BITS, WEIGHT_BITS));
    if (width * height > MAX_PIXELS || width == 0 || height == 0)
      fail($sformatf("frame %0dx%0d: 1 to %0d pixels (MAX_PIXELS)", width, height, MAX_PIXELS));
    for (int unsigned p = 0; p < width * height; p++) begin
      fb_color[p] = w[95:64];
      fb_depth[p] = depth_max();
      fb_cov[p]   = '0;
      fb_peel[p]  = '0;
      fb_acc[p]   = acc_clear();
    end
`ifdef ZB_CONF_LOCKSTEP
    u_sb.begin_frame(width, height, DEPTH_BITS, COV_SAMPLES, w[95:64], WEIGHT_BITS);
`endif
    n_passes = 0;
    n_frags  = 0;
    n_tiles  = 0;
    repeat (2) @(negedge clk);
    rst_n = 1'b1;
    @(negedge clk);
    planes_at_reset = planes;
    layers_at_reset = layers;
    progress();
    checking = 1'b1;
    if (planes[3:0] != 4'hf)
      fail($sformatf("the adapter's planes_o is %05b: colour, depth, coverage and peel are needed", planes));
    if (planes[4]) $display("zb_conf: planes: color depth coverage peel accum");
    else           $display("zb_conf: planes: color depth coverage peel");
    // A resolve wboit (frame operation 4) reads the accumulation plane.
    needs_accum = 1'b0;
    for (int unsigned k = 2; k <= count; k++)
      if (opcode(words[k]) == OpFrameOp && words[k][3:0] == 4'd4) needs_accum = 1'b1;
    if (needs_accum && !planes[4]) begin
      $display("zb_conf: skip: %s: the test resolves from the accumulation plane, which the DUT does not have",
               stream_path);
      $finish;
    end
    // A layers pass (blend 6) keeps K = [15:13] + 1 layers a pixel: at most layers_o.
    needs_layers = 0;
    for (int unsigned k = 2; k <= count; k++)
      if (opcode(words[k]) == OpPass && words[k][7:5] == 3'd6 && 32'(words[k][15:13]) + 1 > needs_layers)
        needs_layers = 32'(words[k][15:13]) + 1;
    if (needs_layers > 32'(layers)) begin
      $display("zb_conf: skip: %s: the test keeps %0d layers a pixel; the DUT keeps %0d (layers_o)",
               stream_path, needs_layers, layers);
      $finish;
    end

    passes_fd = $fopen({out_dir, "/got.passes.hex"}, "w");
    if (passes_fd == 0) fail($sformatf("cannot write %s/got.passes.hex (does the folder exist?)", out_dir));
    pc = 2;
    while (opcode(words[pc]) != OpEnd) begin
      if (pc > count) fail("no END command");
      w = words[pc];
      if (opcode(w) == OpFrameOp) begin
        frame_op(w);
        pc++;
      end else if (opcode(w) == OpPass) begin
        // A pass; on resident tiles, the passes up to the next frame operation or END, run
        // tile by tile.
        group   = 0;
        layered = 1'b0;
        while (opcode(words[pc]) == OpPass && group < (resident ? MAX_GROUP : 1)) begin
          group_state[group] = 32'(words[pc][15:0]);
          layered |= words[pc][7:5] == 3'd6;
          group_first[group] = pc + 1;
          pc++;
          while (pc <= count && opcode(words[pc]) == OpFrag) pc++;
          if (opcode(words[pc]) != OpEndPass) fail($sformatf("word %0d: a pass not ended by END_PASS", pc));
          group_last[group] = pc;
          group++;
          pc++;
        end
        // The layers live on the tile: the group's stores resolve them when a resolve of the
        // layers follows it, and a layers pass must be followed by one before any store.
        resolve = opcode(words[pc]) == OpFrameOp && words[pc][3:0] == 4'd5;
        if (layered && !resolve)
          fail($sformatf("word %0d: a layers pass (blend 6) not followed by frame operation 5 (resolve layers): %s",
                         pc, resident ? "its layers would be lost at the tile's store"
                                      : "its layers would be lost at the pass's store (try +resident=1)"));
        if (resident) run_resident(group, resolve);
        else run_pass(16'(group_state[0]), group_first[0], group_last[0], resolve);
        n_passes += group;
        if (!resolve) $fdisplay(passes_fd, "%0d %016x", n_passes, frame_digest());
      end else begin
        fail($sformatf("word %0d: opcode %02x where a pass, a frame operation or END belongs",
                       pc, opcode(w)));
      end
    end
    $fclose(passes_fd);
    for (int plane = 0; plane < (planes[4] ? 5 : 4); plane++) write_plane(plane);
    $display("zb_conf: done: %s: %0dx%0d, %0d passes, %0d fragments, %0d tile loads, %0d cycles",
             stream_path, width, height, n_passes, n_frags, n_tiles, $time / 10);
    $finish;
  end

endmodule
