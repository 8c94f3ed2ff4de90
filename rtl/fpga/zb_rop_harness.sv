// zb_rop_harness: FPGA timing top for scripts/synth.sh, not part of the design (so not in rtl/).
// zb_rop has far more I/O bits than an iCE40 has pins. Here every zb_rop input comes from a
// flip-flop of one long shift register loaded from one pin (sin_i), and the outputs are
// XOR-reduced over three registered levels to one pin (sout_o): four outputs into a flop through
// one LUT (the counters, flops inside zb_rop already, skip that level), then 16, then the rest.
// Each input is an independent flop and each output reaches the pin, so nothing of zb_rop can be
// optimised away, and every timed path that touches zb_rop starts and ends on a flop: nextpnr's
// clock figure is register to register through zb_rop, an output's path with one harness LUT
// more (a registered output in a flop of its own costs a logic cell each: 460 at BEAT 2).
// rst_ni: pin, asserted asynchronously, released through a two-flop synchroniser.
module zb_rop_harness #(
  parameter int unsigned DEPTH_BITS  = 24,
  parameter int unsigned TILE_W      = 32,
  parameter int unsigned TILE_H      = 16,
  parameter int unsigned CNT_W       = 32,
  parameter int unsigned COV_SAMPLES = 16,
  parameter int unsigned WINDOW      = 8,
  parameter int unsigned BEAT        = 1,   // scripts/synth.sh --beat
  parameter int unsigned ACC_BITS    = 16,
  parameter int unsigned REV_BITS    = 8,
  parameter int unsigned WEIGHT_BITS = 4,
  parameter bit          TILE_OPS    = 1'b0   // scripts/synth.sh --tile-ops (docs/rtl.md "Synthesis")
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sin_i,
  output logic sout_o
);

  localparam int unsigned CovW   = $clog2(COV_SAMPLES + 1);
  localparam int unsigned BeatAW = $clog2(TILE_W * TILE_H / BEAT);
  localparam int unsigned AccW   = 4 * ACC_BITS + REV_BITS;
  // The inputs in the shift register, each at its offset.
  localparam int unsigned IStateWe = 0;
  localparam int unsigned IState   = IStateWe + 1;
  localparam int unsigned IX0      = IState + 13;
  localparam int unsigned IY0      = IX0 + 16;
  localparam int unsigned IValid   = IY0 + 16;
  localparam int unsigned IX       = IValid + 1;
  localparam int unsigned IY       = IX + 16;
  localparam int unsigned IZ       = IY + 16;
  localparam int unsigned IRgba    = IZ + DEPTH_BITS;
  localparam int unsigned ICov     = IRgba + 32;
  localparam int unsigned IStall   = ICov + CovW;
  localparam int unsigned IReq     = IStall + 1;
  localparam int unsigned IWe      = IReq + 1;
  localparam int unsigned IClear   = IWe + 1;
  localparam int unsigned ICopy    = IClear + 1;
  localparam int unsigned IResolve = ICopy + 1;
  // tile_wboit_i only with TILE_OPS: without, the chain stays as it was before the input came
  // (its placement, and so the HX8K's clock by seed, moved by a flop; docs/rtl.md "Synthesis").
  localparam int unsigned IWboit   = IResolve + 1;
  localparam int unsigned IPlanes  = IWboit + (TILE_OPS ? 1 : 0);
  localparam int unsigned IAddr    = IPlanes + 5;
  localparam int unsigned IWColor  = IAddr + BeatAW;
  localparam int unsigned IWDepth  = IWColor + BEAT * 32;
  localparam int unsigned IWCov    = IWDepth + BEAT * DEPTH_BITS;
  localparam int unsigned IWPeel   = IWCov + BEAT * CovW;
  localparam int unsigned IWAcc    = IWPeel + BEAT * DEPTH_BITS;
  localparam int unsigned ICntClr  = IWAcc + BEAT * AccW;
  localparam int unsigned InW      = ICntClr + 1;
  // The outputs: frag_ready, the read beat, busy, eleven counters.
  localparam int unsigned OReady   = 0;
  localparam int unsigned ORColor  = OReady + 1;
  localparam int unsigned ORDepth  = ORColor + BEAT * 32;
  localparam int unsigned ORCov    = ORDepth + BEAT * DEPTH_BITS;
  localparam int unsigned ORPeel   = ORCov + BEAT * CovW;
  localparam int unsigned ORAcc    = ORPeel + BEAT * DEPTH_BITS;
  localparam int unsigned OBusy    = ORAcc + BEAT * AccW;
  localparam int unsigned OCnt     = OBusy + 1;
  localparam int unsigned OutW     = OCnt + 11 * CNT_W;
  localparam int unsigned Grp      = 16;                       // bits per second-level XOR
  // First level: each flop takes the XOR of four outputs (one LUT, packed with its flop).
  localparam int unsigned X0W      = (OCnt + 3) / 4;
  localparam int unsigned PadW     = X0W + OutW - OCnt;        // the first level and the counters
  localparam int unsigned X1N      = (PadW + Grp - 1) / Grp;

  logic       rst_sync_q, rst_n_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rst_sync_q <= 1'b0;
      rst_n_q    <= 1'b0;
    end else begin
      rst_sync_q <= 1'b1;
      rst_n_q    <= rst_sync_q;
    end
  end

  logic [InW-1:0] in_q;
  always_ff @(posedge clk_i) begin
    in_q <= {in_q[InW-2:0], sin_i};
  end

  logic [OutW-1:0] out_d;
  zb_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .CNT_W      (CNT_W),
    .COV_SAMPLES(COV_SAMPLES),
    .WINDOW     (WINDOW),
    .BEAT       (BEAT),
    .ACC_BITS   (ACC_BITS),
    .REV_BITS   (REV_BITS),
    .WEIGHT_BITS(WEIGHT_BITS),
    .TILE_OPS   (TILE_OPS)
  ) u_rop (
    .clk_i,
    .rst_ni            (rst_n_q),
    .state_we_i        (in_q[IStateWe]),
    .state_i           (in_q[IState +: 13]),
    .state_layers_i    (3'b000),  // no layers unit
    .tile_x0_i         (in_q[IX0 +: 16]),
    .tile_y0_i         (in_q[IY0 +: 16]),
    .frag_valid_i      (in_q[IValid]),
    .frag_ready_o      (out_d[OReady]),
    .frag_x_i          (in_q[IX +: 16]),
    .frag_y_i          (in_q[IY +: 16]),
    .frag_z_i          (in_q[IZ +: DEPTH_BITS]),
    .frag_rgba_i       (in_q[IRgba +: 32]),
    .frag_cov_i        (in_q[ICov +: CovW]),
    .stall_i           (in_q[IStall]),
    .tile_req_i        (in_q[IReq]),
    .tile_we_i         (in_q[IWe]),
    .tile_clear_i      (in_q[IClear]),
    .tile_copy_i       (in_q[ICopy]),
    .tile_resolve_i    (in_q[IResolve]),
    .tile_wboit_i      (TILE_OPS ? in_q[IWboit] : 1'b0),
    .tile_mlab_i       (1'b0),
    .tile_planes_i     (in_q[IPlanes +: 5]),
    .tile_addr_i       (in_q[IAddr +: BeatAW]),
    .tile_wcolor_i     (in_q[IWColor +: BEAT * 32]),
    .tile_wdepth_i     (in_q[IWDepth +: BEAT * DEPTH_BITS]),
    .tile_wcov_i       (in_q[IWCov +: BEAT * CovW]),
    .tile_wpeel_i      (in_q[IWPeel +: BEAT * DEPTH_BITS]),
    .tile_wacc_i       (in_q[IWAcc +: BEAT * AccW]),
    .tile_rcolor_o     (out_d[ORColor +: BEAT * 32]),
    .tile_rdepth_o     (out_d[ORDepth +: BEAT * DEPTH_BITS]),
    .tile_rcov_o       (out_d[ORCov +: BEAT * CovW]),
    .tile_rpeel_o      (out_d[ORPeel +: BEAT * DEPTH_BITS]),
    .tile_racc_o       (out_d[ORAcc +: BEAT * AccW]),
    .busy_o            (out_d[OBusy]),
    .cnt_clear_i       (in_q[ICntClr]),
    .cnt_frag_in_o     (out_d[OCnt + 0 * CNT_W +: CNT_W]),
    .cnt_frag_passed_o (out_d[OCnt + 1 * CNT_W +: CNT_W]),
    .cnt_frag_killed_o (out_d[OCnt + 2 * CNT_W +: CNT_W]),
    .cnt_depth_reads_o (out_d[OCnt + 3 * CNT_W +: CNT_W]),
    .cnt_depth_writes_o(out_d[OCnt + 4 * CNT_W +: CNT_W]),
    .cnt_color_reads_o (out_d[OCnt + 5 * CNT_W +: CNT_W]),
    .cnt_color_writes_o(out_d[OCnt + 6 * CNT_W +: CNT_W]),
    .cnt_stall_cycles_o(out_d[OCnt + 7 * CNT_W +: CNT_W]),
    .cnt_cycles_o      (out_d[OCnt + 8 * CNT_W +: CNT_W]),
    .cnt_tile_loads_o  (out_d[OCnt + 9 * CNT_W +: CNT_W]),
    .cnt_tile_stores_o (out_d[OCnt + 10 * CNT_W +: CNT_W]),
    // The retire port taps registers timed above; a testbench's, not the FPGA's.
    .mon_x4_valid_o    (),
    .mon_x4_addr_o     (),
    .mon_dwe_o         (),
    .mon_wdepth_o      (),
    .mon_vwe_o         (),
    .mon_wcov_o        (),
    .mon_x11_valid_o   (),
    .mon_x11_addr_o    (),
    .mon_cwe_o         (),
    .mon_wcolor_o      (),
    .mon_awe_o         (),
    .mon_wacc_o        (),
    .mon_lwe_o         (),
    .mon_wlayers_o     ()
  );

  logic [4*X0W-1:0]    out0;
  logic [X0W-1:0]      x0_q;
  logic [X1N*Grp-1:0]  out_pad;
  logic [X1N-1:0]      x1_q;
  logic                sout_q;

  assign out0 = {{(4 * X0W - OCnt){1'b0}}, out_d[OCnt-1:0]};
  assign out_pad = {{(X1N * Grp - PadW){1'b0}}, out_d[OutW-1:OCnt], x0_q};

  always_ff @(posedge clk_i) begin
    for (int unsigned j = 0; j < X0W; j++) begin
      x0_q[j] <= ^out0[4*j +: 4];
    end
    for (int unsigned i = 0; i < X1N; i++) begin
      x1_q[i] <= ^out_pad[i*Grp +: Grp];
    end
    sout_q <= ^x1_q;
  end

  assign sout_o = sout_q;

endmodule
