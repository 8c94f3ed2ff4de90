// zb_rop: the per-pixel datapath (raster operations unit) of docs/datapath.md, top level.
//
// Pipelined for 100 MHz in iCE40 fabric, one fragment per clock; docs/rtl.md has the diagram.
//   I/S  input register and skid register (frag_ready_o comes from a flop)
//   W    issue window (zb_issue_window): picks the oldest fragment whose pixel is free, so a
//        fragment that waits for its pixel does not hold back fragments to other pixels
//   M    issue: depth, coverage and peel reads
//   X1..X4   depth, coverage, peel: data, compare, decide, write (edge E4)
//   X1..X6   fragment side of the blend: m(s, a), k, 3k, coverage weight terms
//   X6..X11  colour: read at edge E6, blend (zb_blend, 4 stages), write at edge E11
// A fragment issues at least Span = 4 cycles after an older one to its pixel, so every read
// sees every older write: from the memory; at the edge of the older fragment's write (depth,
// coverage at E4; colour at E11), from the forwarding register that holds that write (the RAMs
// need no read-during-write behaviour); or, a colour read one edge before the older colour
// write, from that write's data itself, bypassed into the younger fragment's X7.
// Reset: rst_ni, asynchronous, active low, on control state only (valid bits, window, pass
// state, counters). Memories and data registers are not reset.
module zb_rop
#(
  parameter int unsigned DEPTH_BITS = 24,   // 8..32
  parameter int unsigned TILE_W     = 64,   // power of two
  parameter int unsigned TILE_H     = 64,   // power of two
  parameter int unsigned CNT_W      = 32,
  parameter int unsigned COV_SAMPLES = 16,  // N of the sample pattern: 1, 2, 4, 8 or 16
  parameter int unsigned WINDOW     = 8,    // issue window slots, 2..16
  parameter int unsigned BEAT       = 8,    // tile port pixels per clock: 2..TILE_W, power of two
  localparam int unsigned AddrW     = $clog2(TILE_W * TILE_H),
  localparam int unsigned BeatAW    = $clog2(TILE_W * TILE_H / BEAT),
  localparam int unsigned CovW      = $clog2(COV_SAMPLES + 1)  // coverage count 0..N
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  state_we_i,
  input  zb_pkg::pass_state_t   state_i,
  input  logic [15:0]           tile_x0_i,
  input  logic [15:0]           tile_y0_i,
  input  logic                  frag_valid_i,
  output logic                  frag_ready_o,
  input  logic [15:0]           frag_x_i,
  input  logic [15:0]           frag_y_i,
  input  logic [DEPTH_BITS-1:0] frag_z_i,
  input  logic [31:0]           frag_rgba_i,
  input  logic [CovW-1:0]       frag_cov_i,
  input  logic                  stall_i,
  // Tile port (docs/rtl.md "Tile port"): a beat of BEAT pixels of a row a clock, lane b at
  // [b*width +: width]. tile_req_i with tile_we_i loads the beat at tile_addr_i into the planes
  // of tile_planes_i; without, reads it (the data next clock). tile_clear_i fast-clears the
  // planes of tile_planes_i to lane 0 of the write data: no beat moves.
  input  logic                       tile_req_i,
  input  logic                       tile_we_i,
  input  logic                       tile_clear_i,
  input  zb_pkg::planes_t            tile_planes_i,
  input  logic [BeatAW-1:0]          tile_addr_i,
  input  logic [BEAT*32-1:0]         tile_wcolor_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wdepth_i,
  input  logic [BEAT*CovW-1:0]       tile_wcov_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wpeel_i,
  output logic [BEAT*32-1:0]         tile_rcolor_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rdepth_o,
  output logic [BEAT*CovW-1:0]       tile_rcov_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rpeel_o,
  output logic                  busy_o,
  input  logic                  cnt_clear_i,
  output logic [CNT_W-1:0]      cnt_frag_in_o,
  output logic [CNT_W-1:0]      cnt_frag_passed_o,
  output logic [CNT_W-1:0]      cnt_frag_killed_o,
  output logic [CNT_W-1:0]      cnt_depth_reads_o,
  output logic [CNT_W-1:0]      cnt_depth_writes_o,
  output logic [CNT_W-1:0]      cnt_color_reads_o,
  output logic [CNT_W-1:0]      cnt_color_writes_o,
  output logic [CNT_W-1:0]      cnt_stall_cycles_o,
  output logic [CNT_W-1:0]      cnt_cycles_o,
  output logic [CNT_W-1:0]      cnt_tile_loads_o,    // beats loaded
  output logic [CNT_W-1:0]      cnt_tile_stores_o    // beats read
);

  localparam int unsigned XW    = $clog2(TILE_W);
  localparam int unsigned YW    = $clog2(TILE_H);
  localparam int unsigned Words = TILE_W * TILE_H;

