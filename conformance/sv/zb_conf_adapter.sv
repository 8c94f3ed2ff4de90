// zb_conf_adapter: zb_rop behind the conformance testbench's DUT interface (docs/conformance.md
// "The adapter"). The testbench speaks pixels: a tile is loaded and stored one pixel a clock in
// raster order, fragments stream with valid/ready. This adapter gathers the pixels into zb_rop's
// tile-port beats and spreads the stored beats back into pixels. A team's own ROP gets an
// adapter of its own with the same ports; this one is the worked example. Defined
// ZB_CONF_NO_ACCUM, it stands for a DUT without the accumulation plane: planes_o says so and
// the testbench skips the tests that need the plane. LAYERS is zb_rop's layers unit (mlab-K):
// a load fast-clears the layers first, a store with st_resolve_i reads with tile_mlab_i; after
// reset a read of every beat puts the plane's words at its epoch (zb_plane's
// FastClearAfterSweep), as zb_rop's C++ driver does. Defined ZB_CONF_NO_LAYERS, and under
// Icarus, LAYERS is 0: a four-state simulator cannot settle the never-loaded layers plane's X
// words by that sweep, so there zb_rop runs without the unit and the testbench skips the layers
// tests (layers_o = 0).
module zb_conf_adapter #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 64,
  parameter int TILE_H      = 64,
  parameter int BEAT        = 8,
  parameter int ACC_BITS    = 16,  // the accumulation word: 4 channels of ACC_BITS, then
  parameter int REV_BITS    = 8,   // the revealage (docs/datapath.md "7. Accumulate blend")
  parameter int WEIGHT_BITS = 4,
  // zb_rop's own, not the testbench's: the most layers a pixel (0: no layers unit)
`ifdef ZB_CONF_NO_LAYERS
  parameter int LAYERS      = 0
`elsif __ICARUS__
  parameter int LAYERS      = 0
`else
  parameter int LAYERS      = 4
`endif
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  // Pass state register (docs/datapath.md "The pass state"), loaded while idle_o.
  input  logic        state_we_i,
  input  logic [12:0] state_i,
  input  logic [2:0]  state_layers_i,  // the pass state's [15:13]: K - 1 (layers mode)
  // The resident tile's origin in frame pixels; stable from a tile's load to its store.
  input  logic [15:0] tile_x0_i,
  input  logic [15:0] tile_y0_i,
  // Load: all TILE_W * TILE_H pixels of the tile, pixel p = y_local * TILE_W + x_local in
  // order, one per ld_valid_i && ld_ready_o. Depth and peel in the low DEPTH_BITS.
  input  logic        ld_valid_i,
  output logic        ld_ready_o,
  input  logic [31:0] ld_color_i,
  input  logic [31:0] ld_depth_i,
  input  logic [7:0]  ld_cov_i,
  input  logic [31:0] ld_peel_i,
  input  logic [4*ACC_BITS+REV_BITS-1:0] ld_acc_i,  // {r, acc_A, acc_B, acc_G, acc_R}
  // Fragments (docs/datapath.md "The fragment"), frame coordinates, inside the tile.
  input  logic        frag_valid_i,
  output logic        frag_ready_o,
  input  logic [15:0] frag_x_i,
  input  logic [15:0] frag_y_i,
  input  logic [31:0] frag_z_i,
  input  logic [31:0] frag_rgba_i,
  input  logic [7:0]  frag_cov_i,
  // Every accepted fragment has made its writes and no load or store is under way.
  output logic        idle_o,
  // Store: a pulse on st_start_i (while idle_o) reads the tile back; its pixels come out in
  // load order, one per st_valid_o. With st_resolve_i beside st_start_i, each colour is its
  // pixel's layers resolved over it (frame operation 5 on the way out).
  input  logic        st_start_i,
  input  logic        st_resolve_i,
  output logic        st_valid_o,
  output logic [31:0] st_color_o,
  output logic [31:0] st_depth_o,
  output logic [7:0]  st_cov_o,
  output logic [31:0] st_peel_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] st_acc_o,
  // The planes the DUT carries (zb_pkg::planes_t order: colour, depth, coverage, peel,
  // accumulation); constant. Without bit 4, st_acc_o and the ret_a* outputs are unused.
  output logic [4:0]  planes_o,
  // The most layers a pixel the DUT keeps (mlab-K's K); constant. 0: no layers mode.
  output logic [3:0]  layers_o,
  // Retire port for a lock-step scoreboard (optional for other DUTs: tie the valids low). Per
  // accepted fragment, in order per pixel: one depth-side retire (depth and coverage writes)
  // and one colour-side retire, each naming the tile pixel and what it wrote.
  output logic        ret_d_valid_o,
  output logic [31:0] ret_d_pixel_o,
  output logic        ret_dwe_o,
  output logic [31:0] ret_wdepth_o,
  output logic        ret_vwe_o,
  output logic [7:0]  ret_wcov_o,
  output logic        ret_c_valid_o,
  output logic [31:0] ret_c_pixel_o,
  output logic        ret_cwe_o,
  output logic [31:0] ret_wcolor_o,
  output logic        ret_awe_o,    // beside the colour side's retire: the accumulation word
  output logic [4*ACC_BITS+REV_BITS-1:0] ret_wacc_o
);

  localparam int Words  = TILE_W * TILE_H;
  localparam int Beats  = Words / BEAT;
  localparam int AddrW  = $clog2(Words);
  localparam int BeatAW = $clog2(Beats);
  localparam int LaneW  = $clog2(BEAT);
  localparam int CovW   = $clog2(COV_SAMPLES + 1);
  localparam int D      = DEPTH_BITS;
  localparam int AccW   = 4 * ACC_BITS + REV_BITS;
