// zb_rop's issue window, restated inside a zb_rop harness (after `zb_rop_dut.svh`, rst_ni
// as the harness drives it): the window group's invariants (tb/formal/zb_window_check.sv) on the
// real pipeline (P1 = M, P2 = X1). Induction over zb_rop needs them: a state with a wrong hit,
// same or age bit would issue a fragment too early or out of pixel order. They hold
// whatever the fragments, so the harnesses assert them, never assume them.
  localparam int unsigned WSpan = 4;   // zb_rop's Span
  localparam int unsigned WHitW = WSpan - 1;

  // formal-tap: tap_w_valid dut.u_window.valid_q
  // formal-tap: tap_w_addr dut.u_window.addr_q
  // formal-tap: tap_w_hit dut.u_window.hit_q
  // formal-tap: tap_w_same dut.u_window.same_q
  // formal-tap: tap_w_older dut.u_window.older_q
  // formal-tap: tap_w_pick dut.u_window.pick
  // formal-tap: tap_w_pick_q dut.u_window.pick_q
  // formal-tap: tap_k_addr dut.u_window.pick_addr_o
  // formal-tap: tap_w_pos_valid dut.u_window.pos_valid_i
  // formal-tap: tap_w_pos_addr dut.u_window.pos_addr_i
  logic [WINDOW-1:0]           tap_w_valid, tap_w_pick, tap_w_pick_q;
  logic [WINDOW*AddrW-1:0]     tap_w_addr;
  logic [WINDOW*WHitW-1:0]     tap_w_hit;
  logic [WINDOW*WINDOW-1:0]    tap_w_same, tap_w_older;
  logic [AddrW-1:0]            tap_k_addr;
  logic [WSpan-3:0]            tap_w_pos_valid;
  logic [(WSpan-2)*AddrW-1:0]  tap_w_pos_addr;

  logic [WINDOW-1:0]           w_hit_ok, w_free_ok;
  logic [WINDOW*WINDOW-1:0]    w_same_ok, w_age_ok, w_order_ok, w_clean_ok;
  logic [WINDOW*WINDOW*WINDOW-1:0] w_trans_ok;
  for (genvar i = 0; i < WINDOW; i++) begin : g_w_slot
    logic [AddrW-1:0] a;
    logic [WHitW-1:0] hit_exp;
    assign a = tap_w_addr[i*AddrW +: AddrW];
    assign hit_exp[0] = |tap_w_pick_q && tap_k_addr == a;
    for (genvar k = 1; k < WHitW; k++) begin : g_hit
      assign hit_exp[k] = tap_w_pos_valid[k-1] && tap_w_pos_addr[(k-1)*AddrW +: AddrW] == a;
    end
    assign w_hit_ok[i]  = !tap_w_valid[i] || tap_w_hit[i*WHitW +: WHitW] == hit_exp;
    assign w_free_ok[i] = !tap_w_pick[i] || hit_exp == '0;
    for (genvar j = 0; j < WINDOW; j++) begin : g_pair
      logic same_px;
      assign same_px = tap_w_addr[j*AddrW +: AddrW] == a;
      assign w_same_ok[i*WINDOW + j] = !tap_w_valid[i] || i == j ||
          tap_w_same[i*WINDOW + j] == (tap_w_valid[j] && tap_w_older[i*WINDOW + j] && same_px);
      assign w_age_ok[i*WINDOW + j] = !(tap_w_valid[i] && tap_w_valid[j]) || i == j ||
          tap_w_older[i*WINDOW + j] != tap_w_older[j*WINDOW + i];
      assign w_order_ok[i*WINDOW + j] = !(tap_w_pick[i] && tap_w_valid[j] &&
                                          tap_w_older[i*WINDOW + j] && same_px);
      assign w_clean_ok[i*WINDOW + j] = !(tap_w_valid[i] && !tap_w_valid[j]) ||
          !(tap_w_older[i*WINDOW + j] || tap_w_same[i*WINDOW + j]);
      for (genvar k = 0; k < WINDOW; k++) begin : g_trans
        assign w_trans_ok[(i*WINDOW + j)*WINDOW + k] = !(tap_w_valid[i] && tap_w_valid[j] &&
            tap_w_valid[k] && tap_w_older[i*WINDOW + j] && tap_w_older[j*WINDOW + k]) ||
            tap_w_older[i*WINDOW + k];
      end
    end
  end

  always_comb begin
    if (rst_ni) begin
      WinHitExact: assert (&w_hit_ok);
      WinSameExact: assert (&w_same_ok);
      WinAgeOrder: assert (&w_age_ok);
      WinPickInPixelOrder: assert (&w_order_ok);
      WinOnePick: assert ($onehot0(tap_w_pick));
      WinPickedSlotHeld: assert ((tap_w_pick_q & tap_w_valid) == '0 && $onehot0(tap_w_pick_q));
      WinPickPixelFree: assert (&w_free_ok);
      WinNoStaleRelation: assert (&w_clean_ok);
      WinAgeTransitive: assert (&w_trans_ok);
    end
  end