`ifndef SYNTHESIS
  if (TILE_W < 2 || TILE_W != (1 << XW) || TILE_H < 2 || TILE_H != (1 << YW)) begin : g_bad_tile
    $error("zb_rop: TILE_W and TILE_H must be powers of two, at least 2");
  end
  if (DEPTH_BITS < 8 || DEPTH_BITS > 32) begin : g_bad_depth
    $error("zb_rop: DEPTH_BITS must be 8..32");
  end
  if (COV_SAMPLES < 1 || COV_SAMPLES > 16 || (COV_SAMPLES & (COV_SAMPLES - 1)) != 0)
  begin : g_bad_cov
    $error("zb_rop: COV_SAMPLES must be 1, 2, 4, 8 or 16");
  end
  if (BEAT < 2 || BEAT > TILE_W || (BEAT & (BEAT - 1)) != 0) begin : g_bad_beat
    $error("zb_rop: BEAT must be a power of two, 2..TILE_W");
  end
`endif

  // ---------------------------------------------------------------------------------------
  // Pass state register (docs/datapath.md "The pass state"); loaded only while idle.
  // ---------------------------------------------------------------------------------------
  zb_pkg::pass_state_t state_d, state_q;
  logic        st_depth_test, st_depth_write, st_peel_test;
  zb_pkg::depth_func_e st_depth_func;
  zb_pkg::blend_mode_e st_blend;
  logic [3:0]  st_color_mask;


  always_comb begin
    state_d = state_q;
    if (state_we_i) begin
      state_d = state_i;
    end
  end

  assign st_depth_test  = state_q.depth_test;
  assign st_depth_func  = state_q.depth_func;
  assign st_depth_write = state_q.depth_write;
  assign st_blend       = state_q.blend;
  assign st_color_mask  = state_q.color_mask;
  assign st_peel_test   = state_q.peel_test;

  logic st_cov;  // coverage mode (docs/datapath.md "Coverage blend")
  assign st_cov = st_blend == zb_pkg::BlendCoverage;

  localparam int unsigned QW    = 8 + CovW;  // coverage blend addend w*s + N/2 (zb_blend)
  // A younger fragment to the same pixel issues at least Span cycles after the older one. At
  // Span its depth and coverage reads meet the older one's writes (E4) and take the written
  // words from the forwarding registers. Its colour read (E5) comes before the older colour
  // write: at Span that write is at the younger's E7, so X7 takes the older one's write data
  // (bypass); at Span + 1 at E6, and at Span + 2 at the read edge E5: X6 catches either in
  // fwd_color_q. Below 4 the older result would not exist yet when the younger's X7 needs it.
  localparam int unsigned Span  = 4;

  // ---------------------------------------------------------------------------------------
  // Input: I (main) and S (skid). frag_ready_o is a flop (S empty) gated by the two inputs
  // that stop the stream, so it is not at the end of the interlock's comparators.
  // ---------------------------------------------------------------------------------------
  logic                  accept, in_ready_d, in_ready_q;
  logic [15:0]           dx, dy;
  logic [AddrW-1:0]      in_addr;
  logic                  i_valid_d, i_valid_q, s_valid_d, s_valid_q;
  logic [AddrW-1:0]      i_addr_d, i_addr_q, s_addr_d, s_addr_q;
  logic [DEPTH_BITS-1:0] i_z_d, i_z_q, s_z_d, s_z_q;
  logic [31:0]           i_rgba_d, i_rgba_q, s_rgba_d, s_rgba_q;
  logic [CovW-1:0]       i_cov_d, i_cov_q, s_cov_d, s_cov_q;
  logic                  i_free;       // I's fragment leaves (or I is empty) at this edge
  logic                  m_adv;        // the window takes I's fragment at this edge

  assign frag_ready_o = in_ready_q & ~stall_i & ~tile_req_i & ~tile_clear_i;
  assign accept       = frag_valid_i & frag_ready_o;
  assign dx           = frag_x_i - tile_x0_i;
  assign dy           = frag_y_i - tile_y0_i;
  assign in_addr      = {dy[YW-1:0], dx[XW-1:0]};   // y_local * TILE_W + x_local
  assign i_free       = ~i_valid_q | m_adv;

  always_comb begin
    i_valid_d = i_valid_q;
    i_addr_d  = i_addr_q;
    i_z_d     = i_z_q;
    i_rgba_d  = i_rgba_q;
    i_cov_d   = i_cov_q;
    s_valid_d = s_valid_q;
    s_addr_d  = s_addr_q;
    s_z_d     = s_z_q;
    s_rgba_d  = s_rgba_q;
    s_cov_d   = s_cov_q;
    if (i_free) begin
      if (s_valid_q) begin          // (no accept: frag_ready_o is low while S is full)
        i_valid_d = 1'b1;
        i_addr_d  = s_addr_q;
        i_z_d     = s_z_q;
        i_rgba_d  = s_rgba_q;
        i_cov_d   = s_cov_q;
        s_valid_d = 1'b0;
      end else begin
        i_valid_d = accept;
        if (accept) begin
          i_addr_d = in_addr;
          i_z_d    = frag_z_i;
          i_rgba_d = frag_rgba_i;
          i_cov_d  = frag_cov_i;
        end
      end
    end else if (accept) begin
      s_valid_d = 1'b1;
      s_addr_d  = in_addr;
      s_z_d     = frag_z_i;
      s_rgba_d  = frag_rgba_i;
      s_cov_d   = frag_cov_i;
    end
  end
  assign in_ready_d = ~s_valid_d;

