// zb_rop: the per-pixel datapath (raster operations unit) of docs/datapath.md, top level.
//
// Pipelined for 100 MHz in iCE40 fabric, one fragment per clock; docs/rtl.md has the diagram.
// Each stage is a module of its own file:
//   I/S      zb_input: input register and skid register (frag_ready_o comes from a flop)
//   W        zb_issue_window: picks the oldest fragment whose pixel is free, so a fragment
//            that waits for its pixel does not hold back fragments to other pixels
//   M        here: issue, the depth, coverage and peel reads
//   X1..X4   zb_depth: depth, coverage, peel: data, compare, decide, write (edge E4)
//   X1..X6   zb_operands: fragment side of the blend: m(s, a), k, 3k, coverage weight terms
//   M..X8    zb_weight: fragment side of the accumulate blend: depth weight, w, the terms
//   X5..X11  zb_color: colour read at edge E5, blend (zb_blend, 4 stages), write at edge E11
//   X5..X11  zb_accum: the accumulation word, read and written as the colour (accumulate mode)
//   X5..X11  zb_layers: mlab-K's layers, read and written as the colour (layers mode; LAYERS)
// This module holds the pass state, M, the pipeline's valid, address and pass bits (arrays
// indexed by stage), the counters and the assertions that span stages.
// A fragment issues at least Span = 4 cycles after an older one to its pixel, so every read
// sees every older write: from the memory; at and just after the edge of the older fragment's
// write, from the forwarding registers that hold it (the RAMs need no read-during-write
// behaviour); or, a colour (or accumulation) write two edges after the read, from that write's
// data itself, bypassed into the younger fragment's X7.
// Reset: rst_ni, asynchronous, active low, on control state only (valid bits, window, pass
// state, counters). Memories and data registers are not reset.
module zb_rop
#(
  parameter int DEPTH_BITS = 24,   // 8..32
  parameter int TILE_W     = 64,   // power of two
  parameter int TILE_H     = 64,   // power of two
  parameter int CNT_W      = 32,
  parameter int COV_SAMPLES = 16,  // N of the sample pattern: 1, 2, 4, 8 or 16
  parameter int WINDOW     = 8,    // issue window slots, 2..16
  parameter int BEAT       = 8,    // tile port pixels per clock: 1..TILE_W, power of two
  parameter int ACC_BITS   = 16,   // accumulation channel, 8..32
  parameter int REV_BITS   = 8,    // revealage, 8..16
  parameter int WEIGHT_BITS = 4,   // depth weight's range, 0..16
  parameter bit TILE_OPS   = 1'b1, // the tile operations: copy, the resolves (docs/rtl.md)
  parameter int DEPTH_GEN  = 2,    // TILE_OPS: generation bits of the renamed depth banks
  parameter int LAYERS     = 0,    // mlab-K's layers a pixel, 1..8 (TILE_OPS); 0: no layers unit
  localparam int AddrW     = $clog2(TILE_W * TILE_H),
  localparam int BeatAW    = $clog2(TILE_W * TILE_H / BEAT),
  localparam int CovW      = $clog2(COV_SAMPLES + 1),  // coverage count 0..N
  localparam int AccW      = 4 * ACC_BITS + REV_BITS,  // {r, acc_A, acc_B, acc_G, acc_R}
  localparam int LayW      = LAYERS > 0 ? LAYERS * (DEPTH_BITS + 32) : 1  // a pixel's layers
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  state_we_i,
  input  zb_pkg::pass_state_t   state_i,
  input  logic [2:0]            state_layers_i,  // the pass state's K - 1 (layers mode; LAYERS)
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
  // planes of tile_planes_i to lane 0 of the write data: no beat moves. With a read,
  // tile_copy_i also loads the depth beat read into the peel plane at the next edge, and
  // tile_resolve_i shows the colour beat resolved under lane 0 of tile_wcolor_i (TILE_OPS).
  // With a read, tile_wboit_i shows the colour beat resolved from the accumulation beat read
  // with it (docs/datapath.md "Resolve (frame operation 4)"; TILE_OPS).
  // With a read, tile_mlab_i shows the colour beat with the layers read with it composited over
  // it (docs/datapath.md "8. Layers"; LAYERS); with a fast clear, it empties the layers plane
  // too: their only port operations (the layers never cross the port).
  // With a fast clear of depth (not of peel), tile_copy_i makes the depth plane the peel plane
  // and clears the other bank as depth: a copy and a clear, renamed (TILE_OPS).
  input  logic                       tile_req_i,
  input  logic                       tile_we_i,
  input  logic                       tile_clear_i,
  input  logic                       tile_copy_i,
  input  logic                       tile_resolve_i,
  input  logic                       tile_wboit_i,
  input  logic                       tile_mlab_i,
  input  zb_pkg::planes_t            tile_planes_i,
  input  logic [BeatAW-1:0]          tile_addr_i,
  input  logic [BEAT*32-1:0]         tile_wcolor_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wdepth_i,
  input  logic [BEAT*CovW-1:0]       tile_wcov_i,
  input  logic [BEAT*DEPTH_BITS-1:0] tile_wpeel_i,
  input  logic [BEAT*AccW-1:0]       tile_wacc_i,
  output logic [BEAT*32-1:0]         tile_rcolor_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rdepth_o,
  output logic [BEAT*CovW-1:0]       tile_rcov_o,
  output logic [BEAT*DEPTH_BITS-1:0] tile_rpeel_o,
  output logic [BEAT*AccW-1:0]       tile_racc_o,
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
  output logic [CNT_W-1:0]      cnt_tile_stores_o,   // beats read
  // Retire port (docs/testbench.md "A mismatch"), for a testbench's monitor: the plane writes
  // as the planes take them at this cycle's edge. X4 writes depth and coverage, X11 colour or
  // (accumulate mode) the accumulation word; a fragment's stage is valid whether or not it
  // writes. Taps only: no logic of its own.
  output logic                  mon_x4_valid_o,
  output logic [AddrW-1:0]      mon_x4_addr_o,
  output logic                  mon_dwe_o,
  output logic [DEPTH_BITS-1:0] mon_wdepth_o,
  output logic                  mon_vwe_o,
  output logic [CovW-1:0]       mon_wcov_o,
  output logic                  mon_x11_valid_o,
  output logic [AddrW-1:0]      mon_x11_addr_o,
  output logic                  mon_cwe_o,
  output logic [31:0]           mon_wcolor_o,
  output logic                  mon_awe_o,
  output logic [AccW-1:0]       mon_wacc_o,
  output logic                  mon_lwe_o,      // layers mode: the layers word written at X11
  output logic [LayW-1:0]       mon_wlayers_o
);

  localparam int XW    = $clog2(TILE_W);
  localparam int YW    = $clog2(TILE_H);
  localparam int Words = TILE_W * TILE_H;
  localparam int QW    = 8 + CovW;  // coverage blend addend w*s + N/2 (zb_blend)

