// zb_rop: the per-pixel datapath (raster operations unit) of docs/datapath.md, top level.
//
// Three-stage pipeline, one fragment per clock, no interlock (docs/rtl.md has the diagram):
//   S0  accept (frag_valid_i && frag_ready_o); issue the depth- and coverage-memory reads.
//   S1  depth, peel and coverage read data; depth and coverage forwarding; depth test and the
//       peel test (z > peel), or in coverage mode the four-case decision
//       (zb_coverage_composite); depth and coverage writes; colour read.
//   S2  colour read data; colour forwarding; blend; write mask; colour write.
// Each memory is read one edge before it is written, so a fragment's read can miss only the
// write landing on the same edge (the previous fragment's); one forwarding register per
// memory holds that write's post-state. The peel memory is written only through the tile port,
// never by a fragment, so it needs no forwarding.
// Reset: rst_ni, asynchronous, active low. Memories are not reset (load the tile).
module zb_rop #(
  parameter int unsigned DEPTH_BITS = 24,   // 8..32
  parameter int unsigned TILE_W     = 64,   // power of two
  parameter int unsigned TILE_H     = 64,   // power of two
  parameter int unsigned CNT_W      = 32,
  parameter int unsigned COV_SAMPLES = 16,  // N of the sample pattern: 1, 2, 4, 8 or 16
  localparam int unsigned AddrW     = $clog2(TILE_W * TILE_H),
  localparam int unsigned CovW      = $clog2(COV_SAMPLES + 1)  // coverage count 0..N
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  state_we_i,
  input  logic [12:0]           state_i,
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
  input  logic                  tile_req_i,
  input  logic                  tile_we_i,
  input  logic [AddrW-1:0]      tile_addr_i,
  input  logic [31:0]           tile_wcolor_i,
  input  logic [DEPTH_BITS-1:0] tile_wdepth_i,
  input  logic [CovW-1:0]       tile_wcov_i,
  input  logic [DEPTH_BITS-1:0] tile_wpeel_i,
  output logic [31:0]           tile_rcolor_o,
  output logic [DEPTH_BITS-1:0] tile_rdepth_o,
  output logic [CovW-1:0]       tile_rcov_o,
  output logic [DEPTH_BITS-1:0] tile_rpeel_o,
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
  output logic [CNT_W-1:0]      cnt_cycles_o
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
`endif

  // ---------------------------------------------------------------------------------------
  // Pass state register (docs/datapath.md "The pass state"); loaded only while idle.
  // ---------------------------------------------------------------------------------------
  logic [12:0] state_d, state_q;
  logic        st_depth_test, st_depth_write, st_peel_test;
  logic [2:0]  st_depth_func;
  logic [2:0]  st_blend;
  logic [3:0]  st_color_mask;

  always_comb begin
    state_d = state_q;
    if (state_we_i) begin
      state_d = state_i;
    end
  end

  assign st_depth_test  = state_q[0];
  assign st_depth_func  = state_q[3:1];
  assign st_depth_write = state_q[4];
  assign st_blend       = state_q[7:5];
  assign st_color_mask  = state_q[11:8];
  assign st_peel_test   = state_q[12];

  logic st_cov;  // coverage mode: blend code 3 (docs/datapath.md "Coverage blend")
  assign st_cov = st_blend == 3'd3;

  // ---------------------------------------------------------------------------------------
  // Tile port decode
  // ---------------------------------------------------------------------------------------
  logic tile_rd, tile_wr;

  assign tile_rd = tile_req_i & ~tile_we_i;
  assign tile_wr = tile_req_i &  tile_we_i;

  // ---------------------------------------------------------------------------------------
  // S0: accept, tile-local address, depth read
  // ---------------------------------------------------------------------------------------
  logic             accept;
  logic [15:0]      dx, dy;
  logic [AddrW-1:0] s0_addr;

  assign frag_ready_o = ~stall_i & ~tile_req_i;
  assign accept       = frag_valid_i & frag_ready_o;

  assign dx      = frag_x_i - tile_x0_i;
  assign dy      = frag_y_i - tile_y0_i;
  assign s0_addr = {dy[YW-1:0], dx[XW-1:0]};   // y_local * TILE_W + x_local

  logic                  s1_valid_d, s1_valid_q;
  logic [AddrW-1:0]      s1_addr_d, s1_addr_q;
  logic [DEPTH_BITS-1:0] s1_z_d, s1_z_q;
  logic [31:0]           s1_rgba_d, s1_rgba_q;
  logic [CovW-1:0]       s1_cov_d, s1_cov_q;

  always_comb begin
    s1_valid_d = accept;
    s1_addr_d  = s1_addr_q;
    s1_z_d     = s1_z_q;
    s1_rgba_d  = s1_rgba_q;
    s1_cov_d   = s1_cov_q;
    if (accept) begin
      s1_addr_d = s0_addr;
      s1_z_d    = frag_z_i;
      s1_rgba_d = frag_rgba_i;
      s1_cov_d  = frag_cov_i;
    end
  end

`ifndef SYNTHESIS
  // An accepted fragment lies inside the resident tile.
  FragInTile: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
  // A fragment covers at most the N samples of a pixel.
  FragCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      accept |-> (frag_cov_i <= CovW'(COV_SAMPLES)));
`endif

  // Depth memory. Read: S0 (fragment) or the tile port. Write: S1 (fragment) or the tile port.
  logic                  dmem_re, dmem_we;
  logic [AddrW-1:0]      dmem_raddr, dmem_waddr;
  logic [DEPTH_BITS-1:0] dmem_rdata, dmem_wdata;

  // ---------------------------------------------------------------------------------------
  // S1: depth forwarding, depth test, depth write, colour read
  // ---------------------------------------------------------------------------------------
  logic                  dfwd_valid_d, dfwd_valid_q;
  logic [AddrW-1:0]      dfwd_addr_d, dfwd_addr_q;
  logic [DEPTH_BITS-1:0] dfwd_depth_d, dfwd_depth_q;
  logic                  s1_dfwd_hit;
  logic [DEPTH_BITS-1:0] s1_zs;        // stored depth as sequential processing sees it
  logic                  s1_cmp, s1_pass, s1_dwe;

  // The previous fragment's depth write landed on the same edge as this fragment's read
  // (read-first: the read returned the old word), so take its post-state from dfwd.
  assign s1_dfwd_hit = dfwd_valid_q && (dfwd_addr_q == s1_addr_q);
  assign s1_zs       = s1_dfwd_hit ? dfwd_depth_q : dmem_rdata;

  zb_depth_test #(
    .DEPTH_BITS(DEPTH_BITS)
  ) u_depth_test (
    .func_i  (st_depth_func),
    .z_i     (s1_z_q),
    .stored_i(s1_zs),
    .pass_o  (s1_cmp)
  );

  // Coverage memory: read and written with the depth memory's timing (read S0, write S1), so
  // it forwards the same way (vfwd).
  logic                  vmem_re, vmem_we;
  logic [AddrW-1:0]      vmem_raddr, vmem_waddr;
  logic [CovW-1:0]       vmem_rdata, vmem_wdata;
  logic                  vfwd_valid_d, vfwd_valid_q;
  logic [AddrW-1:0]      vfwd_addr_d, vfwd_addr_q;
  logic [CovW-1:0]       vfwd_cov_d, vfwd_cov_q;
  logic                  s1_vfwd_hit;
  logic [CovW-1:0]       s1_cs;        // stored coverage as sequential processing sees it
  logic                  s1_nearer, s1_vwe;
  logic [CovW-1:0]       s1_weight, s1_cov_new;

  assign s1_vfwd_hit = vfwd_valid_q && (vfwd_addr_q == s1_addr_q);
  assign s1_cs       = s1_vfwd_hit ? vfwd_cov_q : vmem_rdata;

  zb_coverage_composite #(
    .DEPTH_BITS (DEPTH_BITS),
    .COV_SAMPLES(COV_SAMPLES)
  ) u_coverage (
    .z_i         (s1_z_q),
    .stored_z_i  (s1_zs),
    .cov_i       (s1_cov_q),
    .stored_cov_i(s1_cs),
    .nearer_o    (s1_nearer),
    .weight_o    (s1_weight),
    .cov_o       (s1_cov_new)
  );

  // Peel memory (docs/datapath.md "Peel test"): read in S0 with the depth memory, written only
  // by the tile port. Its word is constant during a pass, so the read is never stale.
  logic                  pmem_re, pmem_we;
  logic [AddrW-1:0]      pmem_raddr;
  logic [DEPTH_BITS-1:0] pmem_rdata;
  logic                  s1_peel_ok;

  assign pmem_re    = accept | tile_rd;
  assign pmem_raddr = tile_req_i ? tile_addr_i : s0_addr;
  assign pmem_we    = tile_wr;
  assign s1_peel_ok = s1_z_q > pmem_rdata;   // strictly behind the previous layer

  zb_tile_mem #(
    .WIDTH(DEPTH_BITS),
    .WORDS(Words)
  ) u_peel_mem (
    .clk_i  (clk_i),
    .re_i   (pmem_re),
    .raddr_i(pmem_raddr),
    .rdata_o(pmem_rdata),
    .we_i   (pmem_we),
    .waddr_i(tile_addr_i),
    .wdata_i(tile_wpeel_i)
  );

  // Test off: every fragment passes the depth test and depth is never written. Peel test on:
  // a fragment must also lie strictly behind the peel plane. Coverage mode: every fragment
  // passes to the compositing (the peel test is not used); depth is written only in the
  // nearer case.
  assign s1_pass = st_cov | ((~st_depth_test | s1_cmp) & (~st_peel_test | s1_peel_ok));
  assign s1_dwe  = s1_valid_q & s1_pass & st_depth_test & st_depth_write &
                   (~st_cov | s1_nearer);
  assign s1_vwe  = s1_valid_q & st_cov;

  always_comb begin
    vfwd_valid_d = s1_valid_q;
    vfwd_addr_d  = s1_addr_q;
    vfwd_cov_d   = s1_vwe ? s1_cov_new : s1_cs;
  end

  always_comb begin
    vmem_re    = accept | tile_rd;
    vmem_raddr = tile_req_i ? tile_addr_i : s0_addr;
    vmem_we    = s1_vwe | tile_wr;
    vmem_waddr = s1_vwe ? s1_addr_q : tile_addr_i;
    vmem_wdata = s1_vwe ? s1_cov_new : tile_wcov_i;
  end

  zb_tile_mem #(
    .WIDTH(CovW),
    .WORDS(Words)
  ) u_cov_mem (
    .clk_i  (clk_i),
    .re_i   (vmem_re),
    .raddr_i(vmem_raddr),
    .rdata_o(vmem_rdata),
    .we_i   (vmem_we),
    .waddr_i(vmem_waddr),
    .wdata_i(vmem_wdata)
  );

`ifndef SYNTHESIS
  // The coverage plane holds counts 0..N: a coverage-mode fragment never reads more.
  StoredCoverageInRange: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && st_cov) |-> (s1_cs <= CovW'(COV_SAMPLES)));
`endif

  always_comb begin
    dfwd_valid_d = s1_valid_q;
    dfwd_addr_d  = s1_addr_q;
    dfwd_depth_d = s1_dwe ? s1_z_q : s1_zs;
  end

  always_comb begin
    dmem_re    = accept | tile_rd;
    dmem_raddr = tile_req_i ? tile_addr_i : s0_addr;
    dmem_we    = s1_dwe | tile_wr;
    dmem_waddr = s1_dwe ? s1_addr_q : tile_addr_i;
    dmem_wdata = s1_dwe ? s1_z_q : tile_wdepth_i;
  end

  zb_tile_mem #(
    .WIDTH(DEPTH_BITS),
    .WORDS(Words)
  ) u_depth_mem (
    .clk_i  (clk_i),
    .re_i   (dmem_re),
    .raddr_i(dmem_raddr),
    .rdata_o(dmem_rdata),
    .we_i   (dmem_we),
    .waddr_i(dmem_waddr),
    .wdata_i(dmem_wdata)
  );

  logic             s2_valid_d, s2_valid_q;
  logic [AddrW-1:0] s2_addr_d, s2_addr_q;
  logic [31:0]      s2_rgba_d, s2_rgba_q;
  logic             s2_pass_d, s2_pass_q;
  logic [CovW-1:0]  s2_weight_d, s2_weight_q;

  always_comb begin
    s2_valid_d  = s1_valid_q;
    s2_addr_d   = s2_addr_q;
    s2_rgba_d   = s2_rgba_q;
    s2_pass_d   = s2_pass_q;
    s2_weight_d = s2_weight_q;
    if (s1_valid_q) begin
      s2_addr_d   = s1_addr_q;
      s2_rgba_d   = s1_rgba_q;
      s2_pass_d   = s1_pass;
      s2_weight_d = s1_weight;
    end
  end

  // ---------------------------------------------------------------------------------------
  // S2: colour forwarding, blend, write mask, colour write
  // ---------------------------------------------------------------------------------------
  logic             cmem_re, cmem_we;
  logic [AddrW-1:0] cmem_raddr, cmem_waddr;
  logic [31:0]      cmem_rdata, cmem_wdata;

  logic             cfwd_valid_d, cfwd_valid_q;
  logic [AddrW-1:0] cfwd_addr_d, cfwd_addr_q;
  logic [31:0]      cfwd_color_d, cfwd_color_q;
  logic             s2_cfwd_hit;
  logic [31:0]      s2_cs;          // stored colour as sequential processing sees it
  logic [31:0]      s2_blended, s2_merged;
  logic             s2_cwe;

  assign s2_cfwd_hit = cfwd_valid_q && (cfwd_addr_q == s2_addr_q);
  assign s2_cs       = s2_cfwd_hit ? cfwd_color_q : cmem_rdata;

  zb_blend #(
    .COV_SAMPLES(COV_SAMPLES)
  ) u_blend (
    .mode_i  (st_blend),
    .src_i   (s2_rgba_q),
    .dst_i   (s2_cs),
    .weight_i(s2_weight_q),
    .color_o (s2_blended)
  );

  zb_color_mask u_color_mask (
    .mask_i   (st_color_mask),
    .blended_i(s2_blended),
    .dst_i    (s2_cs),
    .color_o  (s2_merged)
  );

  assign s2_cwe = s2_valid_q & s2_pass_q & (st_color_mask != 4'h0);

  always_comb begin
    cfwd_valid_d = s2_valid_q;
    cfwd_addr_d  = s2_addr_q;
    cfwd_color_d = s2_cwe ? s2_merged : s2_cs;
  end

  always_comb begin
    cmem_re    = s1_valid_q | tile_rd;
    cmem_raddr = s1_valid_q ? s1_addr_q : tile_addr_i;
    cmem_we    = s2_cwe | tile_wr;
    cmem_waddr = s2_cwe ? s2_addr_q : tile_addr_i;
    cmem_wdata = s2_cwe ? s2_merged : tile_wcolor_i;
  end

  zb_tile_mem #(
    .WIDTH(32),
    .WORDS(Words)
  ) u_color_mem (
    .clk_i  (clk_i),
    .re_i   (cmem_re),
    .raddr_i(cmem_raddr),
    .rdata_o(cmem_rdata),
    .we_i   (cmem_we),
    .waddr_i(cmem_waddr),
    .wdata_i(cmem_wdata)
  );

  assign tile_rcolor_o = cmem_rdata;
  assign tile_rdepth_o = dmem_rdata;
  assign tile_rcov_o   = vmem_rdata;
  assign tile_rpeel_o  = pmem_rdata;
  assign busy_o        = s1_valid_q | s2_valid_q;

  // ---------------------------------------------------------------------------------------
  // Flops
  // ---------------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q      <= '0;
      s1_valid_q   <= 1'b0;
      s1_addr_q    <= '0;
      s1_z_q       <= '0;
      s1_rgba_q    <= '0;
      s1_cov_q     <= '0;
      vfwd_valid_q <= 1'b0;
      vfwd_addr_q  <= '0;
      vfwd_cov_q   <= '0;
      s2_weight_q  <= '0;
      dfwd_valid_q <= 1'b0;
      dfwd_addr_q  <= '0;
      dfwd_depth_q <= '0;
      s2_valid_q   <= 1'b0;
      s2_addr_q    <= '0;
      s2_rgba_q    <= '0;
      s2_pass_q    <= 1'b0;
      cfwd_valid_q <= 1'b0;
      cfwd_addr_q  <= '0;
      cfwd_color_q <= '0;
    end else begin
      state_q      <= state_d;
      s1_valid_q   <= s1_valid_d;
      s1_addr_q    <= s1_addr_d;
      s1_z_q       <= s1_z_d;
      s1_rgba_q    <= s1_rgba_d;
      s1_cov_q     <= s1_cov_d;
      vfwd_valid_q <= vfwd_valid_d;
      vfwd_addr_q  <= vfwd_addr_d;
      vfwd_cov_q   <= vfwd_cov_d;
      s2_weight_q  <= s2_weight_d;
      dfwd_valid_q <= dfwd_valid_d;
      dfwd_addr_q  <= dfwd_addr_d;
      dfwd_depth_q <= dfwd_depth_d;
      s2_valid_q   <= s2_valid_d;
      s2_addr_q    <= s2_addr_d;
      s2_rgba_q    <= s2_rgba_d;
      s2_pass_q    <= s2_pass_d;
      cfwd_valid_q <= cfwd_valid_d;
      cfwd_addr_q  <= cfwd_addr_d;
      cfwd_color_q <= cfwd_color_d;
    end
  end

  // ---------------------------------------------------------------------------------------
  // Counters (docs/datapath.md "Counters"); fragment events are counted in S1.
  // ---------------------------------------------------------------------------------------
  localparam int unsigned NumCnt = 9;

  logic                    s1_color_on, s1_reads_dest;
  logic [NumCnt-1:0]       cnt_inc;
  logic [NumCnt*CNT_W-1:0] cnt_all;

  assign s1_color_on   = s1_valid_q & s1_pass & (st_color_mask != 4'h0);
  // Replace with all four channels written needs no destination colour; the other modes
  // (alpha, additive, coverage) blend with it.
  assign s1_reads_dest = (st_blend != 3'd0) | (st_color_mask != 4'hf);

  always_comb begin
    cnt_inc    = '0;
    cnt_inc[0] = s1_valid_q;                       // fragments_in
    cnt_inc[1] = s1_valid_q & s1_pass;             // fragments_passed
    cnt_inc[2] = s1_valid_q & ~s1_pass;            // fragments_killed
    cnt_inc[3] = s1_valid_q & (st_depth_test | st_cov);  // depth_reads
    cnt_inc[4] = s1_dwe;                           // depth_writes
    cnt_inc[5] = s1_color_on & s1_reads_dest;      // color_reads
    cnt_inc[6] = s1_color_on;                      // color_writes
    cnt_inc[7] = frag_valid_i & ~frag_ready_o;     // stall cycles
    cnt_inc[8] = 1'b1;                             // cycles
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

  // ---------------------------------------------------------------------------------------
  // Assertions
  // ---------------------------------------------------------------------------------------
`ifndef SYNTHESIS
  // The tile port is used only while no fragment is in flight (its address and write would
  // collide with the pipeline's).
  TilePortIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      tile_req_i |-> !busy_o);

  // The pass state is written only while idle (a write in the cycle of an accept applies to
  // that fragment).
  StateWriteIdle: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> !busy_o);

  // Forwarding invariant: a fragment's read can miss at most one write to its memory, the one
  // landing on the read edge, and that write is the previous fragment's, held in the
  // forwarding register. dwe_last_q/vwe_last_q/cwe_last_q record the writes of the previous
  // edge.
  logic             dwe_last_q, vwe_last_q, cwe_last_q;
  logic [AddrW-1:0] dwaddr_last_q, vwaddr_last_q, cwaddr_last_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      dwe_last_q    <= 1'b0;
      dwaddr_last_q <= '0;
      vwe_last_q    <= 1'b0;
      vwaddr_last_q <= '0;
      cwe_last_q    <= 1'b0;
      cwaddr_last_q <= '0;
    end else begin
      dwe_last_q    <= dmem_we;
      dwaddr_last_q <= dmem_waddr;
      vwe_last_q    <= vmem_we;
      vwaddr_last_q <= vmem_waddr;
      cwe_last_q    <= cmem_we;
      cwaddr_last_q <= cmem_waddr;
    end
  end

  DepthFwdCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && dwe_last_q) |-> (dfwd_valid_q && dfwd_addr_q == dwaddr_last_q));
  CovFwdCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && vwe_last_q) |-> (vfwd_valid_q && vfwd_addr_q == vwaddr_last_q));
  ColorFwdCovers: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s2_valid_q && cwe_last_q) |-> (cfwd_valid_q && cfwd_addr_q == cwaddr_last_q));

  // The forwarding registers mirror the memory: they hold the pixel's current contents.
  DepthFwdMirror: assert property (@(posedge clk_i) disable iff (!rst_ni)
      dfwd_valid_q |-> (u_depth_mem.mem_q[dfwd_addr_q] == dfwd_depth_q));
  CovFwdMirror: assert property (@(posedge clk_i) disable iff (!rst_ni)
      vfwd_valid_q |-> (u_cov_mem.mem_q[vfwd_addr_q] == vfwd_cov_q));
  ColorFwdMirror: assert property (@(posedge clk_i) disable iff (!rst_ni)
      cfwd_valid_q |-> (u_color_mem.mem_q[cfwd_addr_q] == cfwd_color_q));

  // Coverage mode: the depth never moves farther, and the pixel's coverage never shrinks.
  CovDepthNeverFarther: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && st_cov && s1_dwe) |-> (s1_z_q < s1_zs));
  CovNeverShrinks: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && st_cov) |-> (s1_cov_new >= s1_cs));

  // The peel plane is read-only during a pass: pmem_we is the tile port's write alone
  // (structural), and TilePortIdle keeps the tile port away from fragments in flight. So the
  // word a fragment read at accept is still the memory's word when it is compared.
  PeelStable: assert property (@(posedge clk_i) disable iff (!rst_ni)
      s1_valid_q |-> (u_peel_mem.mem_q[s1_addr_q] == pmem_rdata));
  // A fragment that passes with the peel test on lies strictly behind the peel plane.
  PeelPassBehind: assert property (@(posedge clk_i) disable iff (!rst_ni)
      (s1_valid_q && s1_pass && st_peel_test && !st_cov) |-> (s1_z_q > pmem_rdata));
  // Only the five blend codes are loaded.
  BlendCodeValid: assert property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i |-> (state_i[7:5] <= 3'd4));

  // A fragment in S1 moves to S2 on the next edge: the pipeline never holds or drops one.
  NoPipelineBubble: assert property (@(posedge clk_i) disable iff (!rst_ni)
      s1_valid_q |=> s2_valid_q);
`endif

endmodule
