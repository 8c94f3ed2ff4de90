// Formal (docs/formal.md, group window): zb_issue_window's bookkeeping, by k-induction, with the
// pipeline after it modelled here as zb_rop builds it (M takes the pick, X1 takes M). The RTL's
// own assertions (HitExactK, HitExact, SameExact, AgeOrder, PickInPixelOrder, OnePick,
// PickedSlotHeld), which yosys 0.23 does not read, restated on taps: the hit bits are exactly
// the address comparisons they stand for, the same-pixel and age bits exact, and no pick has an
// older fragment to its pixel in the window, so fragments to one pixel issue in arrival order
// (no reorder within a pixel) at least SPAN cycles apart (the interlock zb_rop's forwarding
// relies on).
module zb_window_check #(
  parameter int unsigned WINDOW = 2,
  parameter int unsigned ADDR_W = 2,
  parameter int unsigned DATA_W = 4,
  parameter int unsigned SPAN   = 4
) (
  input logic              clk_i,
  input logic              rst_ni,
  input logic              in_valid_i,
  input logic [ADDR_W-1:0] in_addr_i,
  input logic [DATA_W-1:0] in_data_i
);
  localparam int unsigned HitW = SPAN - 1;

  logic                       in_ready, pick_valid, busy;
  logic [ADDR_W-1:0]          pick_addr;
  logic [DATA_W-1:0]          pick_data;
  logic [SPAN-3:0]            pos_valid;
  logic [(SPAN-2)*ADDR_W-1:0] pos_addr;

  zb_issue_window #(
    .WINDOW(WINDOW),
    .ADDR_W(ADDR_W),
    .DATA_W(DATA_W),
    .SPAN  (SPAN)
  ) dut (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .in_valid_i  (in_valid_i),
    .in_ready_o  (in_ready),
    .in_addr_i   (in_addr_i),
    .in_data_i   (in_data_i),
    .pos_valid_i (pos_valid),
    .pos_addr_i  (pos_addr),
    .pick_valid_o(pick_valid),
    .pick_addr_o (pick_addr),
    .pick_data_o (pick_data),
    .busy_o      (busy)
  );

  // formal-tap: tap_valid dut.valid_q
  // formal-tap: tap_addr dut.addr_q
  // formal-tap: tap_hit dut.hit_q
  // formal-tap: tap_same dut.same_q
  // formal-tap: tap_older dut.older_q
  // formal-tap: tap_pick dut.pick
  // formal-tap: tap_pick_q dut.pick_q
  logic [WINDOW-1:0]        tap_valid, tap_pick, tap_pick_q;
  logic [WINDOW*ADDR_W-1:0] tap_addr;
  logic [WINDOW*HitW-1:0]   tap_hit;
  logic [WINDOW*WINDOW-1:0] tap_same, tap_older;

  logic first_q = 1'b1;
  always_ff @(posedge clk_i) first_q <= 1'b0;
  always_comb begin
    ResetFirstCycle: assume (rst_ni == !first_q);
  end

  // The pipeline after the window, as zb_rop has it: P1 = M (last cycle's pick), P2 = X1, ...
  logic [SPAN-3:0]            pv_q;
  logic [(SPAN-2)*ADDR_W-1:0] pa_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) pv_q <= '0;
    else         pv_q <= {pv_q[SPAN-4:0], pick_valid};
  end
  always_ff @(posedge clk_i) pa_q <= {pa_q[(SPAN-3)*ADDR_W-1:0], pick_addr};
  assign pos_valid = pv_q;
  assign pos_addr  = pa_q;

  // Per slot i (and pair i, j) the relations the pick trusts, as continuous assignments
  // (yosys 0.23's proc left comparison wires undriven in the looped always_comb form).
  logic [WINDOW-1:0]        hit_ok, free_ok;
  logic [WINDOW*WINDOW-1:0] same_ok, age_ok, order_ok, clean_ok;
  logic [WINDOW*WINDOW*WINDOW-1:0] trans_ok;
  for (genvar i = 0; i < WINDOW; i++) begin : g_slot
    logic [ADDR_W-1:0] a;
    logic [HitW-1:0]   hit_exp;
    logic [SPAN-3:0]   pos_eq;
    assign a = tap_addr[i*ADDR_W +: ADDR_W];
    assign hit_exp[0] = |tap_pick_q && pick_addr == a;
    for (genvar k = 1; k < HitW; k++) begin : g_hit
      assign hit_exp[k] = pos_valid[k-1] && pos_addr[(k-1)*ADDR_W +: ADDR_W] == a;
    end
    for (genvar k = 0; k < SPAN - 2; k++) begin : g_pos
      assign pos_eq[k] = pos_valid[k] && pos_addr[k*ADDR_W +: ADDR_W] == a;
    end
    assign hit_ok[i]  = !tap_valid[i] || tap_hit[i*HitW +: HitW] == hit_exp;
    // A pick's pixel is in none of K, M, X1: it issues SPAN cycles after the last to it.
    assign free_ok[i] = !tap_pick[i] || !(hit_exp[0] || |pos_eq);
    for (genvar j = 0; j < WINDOW; j++) begin : g_pair
      logic same_px;
      assign same_px = tap_addr[j*ADDR_W +: ADDR_W] == a;
      assign same_ok[i*WINDOW + j] = !tap_valid[i] || i == j ||
          tap_same[i*WINDOW + j] == (tap_valid[j] && tap_older[i*WINDOW + j] && same_px);
      assign age_ok[i*WINDOW + j] = !(tap_valid[i] && tap_valid[j]) || i == j ||
          tap_older[i*WINDOW + j] != tap_older[j*WINDOW + i];
      assign order_ok[i*WINDOW + j] = !(tap_pick[i] && tap_valid[j] &&
                                        tap_older[i*WINDOW + j] && same_px);
      // Induction strengthening: an occupied slot relates to no empty one, and "older" is
      // transitive (so a fragment entering a freed slot is younger than every other).
      assign clean_ok[i*WINDOW + j] = !(tap_valid[i] && !tap_valid[j]) ||
          !(tap_older[i*WINDOW + j] || tap_same[i*WINDOW + j]);
      for (genvar k = 0; k < WINDOW; k++) begin : g_trans
        assign trans_ok[(i*WINDOW + j)*WINDOW + k] = !(tap_valid[i] && tap_valid[j] &&
            tap_valid[k] && tap_older[i*WINDOW + j] && tap_older[j*WINDOW + k]) ||
            tap_older[i*WINDOW + k];
      end
    end
  end

  always_comb begin
    if (rst_ni) begin
      HitExact: assert (&hit_ok);
      SameExact: assert (&same_ok);
      AgeOrder: assert (&age_ok);
      PickInPixelOrder: assert (&order_ok);
      OnePick: assert ($onehot0(tap_pick));
      PickedSlotHeld: assert ((tap_pick_q & tap_valid) == '0 || tap_pick_q == '0);
      PickPixelFree: assert (&free_ok);
      NoStaleRelation: assert (&clean_ok);
      AgeTransitive: assert (&trans_ok);
    end
  end
endmodule