`ifndef SYNTHESIS
  if (TILE_W < 2 || TILE_W != (1 << XW) || TILE_H < 2 || TILE_H != (1 << YW)) begin : g_bad_tile
    `ZB_PARAM_ERROR("zb_rop: TILE_W and TILE_H must be powers of two, at least 2");
  end
  if (DEPTH_BITS < 8 || DEPTH_BITS > 32) begin : g_bad_depth
    `ZB_PARAM_ERROR("zb_rop: DEPTH_BITS must be 8..32");
  end
  if (COV_SAMPLES < 1 || COV_SAMPLES > 16 || (COV_SAMPLES & (COV_SAMPLES - 1)) != 0)
  begin : g_bad_cov
    `ZB_PARAM_ERROR("zb_rop: COV_SAMPLES must be 1, 2, 4, 8 or 16");
  end
  if (BEAT < 1 || BEAT > TILE_W || (BEAT & (BEAT - 1)) != 0) begin : g_bad_beat
    `ZB_PARAM_ERROR("zb_rop: BEAT must be a power of two, 1..TILE_W");
  end
  if (ACC_BITS < 8 || ACC_BITS > 32) begin : g_bad_acc
    `ZB_PARAM_ERROR("zb_rop: ACC_BITS must be 8..32");
  end
  if (REV_BITS < 8 || REV_BITS > 16) begin : g_bad_rev
    `ZB_PARAM_ERROR("zb_rop: REV_BITS must be 8..16");
  end
  if (WEIGHT_BITS < 0 || WEIGHT_BITS > 16) begin : g_bad_weight
    `ZB_PARAM_ERROR("zb_rop: WEIGHT_BITS must be 0..16");
  end
  if (LAYERS < 0 || LAYERS > 8 || (LAYERS > 0 && !TILE_OPS)) begin : g_bad_layers
    `ZB_PARAM_ERROR("zb_rop: LAYERS must be 0..8, and 0 without TILE_OPS");
  end
`endif

  // ---------------------------------------------------------------------------------------
  // Pass state register (docs/datapath.md "The pass state"); loaded only while idle.
  // ---------------------------------------------------------------------------------------
  zb_pkg::pass_state_t state_q;
  logic                st_cov;  // coverage mode (docs/datapath.md "Coverage blend")
  logic                st_acc;  // accumulate mode (docs/datapath.md "Accumulate blend")
  logic                st_lay;  // layers mode (docs/datapath.md "8. Layers")
  assign st_cov = state_q.blend == zb_pkg::BlendCoverage;
  assign st_acc = state_q.blend == zb_pkg::BlendAccumulate;
  assign st_lay = LAYERS > 0 && state_q.blend == zb_pkg::BlendLayers;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= '0;
    end else if (state_we_i) begin
      state_q <= state_i;
    end
  end

  // A younger fragment to the same pixel issues at least Span cycles after the older one. At
  // Span its depth and coverage reads meet the older one's writes (E4) and take the written
  // words from the forwarding registers. Its colour read (E5) comes before the older colour
  // write: at Span that write is at the younger's E7, so X7 takes the older one's write data
  // (bypass); at Span + 1 at E6, and at Span + 2 at the read edge E5: X6 catches either in
  // zb_color's forwarding registers (zb_accum's alike). Below 4 the older result would not
  // exist yet when the younger's X7 needs it.
  localparam int Span = 4;
  localparam int Last = 11;   // the colour write's stage

  // ---------------------------------------------------------------------------------------
  // I/S: the input stage (zb_input).
  // ---------------------------------------------------------------------------------------
  logic                  i_valid, i_busy, w_ready;
  logic [AddrW-1:0]      i_addr;
  logic [9:0]            i_a3;
  logic [DEPTH_BITS-1:0] i_z;
  logic [31:0]           i_rgba;
  logic [CovW-1:0]       i_cov;

  zb_input #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .COV_SAMPLES(COV_SAMPLES)
  ) u_input (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .frag_valid_i(frag_valid_i),
    .frag_ready_o(frag_ready_o),
    .frag_x_i    (frag_x_i),
    .frag_y_i    (frag_y_i),
    .frag_z_i    (frag_z_i),
    .frag_rgba_i (frag_rgba_i),
    .frag_cov_i  (frag_cov_i),
    .tile_x0_i   (tile_x0_i),
    .tile_y0_i   (tile_y0_i),
    .hold_i      (stall_i | tile_req_i | tile_clear_i),
    .take_i      (w_ready),
    .i_valid_o   (i_valid),
    .i_addr_o    (i_addr),
    .i_a3_o      (i_a3),
    .i_z_o       (i_z),
    .i_rgba_o    (i_rgba),
    .i_cov_o     (i_cov),
    .busy_o      (i_busy)
  );

  // ---------------------------------------------------------------------------------------
  // W: the issue window (zb_issue_window). It picks the oldest fragment whose pixel is free
  // (no older fragment in the window has it, and none issued less than Span cycles before this
  // one would issue); M takes the pick and issues it: the depth, coverage and peel reads.
  // ---------------------------------------------------------------------------------------
  localparam int WinDataW = 10 + CovW + 32 + DEPTH_BITS;  // {3 a, cov, rgba, z}

  logic                  m_valid_q;
  logic [AddrW-1:0]      m_addr_q;
  logic [DEPTH_BITS-1:0] m_z_q;
  logic [31:0]           m_rgba_q;
  logic [CovW-1:0]       m_cov_q;
  logic [9:0]            m_a3_q;      // 3 a for the premultiply (zb_premul)
  logic                  w_busy, pick_valid;
  logic [AddrW-1:0]      pick_addr;
  logic [WinDataW-1:0]   pick_data;

  // The pipeline after M: a valid bit, an address and (from X4) a pass bit per stage Xk.
  logic [Last:1]         x_valid_q;
  logic [AddrW-1:0]      x_addr_q [1:Last];
  logic [Last:4]         x_pass_q;

  // The window's view of the pipeline after it: P1 = M, P(k+1) = Xk.
  logic [Span-3:0]           pos_valid;
  logic [(Span-2)*AddrW-1:0] pos_addr;
  assign pos_valid = {x_valid_q[Span-3:1], m_valid_q};
  assign pos_addr[0 +: AddrW] = m_addr_q;
  for (genvar k = 1; k <= Span - 3; k++) begin : g_pos
    assign pos_addr[k*AddrW +: AddrW] = x_addr_q[k];
  end

  zb_issue_window #(
    .WINDOW(WINDOW),
    .ADDR_W(AddrW),
    .DATA_W(WinDataW),
    .SPAN  (Span)
  ) u_window (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .in_valid_i  (i_valid),
    .in_ready_o  (w_ready),
    .in_addr_i   (i_addr),
    .in_data_i   ({i_a3, i_cov, i_rgba, i_z}),
    .pos_valid_i (pos_valid),
    .pos_addr_i  (pos_addr),
    .pick_valid_o(pick_valid),
    .pick_addr_o (pick_addr),
    .pick_data_o (pick_data),
    .busy_o      (w_busy)
  );

  // M and the pipeline's bits.
  logic x3_pass;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      m_valid_q <= 1'b0;
      x_valid_q <= '0;
    end else begin
      m_valid_q <= pick_valid;
      x_valid_q <= {x_valid_q[Last-1:1], m_valid_q};
    end
  end

  always_ff @(posedge clk_i) begin
    m_addr_q <= pick_addr;
    {m_a3_q, m_cov_q, m_rgba_q, m_z_q} <= pick_data;
    x_addr_q[1] <= m_addr_q;
    for (int unsigned k = 2; k <= Last; k++) begin
      x_addr_q[k] <= x_addr_q[k-1];
    end
    x_pass_q[4] <= x3_pass;
    for (int unsigned k = 5; k <= Last; k++) begin
      x_pass_q[k] <= x_pass_q[k-1];
    end
  end

  // ---------------------------------------------------------------------------------------
  // X1..X4: depth, coverage and peel (zb_depth).
  // ---------------------------------------------------------------------------------------
  logic            x4_dwe;
  logic [CovW-1:0] x4_weight;

  zb_depth #(
    .DEPTH_BITS (DEPTH_BITS),
    .WORDS      (Words),
    .BEAT       (BEAT),
    .COV_SAMPLES(COV_SAMPLES),
    .RENAME     (TILE_OPS),
    .DEPTH_GEN  (DEPTH_GEN)
  ) u_depth (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni),
    .depth_test_i (state_q.depth_test),
    .depth_func_i (state_q.depth_func),
    .depth_write_i(state_q.depth_write),
    .peel_test_i  (state_q.peel_test),
    .cov_mode_i   (st_cov),
    .tile_req_i   (tile_req_i),
    .tile_we_i    (tile_we_i),
    .tile_clear_i (tile_clear_i),
    .tile_copy_i  (TILE_OPS ? tile_copy_i : 1'b0),
    .tile_planes_i(tile_planes_i),
    .tile_addr_i  (tile_addr_i),
    .tile_wdepth_i(tile_wdepth_i),
    .tile_wcov_i  (tile_wcov_i),
    .tile_wpeel_i (tile_wpeel_i),
    .tile_rdepth_o(tile_rdepth_o),
    .tile_rcov_o  (tile_rcov_o),
    .tile_rpeel_o (tile_rpeel_o),
    .issue_i      (m_valid_q),
    .m_addr_i     (m_addr_q),
    .m_z_i        (m_z_q),
    .m_cov_i      (m_cov_q),
    .x_valid_i    (x_valid_q[4:2]),
    .x4_addr_i    (x_addr_q[4]),
    .x3_pass_o    (x3_pass),
    .x4_dwe_o     (x4_dwe),
    .x4_weight_o  (x4_weight),
    .x4_wdepth_o  (mon_wdepth_o),
    .x4_vwe_o     (mon_vwe_o),
    .x4_wcov_o    (mon_wcov_o)
  );

  // ---------------------------------------------------------------------------------------
  // X1..X6: the fragment side of the blend (zb_operands).
  // ---------------------------------------------------------------------------------------
  logic [31:0]        x7_k, x7_add;
  logic [39:0]        x7_k3;
  logic [4*QW-1:0]    x7_q;

  logic [31:0]        x5_p;

  zb_operands #(
    .COV_SAMPLES(COV_SAMPLES)
  ) u_operands (
    .clk_i      (clk_i),
    .blend_i    (state_q.blend),
    .m_rgba_i   (m_rgba_q),
    .m_a3_i     (m_a3_q),
    .x4_weight_i(x4_weight),
    .x7_k_o     (x7_k),
    .x7_k3_o    (x7_k3),
    .x7_add_o   (x7_add),
    .x7_q_o     (x7_q),
    .x5_p_o     (x5_p)
  );

  // ---------------------------------------------------------------------------------------
  // M..X8: the fragment side of the accumulate blend (zb_weight); its products p_c * w on
  // zb_blend's multipliers (X6, X7), idle in accumulate mode.
  // ---------------------------------------------------------------------------------------
  localparam int WgtW = 8 + (WEIGHT_BITS > 0 ? WEIGHT_BITS : 1);  // w = a * F
  logic [WgtW-1:0]      x5_w;
  logic [WgtW+1:0]      x5_w3;
  logic [4*(WgtW+8)-1:0] x8_prod;
  logic [8:0]           x8_t;
  logic [10:0]          x8_t3;

  zb_weight #(
    .WEIGHT_BITS(WEIGHT_BITS)
  ) u_weight (
    .clk_i    (clk_i),
    .m_zhi_i  (m_z_q[DEPTH_BITS-1 -: 8]),
    .m_a_i    (m_rgba_q[31:24]),
    .m_a3_i   (m_a3_q),
    .x5_w_o   (x5_w),
    .x5_w3_o  (x5_w3),
    .x8_t_o   (x8_t),
    .x8_t3_o  (x8_t3)
  );

  // ---------------------------------------------------------------------------------------
  // X5..X11: colour (zb_color), and the resolves on the store's way out: a read with
  // tile_resolve_i puts the beat under the background its cycle's lane 0 carries (zb_resolve),
  // one with tile_wboit_i makes it from the accumulation beat (zb_resolve_wboit).
  // ---------------------------------------------------------------------------------------
  logic [BEAT*32-1:0]   color_lanes;
  logic [BEAT*LayW-1:0] layers_lanes;  // the layers plane's beat, for the resolve
  if (TILE_OPS) begin : g_resolve
    logic               resolve_q, wboit_q;
    logic [31:0]        bg_q;
    logic [BEAT*32-1:0] color_under, color_wboit;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        resolve_q <= 1'b0;
        wboit_q   <= 1'b0;
      end else begin
        resolve_q <= tile_req_i & ~tile_we_i & tile_resolve_i;
        wboit_q   <= tile_req_i & ~tile_we_i & tile_wboit_i;
      end
    end
    always_ff @(posedge clk_i) begin
      bg_q <= tile_wcolor_i[31:0];
    end
    zb_resolve #(
      .BEAT(BEAT)
    ) u_resolve (
      .en_i   (resolve_q),
      .bg_i   (bg_q),
      .color_i(color_lanes),
      .color_o(color_under)
    );
    zb_resolve_wboit #(
      .BEAT    (BEAT),
      .ACC_BITS(ACC_BITS),
      .REV_BITS(REV_BITS)
    ) u_resolve_wboit (
      .en_i   (wboit_q),
      .color_i(color_under),
      .acc_i  (tile_racc_o),
      .color_o(color_wboit)
    );
    if (LAYERS > 0) begin : g_mlab
      logic mlab_q;
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          mlab_q <= 1'b0;
        end else begin
          mlab_q <= tile_req_i & ~tile_we_i & tile_mlab_i;
        end
      end
      zb_resolve_layers #(
        .BEAT      (BEAT),
        .DEPTH_BITS(DEPTH_BITS),
        .LAYERS    (LAYERS)
      ) u_resolve_layers (
        .en_i    (mlab_q),
        .color_i (color_wboit),
        .layers_i(layers_lanes),
        .color_o (tile_rcolor_o)
      );
    end else begin : g_no_mlab
      assign tile_rcolor_o = color_wboit;
      logic unused_mlab;
      assign unused_mlab = ^{tile_mlab_i, layers_lanes};
    end
  end else begin : g_no_resolve
    assign tile_rcolor_o = color_lanes;
    logic unused_ops;
    assign unused_ops = ^{tile_copy_i, tile_resolve_i, tile_wboit_i, tile_mlab_i, layers_lanes};
  end

  zb_color #(
    .LAYERS_ON  (LAYERS > 0),
    .WORDS      (Words),
    .BEAT       (BEAT),
    .COV_SAMPLES(COV_SAMPLES),
    .K_W        (WgtW)
  ) u_color (
    .clk_i        (clk_i),
    .rst_ni       (rst_ni),
    .blend_i      (state_q.blend),
    .color_mask_i (state_q.color_mask),
    .tile_req_i   (tile_req_i),
    .tile_we_i    (tile_we_i),
    .tile_clear_i (tile_clear_i),
    .tile_en_i    (tile_planes_i.color),
    .tile_addr_i  (tile_addr_i),
    .tile_wcolor_i(tile_wcolor_i),
    .tile_rcolor_o(color_lanes),
    .x5_valid_i   (x_valid_q[5]),
    .x6_valid_i   (x_valid_q[6]),
    .x10_valid_i  (x_valid_q[10]),
    .x11_valid_i  (x_valid_q[11]),
    .x5_addr_i    (x_addr_q[5]),
    .x6_addr_i    (x_addr_q[6]),
    .x10_addr_i   (x_addr_q[10]),
    .x11_addr_i   (x_addr_q[11]),
    .x10_pass_i   (x_pass_q[10]),
    .x11_pass_i   (x_pass_q[11]),
    .x7_k_i       (x7_k),
    .x7_k3_i      (x7_k3),
    .x7_add_i     (x7_add),
    .x7_q_i       (x7_q),
    .x5_w_i       (x5_w),
    .x5_w3_i      (x5_w3),
    .x5_p_i       (x5_p),
    .x8_prod_o    (x8_prod),
    .x11_cwe_o    (mon_cwe_o),
    .x11_wcolor_o (mon_wcolor_o)
  );

  // ---------------------------------------------------------------------------------------
  // X5..X11: the accumulation word (zb_accum).
  // ---------------------------------------------------------------------------------------
  zb_accum #(
    .WORDS   (Words),
    .BEAT    (BEAT),
    .ACC_BITS(ACC_BITS),
    .REV_BITS(REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS)
  ) u_accum (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .acc_mode_i  (st_acc),
    .color_mask_i(state_q.color_mask),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_clear_i(tile_clear_i),
    .tile_en_i   (tile_planes_i.accum),
    .tile_addr_i (tile_addr_i),
    .tile_wacc_i (tile_wacc_i),
    .tile_racc_o (tile_racc_o),
    .x5_valid_i  (x_valid_q[5]),
    .x6_valid_i  (x_valid_q[6]),
    .x10_valid_i (x_valid_q[10]),
    .x11_valid_i (x_valid_q[11]),
    .x5_addr_i   (x_addr_q[5]),
    .x6_addr_i   (x_addr_q[6]),
    .x10_addr_i  (x_addr_q[10]),
    .x11_addr_i  (x_addr_q[11]),
    .x10_pass_i  (x_pass_q[10]),
    .x11_pass_i  (x_pass_q[11]),
    .x8_prod_i   (x8_prod),
    .x8_t_i      (x8_t),
    .x8_t3_i     (x8_t3),
    .x11_awe_o   (mon_awe_o),
    .x11_wacc_o  (mon_wacc_o)
  );

  // ---------------------------------------------------------------------------------------
  // X5..X11: mlab-K's layers (zb_layers), in the builds that have them.
  // ---------------------------------------------------------------------------------------
  if (LAYERS > 0) begin : g_layers
    logic [2:0] k_m1_q;  // the pass state's K - 1, loaded with it
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        k_m1_q <= '0;
      end else if (state_we_i) begin
        k_m1_q <= state_layers_i;
      end
    end
    zb_layers #(
      .WORDS     (Words),
      .BEAT      (BEAT),
      .DEPTH_BITS(DEPTH_BITS),
      .LAYERS    (LAYERS)
    ) u_layers (
      .clk_i         (clk_i),
      .rst_ni        (rst_ni),
      .layers_mode_i (st_lay),
      .color_mask_i  (state_q.color_mask),
      .k_m1_i        (k_m1_q),
      .tile_req_i    (tile_req_i),
      .tile_we_i     (tile_we_i),
      .tile_clear_i  (tile_clear_i),
      .tile_en_i     (tile_mlab_i),
      .tile_addr_i   (tile_addr_i),
      .tile_rlayers_o(layers_lanes),
      .m_z_i         (m_z_q),
      .x5_valid_i    (x_valid_q[5]),
      .x6_valid_i    (x_valid_q[6]),
      .x10_valid_i   (x_valid_q[10]),
      .x11_valid_i   (x_valid_q[11]),
      .x5_addr_i     (x_addr_q[5]),
      .x6_addr_i     (x_addr_q[6]),
      .x10_addr_i    (x_addr_q[10]),
      .x11_addr_i    (x_addr_q[11]),
      .x10_pass_i    (x_pass_q[10]),
      .x11_pass_i    (x_pass_q[11]),
      .x5_p_i        (x5_p),
      .x11_lwe_o     (mon_lwe_o),
      .x11_wlayers_o (mon_wlayers_o)
    );
  end else begin : g_no_layers
    assign layers_lanes  = '0;
    assign mon_lwe_o     = 1'b0;
    assign mon_wlayers_o = '0;
    logic unused_layers;
    assign unused_layers = ^{st_lay, state_layers_i};
  end

  assign busy_o = i_busy | w_busy | m_valid_q | (|x_valid_q);

  assign mon_x4_valid_o  = x_valid_q[4];
  assign mon_dwe_o       = x4_dwe;
  assign mon_x11_valid_o = x_valid_q[Last];