`ifdef ZB_CONF_NO_ACCUM
  localparam logic [4:0] Planes = 5'b01111;
`else
  localparam logic [4:0] Planes = 5'b11111;
`endif

  // The tile port as zb_rop takes it.
  logic                tile_req, tile_we, tile_clear, tile_mlab;
  logic [4:0]          tile_planes;
  logic [BeatAW-1:0]   tile_addr;
  logic [BEAT*32-1:0]  wcolor_q, rcolor;
  logic [BEAT*D-1:0]   wdepth_q, wpeel_q, rdepth, rpeel;
  logic [BEAT*CovW-1:0] wcov_q, rcov;
  logic [BEAT*AccW-1:0] wacc_q, racc;
  logic                busy;

  // ---------------------------------------------------------------------------------------
  // Load: pixels gather into the beat registers; a full beat is written at the next edge, while
  // the next beat's first pixel lands in the registers (zb_rop samples the old value).
  // ---------------------------------------------------------------------------------------
  logic [AddrW-1:0]  ld_pixel_q;
  logic              ld_go_q;
  logic [BeatAW-1:0] ld_beat_q;
  logic [LaneW-1:0]  ld_lane;
  assign ld_lane    = ld_pixel_q[LaneW-1:0];
  assign ld_ready_o = 1'b1;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ld_pixel_q <= '0;
      ld_go_q    <= 1'b0;
      ld_beat_q  <= '0;
    end else begin
      ld_go_q <= ld_valid_i && ld_lane == LaneW'(BEAT - 1);
      if (ld_valid_i) begin
        ld_pixel_q <= ld_pixel_q + 1'b1;  // wraps after the tile's last pixel
        ld_beat_q  <= ld_pixel_q[AddrW-1:LaneW];
      end
    end
  end

  // A tile starts with no layers: the load's first pixel fast-clears the layers plane alone
  // (no beat is written in that cycle: the previous tile's last one went before its store).
  assign tile_clear = LAYERS > 0 && ld_valid_i && ld_pixel_q == '0;

  always_ff @(posedge clk_i) begin
    if (ld_valid_i) begin
      wcolor_q[ld_lane*32 +: 32]     <= ld_color_i;
      wdepth_q[ld_lane*D +: D]       <= ld_depth_i[D-1:0];
      wcov_q[ld_lane*CovW +: CovW]   <= ld_cov_i[CovW-1:0];
      wpeel_q[ld_lane*D +: D]        <= ld_peel_i[D-1:0];
      wacc_q[ld_lane*AccW +: AccW]   <= ld_acc_i;
    end
  end

  // ---------------------------------------------------------------------------------------
  // Store: read a beat, capture it the cycle after (the read data), send its lanes.
  // ---------------------------------------------------------------------------------------
  typedef enum logic [1:0] { StIdle, StRead, StCapture, StEmit } st_e;
  st_e               st_q;
  logic              st_resolve_q;
  logic [BeatAW-1:0] st_beat_q;
  logic [LaneW-1:0]  st_lane_q;
  logic [BEAT*32-1:0]   cap_color_q;
  logic [BEAT*D-1:0]    cap_depth_q, cap_peel_q;
  logic [BEAT*CovW-1:0] cap_cov_q;
  logic [BEAT*AccW-1:0] cap_acc_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q         <= StIdle;
      st_beat_q    <= '0;
      st_lane_q    <= '0;
      st_resolve_q <= 1'b0;
    end else begin
      unique case (st_q)
        StIdle: if (st_start_i) begin
          st_q         <= StRead;
          st_beat_q    <= '0;
          st_resolve_q <= st_resolve_i && LAYERS > 0;
        end
        StRead:    st_q <= StCapture;
        StCapture: begin
          st_q      <= StEmit;
          st_lane_q <= '0;
        end
        StEmit: begin
          st_lane_q <= st_lane_q + 1'b1;
          if (st_lane_q == LaneW'(BEAT - 1)) begin
            st_beat_q <= st_beat_q + 1'b1;
            st_q      <= st_beat_q == BeatAW'(Beats - 1) ? StIdle : StRead;
          end
        end
        default: st_q <= StIdle;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    if (st_q == StCapture) begin
      cap_color_q <= rcolor;
      cap_depth_q <= rdepth;
      cap_cov_q   <= rcov;
      cap_peel_q  <= rpeel;
      cap_acc_q   <= racc;
    end
  end

  assign st_valid_o = st_q == StEmit;
  assign st_color_o = cap_color_q[st_lane_q*32 +: 32];
  assign st_depth_o = 32'(cap_depth_q[st_lane_q*D +: D]);
  assign st_cov_o   = 8'(cap_cov_q[st_lane_q*CovW +: CovW]);
  assign st_peel_o  = 32'(cap_peel_q[st_lane_q*D +: D]);
  assign st_acc_o   = cap_acc_q[st_lane_q*AccW +: AccW];
  assign planes_o   = Planes;
  assign layers_o   = 4'(LAYERS);

  // The sweep after reset: a read of every beat, nothing sent (the layers plane's words put at
  // its epoch before the first fast clear).
  logic              sweep_q;
  logic [BeatAW-1:0] sweep_beat_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      sweep_q      <= LAYERS > 0;
      sweep_beat_q <= '0;
    end else if (sweep_q) begin
      sweep_beat_q <= sweep_beat_q + 1'b1;
      sweep_q      <= sweep_beat_q != BeatAW'(Beats - 1);
    end
  end

  assign tile_req  = ld_go_q || st_q == StRead || sweep_q;
  assign tile_we   = ld_go_q;
  assign tile_addr = ld_go_q ? ld_beat_q : sweep_q ? sweep_beat_q : st_beat_q;
  assign tile_mlab = tile_clear || (st_q == StRead && st_resolve_q);
  assign tile_planes = tile_clear ? 5'b00000 : Planes;  // the layers' clear alone
  assign idle_o    = !busy && !ld_go_q && st_q == StIdle && !sweep_q;

  // ---------------------------------------------------------------------------------------
  // The DUT.
  // ---------------------------------------------------------------------------------------
  zb_pkg::pass_state_t state;  // the register's bits, as its packed struct
  assign state = state_i;

  logic [AddrW-1:0] mon_x4_addr, mon_x11_addr;
  logic [D-1:0]     mon_wdepth;
  logic [CovW-1:0]  mon_wcov;

  zb_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .COV_SAMPLES(COV_SAMPLES),
    .BEAT       (BEAT),
    .ACC_BITS   (ACC_BITS),
    .REV_BITS   (REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS),
    .LAYERS     (LAYERS)
  ) u_rop (
    .clk_i,
    .rst_ni,
    .state_we_i,
    .state_i           (state),
    .state_layers_i,
    .tile_x0_i,
    .tile_y0_i,
    .frag_valid_i,
    .frag_ready_o,
    .frag_x_i,
    .frag_y_i,
    .frag_z_i          (frag_z_i[D-1:0]),
    .frag_rgba_i,
    .frag_cov_i        (frag_cov_i[CovW-1:0]),
    .stall_i           (1'b0),
    .tile_req_i        (tile_req),
    .tile_we_i         (tile_we),
    .tile_clear_i      (tile_clear),
    .tile_copy_i       (1'b0),
    .tile_resolve_i    (1'b0),
    .tile_wboit_i      (1'b0),
    .tile_mlab_i       (tile_mlab),
    .tile_planes_i     (tile_planes),
    .tile_addr_i       (tile_addr),
    .tile_wcolor_i     (wcolor_q),
    .tile_wdepth_i     (wdepth_q),
    .tile_wcov_i       (wcov_q),
    .tile_wpeel_i      (wpeel_q),
    .tile_wacc_i       (wacc_q),
    .tile_rcolor_o     (rcolor),
    .tile_rdepth_o     (rdepth),
    .tile_rcov_o       (rcov),
    .tile_rpeel_o      (rpeel),
    .tile_racc_o       (racc),
    .busy_o            (busy),
    .cnt_clear_i       (1'b0),
    .cnt_frag_in_o     (),
    .cnt_frag_passed_o (),
    .cnt_frag_killed_o (),
    .cnt_depth_reads_o (),
    .cnt_depth_writes_o(),
    .cnt_color_reads_o (),
    .cnt_color_writes_o(),
    .cnt_stall_cycles_o(),
    .cnt_cycles_o      (),
    .cnt_tile_loads_o  (),
    .cnt_tile_stores_o (),
    .mon_x4_valid_o    (ret_d_valid_o),
    .mon_x4_addr_o     (mon_x4_addr),
    .mon_dwe_o         (ret_dwe_o),
    .mon_wdepth_o      (mon_wdepth),
    .mon_vwe_o         (ret_vwe_o),
    .mon_wcov_o        (mon_wcov),
    .mon_x11_valid_o   (ret_c_valid_o),
    .mon_x11_addr_o    (mon_x11_addr),
    .mon_cwe_o         (ret_cwe_o),
    .mon_wcolor_o      (ret_wcolor_o),
    .mon_awe_o         (ret_awe_o),
    .mon_wacc_o        (ret_wacc_o),
    .mon_lwe_o         (),
    .mon_wlayers_o     ()
  );

  assign ret_d_pixel_o = 32'(mon_x4_addr);
  assign ret_c_pixel_o = 32'(mon_x11_addr);
  assign ret_wdepth_o  = 32'(mon_wdepth);
  assign ret_wcov_o    = 8'(mon_wcov);

endmodule
