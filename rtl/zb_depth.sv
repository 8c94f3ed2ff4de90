// zb_depth: the depth, coverage and peel side of the pipeline (docs/rtl.md "Pipeline"), X1..X4.
// The planes are read at the issue edge E0 (M's address) and depth and coverage written at E4.
// A read that meets a write of its pixel at E4 takes the written word from a forwarding
// register ("Same-pixel distance"); the issue window keeps fragments to one pixel that far
// apart. X1 registers the read data, X2 compares, X3 decides (zb_depth_test,
// zb_coverage_composite), X4 writes.
module zb_depth #(
  parameter int DEPTH_BITS  = 24,
  parameter int WORDS       = 4096,
  parameter int BEAT        = 8,
  parameter int COV_SAMPLES = 16,
  parameter bit RENAME      = 1'b0,  // renamed copies (docs/rtl.md "Renamed copies")
  parameter int DEPTH_GEN   = 2      // with RENAME: the depth banks' generation bits
) (
  input  logic                                clk_i,
  input  logic                                rst_ni,
  // Pass state.
  input  logic                                depth_test_i,
  input  zb_pkg::depth_func_e                 depth_func_i,
  input  logic                                depth_write_i,
  input  logic                                peel_test_i,
  input  logic                                cov_mode_i,
  // Tile port of the three planes (zb_plane).
  input  logic                                tile_req_i,
  input  logic                                tile_we_i,
  input  logic                                tile_clear_i,
  input  logic                                tile_copy_i,  // with a read: depth to peel;
                                                                // with a clear of depth: renamed
  input  zb_pkg::planes_t                     tile_planes_i,
  input  logic [$clog2(WORDS / BEAT)-1:0]     tile_addr_i,
  input  logic [BEAT*DEPTH_BITS-1:0]          tile_wdepth_i,
  input  logic [BEAT*$clog2(COV_SAMPLES+1)-1:0] tile_wcov_i,
  input  logic [BEAT*DEPTH_BITS-1:0]          tile_wpeel_i,
  output logic [BEAT*DEPTH_BITS-1:0]          tile_rdepth_o,
  output logic [BEAT*$clog2(COV_SAMPLES+1)-1:0] tile_rcov_o,
  output logic [BEAT*DEPTH_BITS-1:0]          tile_rpeel_o,
  // M: the fragment issued at E0.
  input  logic                                issue_i,
  input  logic [$clog2(WORDS)-1:0]            m_addr_i,
  input  logic [DEPTH_BITS-1:0]               m_z_i,
  input  logic [$clog2(COV_SAMPLES+1)-1:0]    m_cov_i,
  // The pipeline's valid bits X2..X4 and X4's address.
  input  logic [4:2]                          x_valid_i,
  input  logic [$clog2(WORDS)-1:0]            x4_addr_i,
  // X4: the fragment's outcome.
  output logic                                x3_pass_o,    // into X4 at E3
  output logic                                x4_dwe_o,     // writes depth at E4
  output logic [$clog2(COV_SAMPLES+1)-1:0]    x4_weight_o,  // coverage blend weight w
  // X4's plane writes as the planes take them, for zb_rop's retire port.
  output logic [DEPTH_BITS-1:0]               x4_wdepth_o,
  output logic                                x4_vwe_o,
  output logic [$clog2(COV_SAMPLES+1)-1:0]    x4_wcov_o
);

  localparam int CovW = $clog2(COV_SAMPLES + 1);

  logic [1:0] unused_planes;  // the colour and accumulation planes: zb_color's, zb_accum's
  assign unused_planes = {tile_planes_i.accum, tile_planes_i.color};

  // ---------------------------------------------------------------------------------------
  // The planes, read at E0, written at E4. Peel: written only by the tile port.
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] dmem_rdata, pmem_rdata;
  logic [CovW-1:0]       vmem_rdata;
  logic                  x4_dwe, x4_vwe;
  logic [DEPTH_BITS-1:0] x4_z_q;
  logic [CovW-1:0]       x4_cov_new_q;

  zb_plane #(
    .WIDTH    (CovW),
    .WORDS    (WORDS),
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
    .pipe_re_i   (issue_i),
    .pipe_raddr_i(m_addr_i),
    .pipe_we_i   (x4_vwe),
    .pipe_waddr_i(x4_addr_i),
    .pipe_wdata_i(x4_cov_new_q),
    .rdata_o     (vmem_rdata)
  );

  // Copy depth to peel (docs/rtl.md "Tile operations"): a tile read with tile_copy_i loads the
  // depth beat it read, as the port shows it the next cycle (fresh words as the clear value),
  // into the peel plane at that cycle's edge.
  logic                            copy_q;
  logic [$clog2(WORDS / BEAT)-1:0] copy_addr_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      copy_q <= 1'b0;
    end else begin
      copy_q <= tile_req_i & ~tile_we_i & tile_copy_i;
    end
  end
  always_ff @(posedge clk_i) begin
    copy_addr_q <= tile_addr_i;
  end
  logic [BEAT*DEPTH_BITS-1:0] copy_data;
