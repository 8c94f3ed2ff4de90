// zb_rop_harness: FPGA timing top for scripts/synth.sh, not part of the design (so not in rtl/).
// zb_rop has far more I/O bits than an iCE40 has pins. Here every zb_rop input comes from a
// flip-flop of one long shift register loaded from one pin (sin_i), and every output is
// registered, then XOR-reduced over two registered levels to one pin (sout_o). Each input is an
// independent flop and each output reaches the pin, so nothing of zb_rop can be optimised away,
// and every timed path that touches zb_rop starts and ends on a flop: nextpnr's clock figure is
// register to register inside zb_rop (or the 2-3 LUT levels of the harness itself).
// rst_ni: pin, asserted asynchronously, released through a two-flop synchroniser.
module zb_rop_harness #(
  parameter int unsigned DEPTH_BITS  = 24,
  parameter int unsigned TILE_W      = 32,
  parameter int unsigned TILE_H      = 32,
  parameter int unsigned CNT_W       = 32,
  parameter int unsigned COV_SAMPLES = 16
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sin_i,
  output logic sout_o
);

  localparam int unsigned AddrW = $clog2(TILE_W * TILE_H);
  localparam int unsigned CovW  = $clog2(COV_SAMPLES + 1);
  // state_we 1, state 13, tile_x0/y0 32, frag_valid 1, x/y 32, z, rgba 32, cov, stall 1,
  // tile_req 1, tile_we 1, tile_addr, wcolor 32, wdepth, wcov, wpeel, cnt_clear 1.
  localparam int unsigned InW  = 1 + 13 + 32 + 1 + 32 + DEPTH_BITS + 32 + CovW + 1 + 1 + 1 +
                                 AddrW + 32 + DEPTH_BITS + CovW + DEPTH_BITS + 1;
  // frag_ready 1, rcolor 32, rdepth, rcov, rpeel, busy 1, nine counters.
  localparam int unsigned OutW = 1 + 32 + DEPTH_BITS + CovW + DEPTH_BITS + 1 + 9 * CNT_W;
  localparam int unsigned Grp  = 16;                       // bits per first-level XOR
  localparam int unsigned X1W  = (OutW + Grp - 1) / Grp;

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
    .COV_SAMPLES(COV_SAMPLES)
  ) u_rop (
    .clk_i,
    .rst_ni            (rst_n_q),
    .state_we_i        (in_q[0]),
    .state_i           (in_q[1 +: 13]),
    .tile_x0_i         (in_q[14 +: 16]),
    .tile_y0_i         (in_q[30 +: 16]),
    .frag_valid_i      (in_q[46]),
    .frag_ready_o      (out_d[0]),
    .frag_x_i          (in_q[47 +: 16]),
    .frag_y_i          (in_q[63 +: 16]),
    .frag_z_i          (in_q[79 +: DEPTH_BITS]),
    .frag_rgba_i       (in_q[79 + DEPTH_BITS +: 32]),
    .frag_cov_i        (in_q[111 + DEPTH_BITS +: CovW]),
    .stall_i           (in_q[111 + DEPTH_BITS + CovW]),
    .tile_req_i        (in_q[112 + DEPTH_BITS + CovW]),
    .tile_we_i         (in_q[113 + DEPTH_BITS + CovW]),
    .tile_addr_i       (in_q[114 + DEPTH_BITS + CovW +: AddrW]),
    .tile_wcolor_i     (in_q[114 + DEPTH_BITS + CovW + AddrW +: 32]),
    .tile_wdepth_i     (in_q[146 + DEPTH_BITS + CovW + AddrW +: DEPTH_BITS]),
    .tile_wcov_i       (in_q[146 + 2 * DEPTH_BITS + CovW + AddrW +: CovW]),
    .tile_wpeel_i      (in_q[146 + 2 * DEPTH_BITS + 2 * CovW + AddrW +: DEPTH_BITS]),
    .tile_rcolor_o     (out_d[1 +: 32]),
    .tile_rdepth_o     (out_d[33 +: DEPTH_BITS]),
    .tile_rcov_o       (out_d[33 + DEPTH_BITS +: CovW]),
    .tile_rpeel_o      (out_d[33 + DEPTH_BITS + CovW +: DEPTH_BITS]),
    .busy_o            (out_d[33 + 2 * DEPTH_BITS + CovW]),
    .cnt_clear_i       (in_q[InW-1]),
    .cnt_frag_in_o     (out_d[OutW - 9 * CNT_W +: CNT_W]),
    .cnt_frag_passed_o (out_d[OutW - 8 * CNT_W +: CNT_W]),
    .cnt_frag_killed_o (out_d[OutW - 7 * CNT_W +: CNT_W]),
    .cnt_depth_reads_o (out_d[OutW - 6 * CNT_W +: CNT_W]),
    .cnt_depth_writes_o(out_d[OutW - 5 * CNT_W +: CNT_W]),
    .cnt_color_reads_o (out_d[OutW - 4 * CNT_W +: CNT_W]),
    .cnt_color_writes_o(out_d[OutW - 3 * CNT_W +: CNT_W]),
    .cnt_stall_cycles_o(out_d[OutW - 2 * CNT_W +: CNT_W]),
    .cnt_cycles_o      (out_d[OutW - 1 * CNT_W +: CNT_W])
  );

  logic [OutW-1:0]     out_q;
  logic [X1W*Grp-1:0]  out_pad;
  logic [X1W-1:0]      x1_q;
  logic                sout_q;

  assign out_pad = {{(X1W * Grp - OutW){1'b0}}, out_q};

  always_ff @(posedge clk_i) begin
    out_q <= out_d;
    for (int unsigned i = 0; i < X1W; i++) begin
      x1_q[i] <= ^out_pad[i*Grp +: Grp];
    end
    sout_q <= ^x1_q;
  end

  assign sout_o = sout_q;

endmodule
