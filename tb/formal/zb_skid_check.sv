// Formal (docs/formal.md, group skid): zb_input's I and S registers are a two-entry FIFO
// under any hold (stall_i, the tile port) and any take (the issue window's back-pressure):
// every accepted fragment leaves I once, unchanged, in order; frag_ready_o is high exactly when
// nothing holds the stream and S is empty, so no accept meets a full skid. A reference FIFO in
// this harness is the specification; its entries equal I and S (the taps), so 1-induction
// closes. The DUT's assertion ReadyIsSkidEmpty is restated here. Conditions are written as
// implications, not `if (c) assert`: yosys 0.23 gave such an enable the wrong value when c is
// a tap (docs/formal.md "Engines").
module zb_skid_check #(
  parameter int unsigned DEPTH_BITS  = 8,
  parameter int unsigned TILE_W      = 4,
  parameter int unsigned TILE_H      = 4,
  parameter int unsigned COV_SAMPLES = 4
) (
  input logic                  clk_i,
  input logic                  rst_ni,
  input logic                  frag_valid_i,
  input logic [15:0]           frag_x_i,
  input logic [15:0]           frag_y_i,
  input logic [DEPTH_BITS-1:0] frag_z_i,
  input logic [31:0]           frag_rgba_i,
  input logic [$clog2(COV_SAMPLES + 1)-1:0] frag_cov_i,
  input logic [15:0]           tile_x0_i,
  input logic [15:0]           tile_y0_i,
  input logic                  hold_i,
  input logic                  take_i
);
  localparam int unsigned AddrW = $clog2(TILE_W * TILE_H);
  localparam int unsigned XW    = $clog2(TILE_W);
  localparam int unsigned YW    = $clog2(TILE_H);
  localparam int unsigned CovW  = $clog2(COV_SAMPLES + 1);
  localparam int unsigned FragW = AddrW + DEPTH_BITS + 32 + CovW;  // {addr, z, rgba, cov}

  logic                  frag_ready, i_valid, busy;
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
  ) dut (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .frag_valid_i(frag_valid_i),
    .frag_ready_o(frag_ready),
    .frag_x_i    (frag_x_i),
    .frag_y_i    (frag_y_i),
    .frag_z_i    (frag_z_i),
    .frag_rgba_i (frag_rgba_i),
    .frag_cov_i  (frag_cov_i),
    .tile_x0_i   (tile_x0_i),
    .tile_y0_i   (tile_y0_i),
    .hold_i      (hold_i),
    .take_i      (take_i),
    .i_valid_o   (i_valid),
    .i_addr_o    (i_addr),
    .i_a3_o      (i_a3),
    .i_z_o       (i_z),
    .i_rgba_o    (i_rgba),
    .i_cov_o     (i_cov),
    .busy_o      (busy)
  );

  // Taps (scripts/formal.sh connects them after flattening): the skid register.
  // formal-tap: tap_s_valid dut.s_valid_q
  // formal-tap: tap_in_ready dut.in_ready_q
  // formal-tap: tap_s_addr dut.s_addr_q
  // formal-tap: tap_s_z dut.s_z_q
  // formal-tap: tap_s_rgba dut.s_rgba_q
  // formal-tap: tap_s_cov dut.s_cov_q
  logic                  tap_s_valid, tap_in_ready;
  logic [AddrW-1:0]      tap_s_addr;
  logic [DEPTH_BITS-1:0] tap_s_z;
  logic [31:0]           tap_s_rgba;
  logic [CovW-1:0]       tap_s_cov;

  // Reset in the first cycle only (rst_ni is asynchronous; the flow makes it synchronous).
  logic first_q = 1'b1;
  always_ff @(posedge clk_i) first_q <= 1'b0;
  always_comb begin
    ResetFirstCycle: assume (rst_ni == !first_q);
  end

  // The reference FIFO: the accepted fragments, tile-local address formed as docs/rtl.md
  // states it ({y - y0, x - x0}), not yet handed to the window.
  logic              accept, leave;
  logic [15:0]       dx, dy;
  logic [FragW-1:0]  in_frag, head, ref0_q, ref1_q;
  logic [1:0]        ref_n_q;
  assign accept  = frag_valid_i && frag_ready;
  assign leave   = i_valid && take_i;
  assign dx      = frag_x_i - tile_x0_i;
  assign dy      = frag_y_i - tile_y0_i;
  assign in_frag = {dy[YW-1:0], dx[XW-1:0], frag_z_i, frag_rgba_i, frag_cov_i};
  assign head    = {i_addr, i_z, i_rgba, i_cov};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ref_n_q <= 2'd0;
    end else begin
      ref_n_q <= ref_n_q + 2'(accept) - 2'(leave);
    end
  end
  // A push goes behind the entries that stay; a pop shifts ref1 into ref0.
  logic [1:0] stay;
  assign stay = ref_n_q - 2'(leave);
  always_ff @(posedge clk_i) begin
    if (leave) ref0_q <= ref1_q;
    if (accept && stay == 2'd0) ref0_q <= in_frag;
    if (accept && stay == 2'd1) ref1_q <= in_frag;
  end

  always_comb begin
    if (rst_ni) begin
      // Valid/ready: nothing is accepted while the stream is held; otherwise exactly when S
      // is empty, i.e. the FIFO has room (so no accept is dropped, and none refused with room).
      ReadyHonoursHold: assert (!(hold_i && frag_ready));
      ReadyIsRoom: assert (frag_ready == (!hold_i && ref_n_q != 2'd2));
      ReadyIsSkidEmpty: assert (tap_in_ready == !tap_s_valid);
      // I holds the oldest fragment not yet taken, unchanged; busy while any is held.
      FifoNeverOver: assert (ref_n_q <= 2'd2);
      ValidIsNotEmpty: assert (i_valid == (ref_n_q != 2'd0));
      BusyIsNotEmpty: assert (busy == (ref_n_q != 2'd0));
      HeadIsOldest: assert (!i_valid || head == ref0_q);
      A3IsThreeA: assert (!i_valid || i_a3 == 10'(3 * i_rgba[31:24]));
      // S holds the second (induction strengthening, stated on the taps).
      SkidIsSecond: assert (tap_s_valid == (ref_n_q == 2'd2));
      SkidHoldsSecond: assert (!tap_s_valid ||
                               {tap_s_addr, tap_s_z, tap_s_rgba, tap_s_cov} == ref1_q);
    end
  end

  always_comb begin
    if (rst_ni) begin
      SkidTaken: cover (accept && i_valid && !take_i);
      SkidFullHeld: cover (tap_s_valid && !take_i && frag_valid_i);
    end
  end
endmodule