`ifdef ZB_INJECT_TILEOP_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_copy: the copy flips bit 0
  // of each beat's lane 0.
  logic bug_copy;
  initial bug_copy = $test$plusargs("zb_bug_copy") != 0;
  assign copy_data = tile_rdepth_o ^ (BEAT*DEPTH_BITS)'(bug_copy);
`else
  assign copy_data = tile_rdepth_o;
`endif

  if (!RENAME) begin : g_fixed
    zb_plane #(
      .WIDTH    (DEPTH_BITS),
      .WORDS    (WORDS),
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
      .pipe_re_i   (issue_i),
      .pipe_raddr_i(m_addr_i),
      .pipe_we_i   (x4_dwe),
      .pipe_waddr_i(x4_addr_i),
      .pipe_wdata_i(x4_z_q),
      .rdata_o     (dmem_rdata)
    );

    zb_plane #(
      .WIDTH    (DEPTH_BITS),
      .WORDS    (WORDS),
      .BEAT     (BEAT),
      .READ_ONLY(1'b1)
    ) u_peel_plane (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .tile_req_i  (tile_req_i | copy_q),
      .tile_we_i   (tile_we_i | copy_q),
      .tile_en_i   (tile_planes_i.peel | copy_q),
      .tile_clear_i(tile_clear_i),
      .tile_addr_i (copy_q ? copy_addr_q : tile_addr_i),
      .tile_wdata_i(copy_q ? copy_data : tile_wpeel_i),
      .tile_rdata_o(tile_rpeel_o),
      .pipe_re_i   (issue_i),
      .pipe_raddr_i(m_addr_i),
      .pipe_we_i   (1'b0),
      .pipe_waddr_i(m_addr_i),
      .pipe_wdata_i(m_z_i),
      .rdata_o     (pmem_rdata)
    );
  end else begin : g_renamed
    // Two banks of depth words; role_q names the depth plane's, the other is the peel plane.
    // tile_copy_i with a fast clear of depth trades them (a copy of depth to peel and a clear
    // of depth, with no beat moved): the new depth bank takes the clear, in the same cycle.
    // The read data follow the role of their read's cycle (rd_role_q). A copy by reads still
    // works: the peel bank then takes no part in the reads (its load follows each one).
    logic role_q, role_d, rd_role_q;
    logic [1:0] bank_depth;  // by the role after this edge (the tile port's) and before (pipeline)
    assign role_d = role_q ^ (tile_clear_i & tile_copy_i & tile_planes_i.depth);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        role_q    <= 1'b0;
        rd_role_q <= 1'b0;
      end else begin
        role_q    <= role_d;
        rd_role_q <= role_q;
      end
    end
    assign bank_depth = {role_d, ~role_d};
    logic [2*BEAT*DEPTH_BITS-1:0] bank_tile_rdata;  // bank b's at [b*BEAT*DEPTH_BITS +: ...]
    logic [2*DEPTH_BITS-1:0]      bank_rdata;
    for (genvar b = 0; b < 2; b++) begin : g_bank
      logic peel_copy;  // this bank is peel and the copy writes it this cycle
      assign peel_copy = copy_q & ~bank_depth[b];
      zb_plane #(
        .WIDTH    (DEPTH_BITS),
        .WORDS    (WORDS),
        .BEAT     (BEAT),
        .FORWARDED(1'b1),
        .GEN_BITS (DEPTH_GEN)
      ) u_plane (
        .clk_i       (clk_i),
        .rst_ni      (rst_ni),
        .tile_req_i  ((tile_req_i & (bank_depth[b] | ~tile_copy_i)) | peel_copy),
        .tile_we_i   (tile_we_i | peel_copy),
        .tile_en_i   (bank_depth[b] ? tile_planes_i.depth : (tile_planes_i.peel | copy_q)),
        .tile_clear_i(tile_clear_i),
        .tile_addr_i (peel_copy ? copy_addr_q : tile_addr_i),
        .tile_wdata_i(bank_depth[b] ? tile_wdepth_i : (copy_q ? copy_data : tile_wpeel_i)),
        .tile_rdata_o(bank_tile_rdata[b*BEAT*DEPTH_BITS +: BEAT*DEPTH_BITS]),
        .pipe_re_i   (issue_i),
        .pipe_raddr_i(m_addr_i),
        .pipe_we_i   (x4_dwe & (role_q == 1'(b))),
        .pipe_waddr_i(x4_addr_i),
        .pipe_wdata_i(x4_z_q),
        .rdata_o     (bank_rdata[b*DEPTH_BITS +: DEPTH_BITS])
      );
    end
    localparam int BeatW = BEAT * DEPTH_BITS;
    assign tile_rdepth_o = rd_role_q ? bank_tile_rdata[BeatW +: BeatW] : bank_tile_rdata[0 +: BeatW];
    assign tile_rpeel_o  = rd_role_q ? bank_tile_rdata[0 +: BeatW] : bank_tile_rdata[BeatW +: BeatW];
    assign dmem_rdata    = rd_role_q ? bank_rdata[DEPTH_BITS +: DEPTH_BITS] : bank_rdata[0 +: DEPTH_BITS];
    assign pmem_rdata    = rd_role_q ? bank_rdata[0 +: DEPTH_BITS] : bank_rdata[DEPTH_BITS +: DEPTH_BITS];
  end

  // ---------------------------------------------------------------------------------------
  // Forwarding: a fragment issued at an older one's E4 with its address reads the word that
  // edge writes; the written word replaces the RAM's in X1.
  // ---------------------------------------------------------------------------------------
  logic                  dfwd_hit_q, vfwd_hit_q;
  logic [DEPTH_BITS-1:0] dfwd_z_q, x1_zs;
  logic [CovW-1:0]       vfwd_cov_q, x1_cs;
  assign x1_zs = dfwd_hit_q ? dfwd_z_q : dmem_rdata;
  assign x1_cs = vfwd_hit_q ? vfwd_cov_q : vmem_rdata;

  always_ff @(posedge clk_i) begin
    dfwd_hit_q <= x4_dwe & (m_addr_i == x4_addr_i);
    dfwd_z_q   <= x4_z_q;
    vfwd_hit_q <= x4_vwe & (m_addr_i == x4_addr_i);
    vfwd_cov_q <= x4_cov_new_q;
  end

  // ---------------------------------------------------------------------------------------
  // X1: read data arrives, registered with at most the forwarding mux (the RAM's clock-to-out
  // is long on iCE40).
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] x1_z_q, x2_z_q, x2_zs_q, x2_peel_q;
  logic [CovW-1:0]       x1_cov_q, x2_cov_q, x2_cs_q;

  always_ff @(posedge clk_i) begin
    x1_z_q    <= m_z_i;
    x1_cov_q  <= m_cov_i;
    x2_z_q    <= x1_z_q;
    x2_cov_q  <= x1_cov_q;
    x2_zs_q   <= x1_zs;
    x2_peel_q <= pmem_rdata;
    x2_cs_q   <= x1_cs;
  end

  // ---------------------------------------------------------------------------------------
  // X2: compares.
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] x3_z_q;
  logic [CovW-1:0]       x3_cov_q, x3_cs_q;
  logic                  x3_lt_q, x3_eq_q, x3_behind_q;

  always_ff @(posedge clk_i) begin
    x3_z_q      <= x2_z_q;
    x3_cov_q    <= x2_cov_q;
    x3_cs_q     <= x2_cs_q;
    x3_lt_q     <= x2_z_q < x2_zs_q;
    x3_eq_q     <= x2_z_q == x2_zs_q;
    x3_behind_q <= x2_z_q > x2_peel_q;
  end

  // ---------------------------------------------------------------------------------------
  // X3: decisions.
  // ---------------------------------------------------------------------------------------
  logic            x3_cmp, x3_pass, x3_nearer, x3_dwe;
  logic [CovW-1:0] x3_weight, x3_cov_new;
  logic            x4_dwe_q;
  logic [CovW-1:0] x4_weight_q;

  zb_depth_test u_depth_test (
    .func_i(depth_func_i),
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
  assign x3_pass = cov_mode_i | ((~depth_test_i | x3_cmp) & (~peel_test_i | x3_behind_q));
  assign x3_dwe  = x3_pass & depth_test_i & depth_write_i & (~cov_mode_i | x3_nearer);

  always_ff @(posedge clk_i) begin
    x4_z_q       <= x3_z_q;
    x4_dwe_q     <= x3_dwe;
    x4_weight_q  <= x3_weight;
    x4_cov_new_q <= x3_cov_new;
  end

  // ---------------------------------------------------------------------------------------
  // X4: depth and coverage writes (edge E4).
  // ---------------------------------------------------------------------------------------
  assign x4_dwe = x_valid_i[4] & x4_dwe_q;
  assign x4_vwe = x_valid_i[4] & cov_mode_i;

  assign x3_pass_o   = x3_pass;
  assign x4_dwe_o    = x4_dwe;
  assign x4_weight_o = x4_weight_q;
  assign x4_wdepth_o = x4_z_q;
  assign x4_vwe_o    = x4_vwe;
  assign x4_wcov_o   = x4_cov_new_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // A read that meets a write of its pixel at one edge takes the forwarded word.
  DepthForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (issue_i && x4_dwe && m_addr_i == x4_addr_i) |=> dfwd_hit_q);
  CovForwardCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (issue_i && x4_vwe && m_addr_i == x4_addr_i) |=> vfwd_hit_q);
  DepthForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      issue_i && x4_dwe && m_addr_i == x4_addr_i);
  CovForwardPath: cover property (@(posedge clk_i) disable iff (!rst_ni)
      issue_i && x4_vwe && m_addr_i == x4_addr_i);
  // The copy's peel write takes the peel plane's port in the cycle after its read: a fast clear
  // then would clear peel too (its enable is the copy's), and a load of peel is not taken.
  CopyThenNoClear: assert property (@(posedge clk_i) disable iff (!rst_ni)
      copy_q |-> !(tile_clear_i || (tile_req_i && tile_we_i && tile_planes_i.peel)));
  // The coverage plane holds counts 0..N: a coverage-mode fragment never reads more.
  StoredCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_i[2] && cov_mode_i) |-> (x2_cs_q <= CovW'(COV_SAMPLES)));
  // Coverage mode: the depth never moves farther, and the pixel's coverage never shrinks.
  CovDepthNeverFarther: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_i[3] && cov_mode_i && x3_dwe) |-> x3_lt_q);
  CovNeverShrinks: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_i[3] && cov_mode_i) |-> (x3_cov_new >= x3_cs_q));
  // A fragment that passes with the peel test on lies strictly behind the peel plane.
  PeelPassBehind: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (x_valid_i[3] && x3_pass && peel_test_i && !cov_mode_i) |-> x3_behind_q);
`endif
`endif

endmodule