`ifdef __ICARUS__
  // Icarus 11 may leave a continuous assignment from a word of an unpacked array of this module
  // at X (docs/rtl.md "Simulators"). Only there: a process would renumber Yosys's cells, which
  // tb/mutation/reasons.json names.
  always_comb begin
    mon_x4_addr_o  = x_addr_q[4];
    mon_x11_addr_o = x_addr_q[Last];
  end
`else
  assign mon_x4_addr_o   = x_addr_q[4];
  assign mon_x11_addr_o  = x_addr_q[Last];
`endif

  // ---------------------------------------------------------------------------------------
  // Counters (docs/datapath.md "Counters"); fragment events are counted in X4.
  // ---------------------------------------------------------------------------------------
  localparam int NumCnt = 9;

  logic                    x4_valid, x4_pass, x4_color_on, reads_dest;
  logic [NumCnt-1:0]       cnt_inc;
  logic [NumCnt*CNT_W-1:0] cnt_all;

  assign x4_valid    = x_valid_q[4];
  assign x4_pass     = x_pass_q[4];
  assign x4_color_on = x4_valid & x4_pass & (state_q.color_mask != 4'h0);
  // Replace with all four channels written needs no destination colour; the other modes
  // (alpha, additive, coverage, under) blend with it, and accumulate reads its own word.
  assign reads_dest  = (state_q.blend != zb_pkg::BlendReplace) | (state_q.color_mask != 4'hf);

  always_comb begin
    cnt_inc    = '0;
    cnt_inc[0] = x4_valid;                                   // fragments_in
    cnt_inc[1] = x4_valid & x4_pass;                         // fragments_passed
    cnt_inc[2] = x4_valid & ~x4_pass;                        // fragments_killed
    cnt_inc[3] = x4_valid & (state_q.depth_test | st_cov);   // depth_reads
    cnt_inc[4] = x4_dwe;                                     // depth_writes
    cnt_inc[5] = x4_color_on & reads_dest;                   // color_reads
    cnt_inc[6] = x4_color_on;                                // color_writes
    cnt_inc[7] = frag_valid_i & ~frag_ready_o;               // stall cycles
    cnt_inc[8] = 1'b1;                                       // cycles
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
  localparam int TileCntW = BeatAW + 1;
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
`ifndef ZB_NO_SVA
  // The tile port is used only while no fragment is in flight (its address and write would
  // collide with the pipeline's).
  TilePortIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_req_i || tile_clear_i) |-> !busy_o);
  // The pass state is written only while idle (a write in the cycle of an accept applies to
  // that fragment).
  StateWriteIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> !busy_o);

  // The interlock's invariants, stated on the pipeline rather than on the window's bits: no
  // fragment reads a plane while an older fragment to its pixel has a write to that plane
  // still to come, beyond the ones forwarded or bypassed (depth at the read edge, X4; colour
  // at the read edge and the next, X11 and X10 at E5, and at E7, X9 at E5).
  logic depth_older, color_older;
  always_comb begin
    depth_older = 1'b0;
    for (int unsigned k = 1; k < 4; k++) begin
      depth_older |= x_valid_q[k] && x_addr_q[k] == m_addr_q;
    end
    color_older = 1'b0;
    for (int unsigned k = 6; k < Last - 2; k++) begin
      color_older |= x_valid_q[k] && x_addr_q[k] == x_addr_q[5];
    end
  end
  DepthReadAfterWrite: assert property (@(posedge clk_i) disable iff (!rst_ni)
      m_valid_q |-> !depth_older);
  ColorReadAfterWrite: assert property (@(posedge clk_i) disable iff (!rst_ni)
      x_valid_q[5] |-> !color_older);
  // The tile operations ride on a tile read (docs/rtl.md "Tile operations"), or a renamed
  // copy on a fast clear of depth alone among the depth banks.
  TileOpOnRead: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_resolve_i || tile_wboit_i || (tile_mlab_i && !tile_clear_i) ||
       (tile_copy_i && !tile_clear_i)) |->
      (tile_req_i && !tile_we_i));
  OneResolve: assert property (@(posedge clk_i) disable iff (!rst_ni)
      $onehot0({tile_resolve_i, tile_wboit_i, tile_mlab_i}));
  // The layers never cross the port: no load with tile_mlab_i.
  LayersNotLoaded: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_req_i && tile_we_i) |-> !tile_mlab_i);
  RenameOnClear: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (tile_copy_i && tile_clear_i) |->
      (!tile_req_i && !tile_resolve_i && !tile_wboit_i && !tile_mlab_i && tile_planes_i.depth &&
       !tile_planes_i.peel));
  RenamedCopy: cover property (@(posedge clk_i) disable iff (!rst_ni) tile_copy_i && tile_clear_i);
  TileOpsPresent: assert property (@(posedge clk_i) disable iff (!rst_ni)
      !TILE_OPS |-> !(tile_copy_i || tile_resolve_i || tile_wboit_i || tile_mlab_i));
  LayersPresent: assert property (@(posedge clk_i) disable iff (!rst_ni)
      LAYERS == 0 |-> !(tile_mlab_i || (state_we_i && state_i.blend == zb_pkg::BlendLayers)));
  // Only the seven blend codes are loaded, and K within the unit's layers.
  BlendCodeValid: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> (state_i.blend <= zb_pkg::BlendLayers));
  LayersWithinUnit: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (state_we_i && state_i.blend == zb_pkg::BlendLayers) |-> (32'(state_layers_i) < LAYERS));
`endif
`endif

endmodule