`ifndef SYNTHESIS
  // An accepted fragment lies inside the resident tile.
  FragInTile: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
  // A fragment covers at most the N samples of a pixel.
  FragCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (frag_cov_i <= CovW'(COV_SAMPLES)));
`endif

  // ---------------------------------------------------------------------------------------
  // W: the issue window (zb_issue_window). It picks the oldest fragment whose pixel is free
  // (no older fragment in the window has it, and none issued less than Span cycles before this
  // one would issue); M takes the pick and issues it: the depth, coverage and peel reads.
  // ---------------------------------------------------------------------------------------
  localparam int unsigned WinDataW = 10 + CovW + 32 + DEPTH_BITS;  // {3 a, cov, rgba, z}

  logic                  m_valid_q;
  logic [AddrW-1:0]      m_addr_q;
  logic [DEPTH_BITS-1:0] m_z_q;
  logic [31:0]           m_rgba_q;
  logic [CovW-1:0]       m_cov_q;
  logic [9:0]            m_a3_q;      // 3 a for the premultiply (zb_premul)
  logic                  issue;
  logic                  w_ready, w_busy, pick_valid;
  logic [AddrW-1:0]      pick_addr;
  logic [WinDataW-1:0]   pick_data;
  logic [9:0]            i_a3;

  // Pipeline after M: one valid bit and address per stage, x[k] for Xk (k = 1..11).
  localparam int unsigned Last = 11;
  logic [Last:1]         x_valid_q;
  logic [Last*AddrW-1:0] x_addr_q;          // Xk at [(k-1)*AddrW +: AddrW]
  logic [AddrW-1:0]      x4_addr, x5_addr, x6_addr, x10_addr, x11_addr;
  assign x5_addr  = x_addr_q[4*AddrW +: AddrW];
  assign x4_addr  = x_addr_q[3*AddrW +: AddrW];
  assign x6_addr  = x_addr_q[5*AddrW +: AddrW];
  assign x10_addr = x_addr_q[9*AddrW +: AddrW];
  assign x11_addr = x_addr_q[10*AddrW +: AddrW];

  // The window's view of the pipeline after it: P1 = M, P(k+1) = Xk.
  logic [Span-3:0]           pos_valid;
  logic [(Span-2)*AddrW-1:0] pos_addr;
  assign pos_valid = {x_valid_q[Span-3:1], m_valid_q};
  assign pos_addr  = {x_addr_q[0 +: (Span-3)*AddrW], m_addr_q};

  assign i_a3   = {2'b00, i_rgba_q[31:24]} + {1'b0, i_rgba_q[31:24], 1'b0};
  assign m_adv  = w_ready;
  assign issue  = m_valid_q;

  zb_issue_window #(
    .WINDOW(WINDOW),
    .ADDR_W(AddrW),
    .DATA_W(WinDataW),
    .SPAN  (Span)
  ) u_window (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .in_valid_i  (i_valid_q),
    .in_ready_o  (w_ready),
    .in_addr_i   (i_addr_q),
    .in_data_i   ({i_a3, i_cov_q, i_rgba_q, i_z_q}),
    .pos_valid_i (pos_valid),
    .pos_addr_i  (pos_addr),
    .pick_valid_o(pick_valid),
    .pick_addr_o (pick_addr),
    .pick_data_o (pick_data),
    .busy_o      (w_busy)
  );

  // ---------------------------------------------------------------------------------------
  // Depth, coverage and peel planes: read at the issue edge E0 (M's address), written at E4.
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] dmem_rdata, pmem_rdata;
  logic [CovW-1:0]       vmem_rdata;
  logic                  x4_dwe, x4_vwe;
  logic [DEPTH_BITS-1:0] x4_z_q;
  logic [CovW-1:0]       x4_cov_new_q;

  zb_plane #(
    .WIDTH    (DEPTH_BITS),
    .WORDS    (Words),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_depth_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_planes_i.depth),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wdepth_i),
    .tile_rdata_o(tile_rdepth_o),
    .pipe_re_i   (issue),
    .pipe_raddr_i(m_addr_q),
    .pipe_we_i   (x4_dwe),
    .pipe_waddr_i(x4_addr),
    .pipe_wdata_i(x4_z_q),
    .rdata_o     (dmem_rdata)
  );

  zb_plane #(
    .WIDTH    (CovW),
    .WORDS    (Words),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_cov_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_planes_i.coverage),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wcov_i),
    .tile_rdata_o(tile_rcov_o),
    .pipe_re_i   (issue),
    .pipe_raddr_i(m_addr_q),
    .pipe_we_i   (x4_vwe),
    .pipe_waddr_i(x4_addr),
    .pipe_wdata_i(x4_cov_new_q),
    .rdata_o     (vmem_rdata)
  );

  // Peel: written only by the tile port, so its word is constant during a pass.
  zb_plane #(
    .WIDTH    (DEPTH_BITS),
    .WORDS    (Words),
    .BEAT     (BEAT),
    .READ_ONLY(1'b1)
  ) u_peel_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_planes_i.peel),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wpeel_i),
    .tile_rdata_o(tile_rpeel_o),
    .pipe_re_i   (issue),
    .pipe_raddr_i(m_addr_q),
    .pipe_we_i   (1'b0),
    .pipe_waddr_i(m_addr_q),
    .pipe_wdata_i(m_z_q),
    .rdata_o     (pmem_rdata)
  );

  // Depth and coverage forwarding: a fragment issued at an older one's E4 with its address
  // reads the word that edge writes; the written word replaces the RAM's in X1.
  logic                  dfwd_hit_q, vfwd_hit_q;
  logic [DEPTH_BITS-1:0] dfwd_z_q, x1_zs;
  logic [CovW-1:0]       vfwd_cov_q, x1_cs;
  assign x1_zs = dfwd_hit_q ? dfwd_z_q : dmem_rdata;
  assign x1_cs = vfwd_hit_q ? vfwd_cov_q : vmem_rdata;

  // X1: read data arrives; registered with at most the forwarding mux (the RAM's clock-to-out
  // is long on iCE40).
  logic [DEPTH_BITS-1:0] x1_z_q, x2_z_q, x3_z_q;
  logic [6*32-1:0]       x_rgba_q;          // X1..X6, Xk at [(k-1)*32 +: 32]
  logic [31:0]           x1_rgba, x4_rgba, x6_rgba;
  logic [CovW-1:0]       x1_cov_q, x2_cov_q, x3_cov_q;
  logic [DEPTH_BITS-1:0] x2_zs_q, x2_peel_q;
  logic [CovW-1:0]       x2_cs_q, x3_cs_q;
  logic [39:0]           x2_s3_q, x3_s3_q, x4_s3_q;   // 3 s per channel

  // X2: compares.
  logic x3_lt_q, x3_eq_q, x3_behind_q;

  // X3: decisions (zb_depth_test, zb_coverage_composite).
  logic            x3_cmp, x3_pass, x3_nearer, x3_dwe;
  logic [CovW-1:0] x3_weight, x3_cov_new;
  logic            x4_pass_q, x4_dwe_q;
  logic [CovW-1:0] x4_weight_q;

  zb_depth_test u_depth_test (
    .func_i(st_depth_func),
    .lt_i  (x3_lt_q),
    .eq_i  (x3_eq_q),
    .pass_o(x3_cmp)
  );

  zb_coverage_composite #(
    .COV_SAMPLES(COV_SAMPLES)
  ) u_coverage (
    .lt_i        (x3_lt_q),
    .eq_i        (x3_eq_q),
    .cov_i       (x3_cov_q),
    .stored_cov_i(x3_cs_q),
    .nearer_o    (x3_nearer),
    .weight_o    (x3_weight),
    .cov_o       (x3_cov_new)
  );

  // Test off: every fragment passes the depth test and depth is never written. Peel test on:
  // a fragment must also lie strictly behind the peel plane. Coverage mode: every fragment
  // passes to the compositing (the peel test is not used); depth is written only when nearer.
  assign x3_pass = st_cov | ((~st_depth_test | x3_cmp) & (~st_peel_test | x3_behind_q));
  assign x3_dwe  = x3_pass & st_depth_test & st_depth_write & (~st_cov | x3_nearer);

  // X4: depth and coverage writes (edge E4); the fragment's counters.
  assign x4_dwe = x_valid_q[4] & x4_dwe_q;
  assign x4_vwe = x_valid_q[4] & st_cov;

  // ---------------------------------------------------------------------------------------
  // Fragment side of the blend, X1..X6: m(s, a) (zb_premul, X1 -> X5), the coverage weight's
  // terms (X4 -> X6), then per mode k, 3k and the addend for zb_blend (X6 -> X7).
  // ---------------------------------------------------------------------------------------
  localparam logic [CovW-1:0] Full = CovW'(COV_SAMPLES);
  localparam logic [QW-1:0]   Half = QW'(COV_SAMPLES / 2);

  logic [31:0] x5_ms, x6_ms_q;
  logic [39:0] x6_ms3_q;
  logic [6*10-1:0] x_a3_q;                  // X1..X6, Xk at [(k-1)*10 +: 10]
  logic [9:0]  x6_ia3_q;                    // 3 (255 - a)
  logic [7:0]  x5_kc_q, x6_kc_q;            // coverage k = N - w
  logic [9:0]  x6_kc3_q;
  logic [4*12-1:0] x5_wsa_q, x5_wsb_q;      // w s = sel(w[1:0]) s + 4 sel(w[3:2]) s + 16 w[4] s
  logic [4*QW-1:0] x6_q_q, x7_q_q;
  logic [31:0] x7_k_q, x7_add_q;
  logic [39:0] x7_k3_q;
  logic [Last:4] x_pass_q;                  // X4..X11

  assign x1_rgba = x_rgba_q[0*32 +: 32];
  assign x4_rgba = x_rgba_q[3*32 +: 32];
  assign x6_rgba = x_rgba_q[5*32 +: 32];

  zb_premul u_premul (
    .clk_i (clk_i),
    .rgba_i(x1_rgba),
    .a3_i  (x_a3_q[0*10 +: 10]),
    .ms_o  (x5_ms)
  );

  // The weight terms need w (X4) and 3 s (X1 -> X2).
  logic [4*12-1:0] x4_wsa, x4_wsb;
  logic [CovW-1:0] x4_kc;
  assign x4_kc = Full - x4_weight_q;
  for (genvar c = 0; c < 4; c++) begin : g_weight
    logic [7:0]  s;
    logic [9:0]  s3;
    logic [9:0]  sel_lo, sel_hi;
    logic [CovW-1:0] w;
    assign s  = x4_rgba[8*c +: 8];
    assign s3 = x4_s3_q[10*c +: 10];
    // w <= N <= 16: bits above 4 are zero; widen to five bits.
    logic [4:0] w5;
    assign w  = x4_weight_q;
    assign w5 = 5'(w);
    always_comb begin
      unique case (w5[1:0])
        2'd0:    sel_lo = '0;
        2'd1:    sel_lo = {2'b00, s};
        2'd2:    sel_lo = {1'b0, s, 1'b0};
        default: sel_lo = s3;
      endcase
      unique case (w5[3:2])
        2'd0:    sel_hi = '0;
        2'd1:    sel_hi = {2'b00, s};
        2'd2:    sel_hi = {1'b0, s, 1'b0};
        default: sel_hi = s3;
      endcase
    end
    assign x4_wsa[12*c +: 12] = {2'b00, sel_lo} + {sel_hi, 2'b00};
    assign x4_wsb[12*c +: 12] = w5[4] ? {s, 4'h0} : 12'h000;
  end

  // Per mode: k, 3k and the addend (zb_blend's header), X6 -> X7.
  logic [31:0] x6_k, x6_add;
  logic [39:0] x6_k3;
  logic [7:0]  x6_a;
  assign x6_a = x6_rgba[31:24];

  for (genvar c = 0; c < 4; c++) begin : g_operands
    logic [7:0] s;
    assign s = x6_rgba[8*c +: 8];
    always_comb begin
      x6_k[8*c +: 8]    = 8'h00;                    // replace: m(0) + s = s
      x6_k3[10*c +: 10] = 10'h000;
      x6_add[8*c +: 8]  = s;
      unique case (st_blend)
        zb_pkg::BlendAlpha: begin
          x6_k[8*c +: 8]    = ~x6_a;
          x6_k3[10*c +: 10] = x6_ia3_q;
          x6_add[8*c +: 8]  = x6_ms_q[8*c +: 8];
        end
        zb_pkg::BlendAdditive: begin  // m(d, 255) = d
          x6_k[8*c +: 8]    = 8'hff;
          x6_k3[10*c +: 10] = 10'd765;
          x6_add[8*c +: 8]  = x6_ms_q[8*c +: 8];
        end
        zb_pkg::BlendCoverage: begin
          x6_k[8*c +: 8]    = x6_kc_q;
          x6_k3[10*c +: 10] = x6_kc3_q;
          x6_add[8*c +: 8]  = 8'h00;
        end
        zb_pkg::BlendUnder: begin     // RGB scale m(s, a), alpha a
          x6_k[8*c +: 8]    = (c == 3) ? x6_a : x6_ms_q[8*c +: 8];
          x6_k3[10*c +: 10] = (c == 3) ? x_a3_q[5*10 +: 10] : x6_ms3_q[10*c +: 10];
          x6_add[8*c +: 8]  = 8'h00;
        end
        default: ;
      endcase
    end
  end

  // ---------------------------------------------------------------------------------------
  // Colour: read at E5 (X5's address), the word registered in X6 (the RAM's clock-to-out and
  // the plane's resolve get a cycle of their own), blend X7..X11, write at E11 when passed and
  // masked in.
  // ---------------------------------------------------------------------------------------
  logic [31:0] cmem_rdata, x7_mem_q, x11_color, x7_dst;
  logic        x11_cwe;
  logic        fwd5_hit, fwd6_hit;    // X5's read meets X11's write at E5; X6 meets it at E6
  logic        fwd6_hit_q;            // X6: X5's read met a write of its pixel at E5
  logic [31:0] fwd6_color_q;          // the word written at that edge
  logic        fwd_hit_q;             // X7: a write of its pixel at E5 or E6
  logic [31:0] fwd_color_q;           // that word
  logic        byp_hit_q;       // X7: the fragment now in X11 writes X7's pixel at this edge
  logic        x10_cwe;

  // Forwarding: the RAM's word for a read at the edge of a write to it is undefined
  // (no_rw_check), and a write at E5 or E6 is newer than the word read. Bypass: the fragment
  // now in X11 writes X7's pixel at this edge, the newest word of the pixel; it takes
  // precedence over fwd_color_q.
  assign fwd5_hit = x_valid_q[5] & x11_cwe & (x5_addr == x11_addr);
  assign fwd6_hit = x_valid_q[6] & x11_cwe & (x6_addr == x11_addr);
  assign x7_dst  = byp_hit_q ? x11_color : (fwd_hit_q ? fwd_color_q : x7_mem_q);
  assign x10_cwe = x_valid_q[10] & x_pass_q[10] & (st_color_mask != 4'h0);

  assign x11_cwe = x_valid_q[11] & x_pass_q[11] & (st_color_mask != 4'h0);

  zb_plane #(
    .WIDTH    (32),
    .WORDS    (Words),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_color_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_planes_i.color),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wcolor_i),
    .tile_rdata_o(tile_rcolor_o),
    .pipe_re_i   (x_valid_q[5]),
    .pipe_raddr_i(x5_addr),
    .pipe_we_i   (x11_cwe),
    .pipe_waddr_i(x11_addr),
    .pipe_wdata_i(x11_color),
    .rdata_o     (cmem_rdata)
  );

  zb_blend #(
    .COV_SAMPLES(COV_SAMPLES)
  ) u_blend (
    .clk_i  (clk_i),
    .mode_i (st_blend),
    .mask_i (st_color_mask),
    .dst_i  (x7_dst),
    .k_i    (x7_k_q),
    .k3_i   (x7_k3_q),
    .add_i  (x7_add_q),
    .q_i    (x7_q_q),
    .color_o(x11_color)
  );

  assign busy_o        = i_valid_q | s_valid_q | w_busy | m_valid_q | (|x_valid_q);

  // ---------------------------------------------------------------------------------------
  // Flops. Control (valid bits, interlock, ready, pass state) reset; data not.
  // ---------------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q    <= '0;
      in_ready_q <= 1'b1;
      i_valid_q  <= 1'b0;
      s_valid_q  <= 1'b0;
      m_valid_q  <= 1'b0;
      x_valid_q  <= '0;
    end else begin
      state_q    <= state_d;
      in_ready_q <= in_ready_d;
      i_valid_q  <= i_valid_d;
      s_valid_q  <= s_valid_d;
      m_valid_q  <= pick_valid;
      x_valid_q  <= {x_valid_q[Last-1:1], issue};
    end
  end

  always_ff @(posedge clk_i) begin
    i_addr_q <= i_addr_d;
    i_z_q    <= i_z_d;
    i_rgba_q <= i_rgba_d;
    i_cov_q  <= i_cov_d;
    s_addr_q <= s_addr_d;
    s_z_q    <= s_z_d;
    s_rgba_q <= s_rgba_d;
    s_cov_q  <= s_cov_d;
    m_addr_q <= pick_addr;
    {m_a3_q, m_cov_q, m_rgba_q, m_z_q} <= pick_data;

    x_addr_q <= {x_addr_q[(Last-1)*AddrW-1:0], m_addr_q};
    x_rgba_q <= {x_rgba_q[5*32-1:0], m_rgba_q};
    x_a3_q   <= {x_a3_q[5*10-1:0], m_a3_q};

    // X1 -> X2: read data; 3 s
    x1_z_q    <= m_z_q;
    x1_cov_q  <= m_cov_q;
    x2_z_q    <= x1_z_q;
    x2_cov_q  <= x1_cov_q;
    x2_zs_q   <= x1_zs;
    x2_peel_q <= pmem_rdata;
    x2_cs_q   <= x1_cs;
    for (int unsigned c = 0; c < 4; c++) begin
      x2_s3_q[10*c +: 10] <= {2'b00, x1_rgba[8*c +: 8]} + {1'b0, x1_rgba[8*c +: 8], 1'b0};
    end
    // X2 -> X3: compares
    x3_z_q      <= x2_z_q;
    x3_cov_q    <= x2_cov_q;
    x3_cs_q     <= x2_cs_q;
    x3_s3_q     <= x2_s3_q;
    x3_lt_q     <= x2_z_q < x2_zs_q;
    x3_eq_q     <= x2_z_q == x2_zs_q;
    x3_behind_q <= x2_z_q > x2_peel_q;
    // X3 -> X4: decisions
    x4_z_q       <= x3_z_q;
    x4_s3_q      <= x3_s3_q;
    x4_pass_q    <= x3_pass;
    x4_dwe_q     <= x3_dwe;
    x4_weight_q  <= x3_weight;
    x4_cov_new_q <= x3_cov_new;
    // X4 -> X5: coverage k = N - w and the w s terms
    x5_kc_q  <= 8'(x4_kc);
    x5_wsa_q <= x4_wsa;
    x5_wsb_q <= x4_wsb;
    // X5 -> X6: 3 k, q = w s + N/2, 3 m(s, a), 3 (255 - a)
    x6_kc_q  <= x5_kc_q;
    x6_kc3_q <= {2'b00, x5_kc_q} + {1'b0, x5_kc_q, 1'b0};
    for (int unsigned c = 0; c < 4; c++) begin
      x6_q_q[QW*c +: QW]    <= QW'(x5_wsa_q[12*c +: 12]) + QW'(x5_wsb_q[12*c +: 12]) + Half;
      x6_ms3_q[10*c +: 10]  <= {2'b00, x5_ms[8*c +: 8]} + {1'b0, x5_ms[8*c +: 8], 1'b0};
    end
    x6_ms_q  <= x5_ms;
    x6_ia3_q <= 10'd765 - x_a3_q[4*10 +: 10];
    // X6 -> X7: zb_blend's operands
    x7_k_q   <= x6_k;
    x7_k3_q  <= x6_k3;
    x7_add_q <= x6_add;
    x7_q_q   <= x6_q_q;

    dfwd_hit_q  <= x4_dwe & (m_addr_q == x4_addr);
    dfwd_z_q    <= x4_z_q;
    vfwd_hit_q  <= x4_vwe & (m_addr_q == x4_addr);
    vfwd_cov_q  <= x4_cov_new_q;
    x7_mem_q     <= cmem_rdata;
    fwd6_hit_q   <= fwd5_hit;
    fwd6_color_q <= x11_color;
    fwd_hit_q    <= fwd6_hit | fwd6_hit_q;
    fwd_color_q  <= fwd6_hit ? x11_color : fwd6_color_q;
    byp_hit_q    <= x_valid_q[6] & x10_cwe & (x6_addr == x10_addr);

    x_pass_q[4] <= x3_pass;
    for (int unsigned k = 5; k <= Last; k++) begin
      x_pass_q[k] <= x_pass_q[k-1];
    end
  end

  // ---------------------------------------------------------------------------------------
  // Counters (docs/datapath.md "Counters"); fragment events are counted in X4.
  // ---------------------------------------------------------------------------------------
  localparam int unsigned NumCnt = 9;

  logic                    x4_valid, x4_color_on, reads_dest;
  logic [NumCnt-1:0]       cnt_inc;
  logic [NumCnt*CNT_W-1:0] cnt_all;

  assign x4_valid    = x_valid_q[4];
  assign x4_color_on = x4_valid & x4_pass_q & (st_color_mask != 4'h0);
  // Replace with all four channels written needs no destination colour; the other modes
  // (alpha, additive, coverage, under) blend with it.
  assign reads_dest  = (st_blend != zb_pkg::BlendReplace) | (st_color_mask != 4'hf);

  always_comb begin
    cnt_inc    = '0;
    cnt_inc[0] = x4_valid;                              // fragments_in
    cnt_inc[1] = x4_valid & x4_pass_q;                  // fragments_passed
    cnt_inc[2] = x4_valid & ~x4_pass_q;                 // fragments_killed
    cnt_inc[3] = x4_valid & (st_depth_test | st_cov);   // depth_reads
    cnt_inc[4] = x4_dwe;                                // depth_writes
    cnt_inc[5] = x4_color_on & reads_dest;              // color_reads
    cnt_inc[6] = x4_color_on;                           // color_writes
    cnt_inc[7] = frag_valid_i & ~frag_ready_o;          // stall cycles
    cnt_inc[8] = 1'b1;                                  // cycles
  end

  zb_counters #(
    .NUM  (NumCnt),
    .CNT_W(CNT_W)
  ) u_counters (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .clear_i(cnt_clear_i),
    .inc_i  (cnt_inc),
    .cnt_o  (cnt_all)
  );

  assign cnt_frag_in_o      = cnt_all[0*CNT_W +: CNT_W];
  assign cnt_frag_passed_o  = cnt_all[1*CNT_W +: CNT_W];
  assign cnt_frag_killed_o  = cnt_all[2*CNT_W +: CNT_W];
  assign cnt_depth_reads_o  = cnt_all[3*CNT_W +: CNT_W];
  assign cnt_depth_writes_o = cnt_all[4*CNT_W +: CNT_W];
  assign cnt_color_reads_o  = cnt_all[5*CNT_W +: CNT_W];
  assign cnt_color_writes_o = cnt_all[6*CNT_W +: CNT_W];
  assign cnt_stall_cycles_o = cnt_all[7*CNT_W +: CNT_W];
  assign cnt_cycles_o       = cnt_all[8*CNT_W +: CNT_W];

  // Tile beats: a tile's run (cleared at its setup) loads and reads each beat at most once, so
  // BeatAW + 1 bits hold them (the counters saturate beyond).
  localparam int unsigned TileCntW = BeatAW + 1;
  logic [2*TileCntW-1:0] tile_cnt;
  zb_counters #(
    .NUM  (2),
    .CNT_W(TileCntW)
  ) u_tile_counters (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .clear_i(cnt_clear_i),
    .inc_i  ({tile_req_i & ~tile_we_i, tile_req_i & tile_we_i}),
    .cnt_o  (tile_cnt)
  );
  assign cnt_tile_loads_o  = CNT_W'(tile_cnt[0 +: TileCntW]);
  assign cnt_tile_stores_o = CNT_W'(tile_cnt[TileCntW +: TileCntW]);

  // ---------------------------------------------------------------------------------------
  // Assertions
  // ---------------------------------------------------------------------------------------
`ifndef SYNTHESIS
  // The tile port is used only while no fragment is in flight (its address and write would
  // collide with the pipeline's).
  TilePortIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_req_i || tile_clear_i) |-> !busy_o);
  // The pass state is written only while idle (a write in the cycle of an accept applies to
  // that fragment).
  StateWriteIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> !busy_o);

  // The interlock's invariants, stated on the pipeline rather than on hit_q: no fragment reads
  // a plane while an older fragment to its pixel has a write to that plane still to come,
  // beyond the ones forwarded or bypassed (depth at the read edge, X4; colour at the read edge,
  // X11, and at the next one, X10).
  logic depth_older, color_older;
  always_comb begin
    depth_older = 1'b0;
    for (int unsigned k = 1; k < 4; k++) begin
      depth_older |= x_valid_q[k] && x_addr_q[(k-1)*AddrW +: AddrW] == m_addr_q;
    end
    color_older = 1'b0;
    for (int unsigned k = 6; k < Last - 2; k++) begin
      color_older |= x_valid_q[k] && x_addr_q[(k-1)*AddrW +: AddrW] == x5_addr;
    end
  end
  DepthReadAfterWrite: assert property (@(posedge clk_i) disable iff (!rst_ni)
      issue |-> !depth_older);
  ColorReadAfterWrite: assert property (@(posedge clk_i) disable iff (!rst_ni)
      x_valid_q[5] |-> !color_older);
  // A read that meets a write of its pixel at one edge is forwarded; a colour read one edge
  // before the write, bypassed.
  DepthForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (issue && x4_dwe && m_addr_q == x4_addr) |=> dfwd_hit_q);
  CovForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (issue && x4_vwe && m_addr_q == x4_addr) |=> vfwd_hit_q);
  ColorForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit |=> fwd_hit_q);
  ColorReadEdgeForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd5_hit |=> fwd6_hit_q);
  ColorForwardHeld: assert property (@(posedge clk_i) disable iff (!rst_ni)
      fwd6_hit_q |=> fwd_hit_q);
  ColorBypassCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_q[6] && x10_cwe && x6_addr == x10_addr) |=> (byp_hit_q && x11_cwe));
  // Every path a read can take to its pixel's newest word is reached (`make coverage` lists
  // them, with the window's reorder and full covers, and fails on one never reached).
  DepthForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      issue && x4_dwe && m_addr_q == x4_addr);
  CovForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      issue && x4_vwe && m_addr_q == x4_addr);
  ColorForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd6_hit);
  ColorReadEdgeForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni) fwd5_hit);
  ColorBypassPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x_valid_q[6] && x10_cwe && x6_addr == x10_addr);
  // The skid register takes a fragment (I held by a full window).
  SkidTaken: cover property (@(posedge clk_i) disable iff (!rst_ni) accept && !i_free);
  // frag_ready_o's flop is "S empty": it never drops for another reason.
  ReadyIsSkidEmpty: assert property (@(posedge clk_i) disable iff (!rst_ni)
      in_ready_q == !s_valid_q);

  // The coverage plane holds counts 0..N: a coverage-mode fragment never reads more.
  StoredCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_q[2] && st_cov) |-> (x2_cs_q <= CovW'(COV_SAMPLES)));
  // Coverage mode: the depth never moves farther, and the pixel's coverage never shrinks.
  CovDepthNeverFarther: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_q[3] && st_cov && x3_dwe) |-> x3_lt_q);
  CovNeverShrinks: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_q[3] && st_cov) |-> (x3_cov_new >= x3_cs_q));
  // A fragment that passes with the peel test on lies strictly behind the peel plane.
  PeelPassBehind: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_q[3] && x3_pass && st_peel_test && !st_cov) |-> x3_behind_q);
  // Only the five blend codes are loaded.
  BlendCodeValid: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> (state_i.blend <= zb_pkg::BlendUnder));
`endif

endmodule
