// zb_issue_window: the issue window in front of zb_rop's datapath (docs/rtl.md "Issue window").
//
// WINDOW slots hold fragments between the input register I and M. Each cycle the window picks
// its oldest fragment whose pixel is free; the pick is registered (stage K, pick_q), its slot's
// fragment goes to M at the next edge, and M issues it (the plane reads): two cycles after the
// pick. A pixel is free when none of K, M, X1..X(SPAN-3) has it: a fragment issues at least
// SPAN cycles after the last one to its pixel, so its reads see every older write
// (zb_rop's forwarding and bypass). So a fragment to a busy pixel no longer holds back the
// fragments behind it, and per-pixel order holds without a check of its own: fragments to one
// pixel see the same pipeline, so they are free together, and the oldest goes first (planes and
// counters stay those of the in-order golden model; PickInPixelOrder).
//
// Every decision comes from flops: per slot, hit_q (which of K, M, X1..X(SPAN-3) has its pixel,
// shifted as the pipeline moves), same_q (which slots hold an older fragment to its pixel: the
// pick among them enters M) and older_q (which slots are older). Addresses are compared only
// when a fragment enters, against the slots and the pipeline. The slots' data sit in a memory
// read at the pick (K is its read register), so the window holds addresses and relations in
// flops, not its fragments. A picked slot is refilled at the earliest at K's edge.
// A slot freed by a pick is reused from the next cycle: in_ready_o depends on flops only.
module zb_issue_window #(
  parameter int WINDOW = 8,    // slots, 2..16 (one slot would take only every other cycle)
  parameter int ADDR_W = 12,
  parameter int DATA_W = 64,
  parameter int SPAN   = 4     // same-pixel issue distance, >= 3 (P0 = K, P1 = M)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // From I: a fragment and its tile address; taken when in_valid_i && in_ready_o.
  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  logic [ADDR_W-1:0]   in_addr_i,
  input  logic [DATA_W-1:0]   in_data_i,
  // The pipeline after the window: P1 = M (issuing now), P2..P(SPAN-2) = X1..X(SPAN-3).
  input  logic [SPAN-3:0]     pos_valid_i,      // P(k+1) at [k]
  input  logic [(SPAN-2)*ADDR_W-1:0] pos_addr_i,   // P(k+1) at [k*ADDR_W +: ADDR_W]
  // K: last cycle's pick; M takes it at this edge.
  output logic                pick_valid_o,
  output logic [ADDR_W-1:0]   pick_addr_o,
  output logic [DATA_W-1:0]   pick_data_o,
  output logic                busy_o
);

  localparam int HitW = SPAN - 1;

`ifndef SYNTHESIS
  if (WINDOW < 2 || WINDOW > 16) begin : g_bad_window
    `ZB_PARAM_ERROR("zb_issue_window: WINDOW must be 2..16");
  end
  if (SPAN < 3) begin : g_bad_span
    `ZB_PARAM_ERROR("zb_issue_window: SPAN must be at least 3");
  end
`endif

  // Per slot i, flattened (Yosys 0.23 reads no packed arrays of vectors): slot i's field at
  // [i*W +: W]. hit[i][k]: P_k has slot i's pixel; same[i][j]: slot j is older and has slot i's
  // pixel; older[i][j]: slot j is older than slot i.
  logic [WINDOW-1:0]             valid_d, valid_q;
  logic [WINDOW*ADDR_W-1:0]      addr_d, addr_q;
  logic [WINDOW*HitW-1:0]        hit_d, hit_q;
  logic [WINDOW*WINDOW-1:0]      same_d, same_q;
  logic [WINDOW*WINDOW-1:0]      older_d, older_q;

  // ---------------------------------------------------------------------------------------
  // Pick: the oldest slot whose pixel is free; K registers it.
  // ---------------------------------------------------------------------------------------
  logic [WINDOW-1:0] ready, pick, pick_q;
  logic              bug_early;  // ZB_INJECT_WINDOW_BUG

`ifdef ZB_INJECT_WINDOW_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_window: a fragment that
  // enters as the window picks one to its pixel misses it, so it may issue a cycle later
  // instead of SPAN cycles later.
  initial bug_early = $test$plusargs("zb_bug_window") != 0;
`else
  assign bug_early = 1'b0;
`endif

  always_comb begin
    for (int unsigned i = 0; i < WINDOW; i++) begin
      ready[i] = valid_q[i] & ~|hit_q[i*HitW +: HitW];
    end
    for (int unsigned i = 0; i < WINDOW; i++) begin
      pick[i] = ready[i] & ~|(ready & older_q[i*WINDOW +: WINDOW]);
    end
  end

  // K: the slot picked last cycle, still holding its fragment.
  always_comb begin
    pick_addr_o = '0;
    for (int unsigned i = 0; i < WINDOW; i++) begin
      pick_addr_o |= pick_q[i] ? addr_q[i*ADDR_W +: ADDR_W] : '0;
    end
  end
  assign pick_valid_o = |pick_q;

  // ---------------------------------------------------------------------------------------
  // Take: I's fragment goes to the lowest free slot, with its relations to the slots and the
  // pipeline as they will be at the next edge.
  // ---------------------------------------------------------------------------------------
  logic [WINDOW-1:0] free, ins, eq, eq_k;
  logic              take;

  assign free       = ~valid_q;
  assign in_ready_o = |free;
  assign take       = in_valid_i & in_ready_o;

  always_comb begin
    ins = '0;
    for (int i = WINDOW - 1; i >= 0; i--) begin
      if (free[i]) ins = WINDOW'(1) << i;
    end
    for (int unsigned j = 0; j < WINDOW; j++) begin
      eq_k[j] = addr_q[j*ADDR_W +: ADDR_W] == in_addr_i;  // K's slot: still its address
      eq[j]   = valid_q[j] & eq_k[j];
    end
  end

  always_comb begin
    valid_d = valid_q & ~pick;
    addr_d  = addr_q;
    for (int unsigned i = 0; i < WINDOW; i++) begin
      // The pipeline moves on: P_k's fragment is P_(k+1)'s next cycle; the pick enters P0.
      hit_d[i*HitW +: HitW]       = {hit_q[i*HitW +: HitW-1], |(pick & same_q[i*WINDOW +: WINDOW])};
      same_d[i*WINDOW +: WINDOW]  = same_q[i*WINDOW +: WINDOW] & ~pick;
      older_d[i*WINDOW +: WINDOW] = older_q[i*WINDOW +: WINDOW] & ~pick;
      if (take && ins[i]) begin
        valid_d[i]                  = 1'b1;
        addr_d[i*ADDR_W +: ADDR_W]  = in_addr_i;
        hit_d[i*HitW]               = |(pick & eq) & ~bug_early;   // the pick: K next
        hit_d[i*HitW + 1]           = |(pick_q & eq_k);            // K: M next
        for (int unsigned k = 2; k < HitW; k++) begin
          hit_d[i*HitW + k] = pos_valid_i[k-2] & (pos_addr_i[(k-2)*ADDR_W +: ADDR_W] == in_addr_i);
        end
        same_d[i*WINDOW +: WINDOW]  = eq & ~pick;
        older_d[i*WINDOW +: WINDOW] = valid_q & ~pick;
      end
    end
  end

  assign busy_o = |valid_q | |pick_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= '0;
      pick_q  <= '0;
      hit_q   <= '0;
      same_q  <= '0;
      older_q <= '0;
    end else begin
      valid_q <= valid_d;
      pick_q  <= pick;
      hit_q   <= hit_d;
      same_q  <= same_d;
      older_q <= older_d;
    end
  end

  always_ff @(posedge clk_i) begin
    addr_q <= addr_d;
  end

  // The slots' fragments (all but the address) in a memory: written at the take, read at the
  // pick, so K's fragment is the read register (a block RAM on an FPGA: no slot flops, no mux).
  // It reads every cycle (an enable from the pick would lengthen the pick's path); M takes the
  // word only after a pick, and a pick never reads the slot being written (taken slots are free).
  localparam int SlotW = $clog2(WINDOW);
  logic [SlotW-1:0] ins_slot, pick_slot;
  always_comb begin
    ins_slot  = '0;
    pick_slot = '0;
    for (int unsigned i = 0; i < WINDOW; i++) begin
      ins_slot  |= ins[i] ? SlotW'(i) : '0;
      pick_slot |= pick[i] ? SlotW'(i) : '0;
    end
  end
  zb_tile_mem #(
    .WIDTH(DATA_W),
    .WORDS(WINDOW)
  ) u_data (
    .clk_i  (clk_i),
    .re_i   (1'b1),
    .raddr_i(pick_slot),
    .rdata_o(pick_data_o),
    .we_i   (take),
    .waddr_i(ins_slot),
    .wdata_i(in_data_i)
  );

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // The relations the pick trusts, stated on addresses: hit_q and same_q are exact for every
  // occupied slot, and older_q orders the occupied slots totally.
  for (genvar i = 0; i < WINDOW; i++) begin : g_slot
    HitExactK: assert property (@(posedge clk_i) disable iff (!rst_ni)
        valid_q[i] |-> (hit_q[i*HitW] == (|pick_q && pick_addr_o == slot_addr(i))));
    for (genvar k = 1; k < HitW; k++) begin : g_hit
      HitExact: assert property (@(posedge clk_i) disable iff (!rst_ni)
          valid_q[i] |-> (hit_q[i*HitW + k] ==
                          (pos_valid_i[k-1] && pos_addr_i[(k-1)*ADDR_W +: ADDR_W] == slot_addr(i))));
    end
    // Per-pixel order: a pick has no older fragment to its pixel in the window.
    PickInPixelOrder: assert property (@(posedge clk_i) disable iff (!rst_ni)
        pick[i] |-> !(|(valid_q & older_q[i*WINDOW +: WINDOW] & eq_addr(i))));
    // Reorder: a fragment issues past an older one that waits for its pixel.
    PickPastOlder: cover property (@(posedge clk_i) disable iff (!rst_ni)
        pick[i] && |(valid_q & older_q[i*WINDOW +: WINDOW]));
  end
  // Pairs of occupied slots, checked in one assertion each (one evaluation per cycle, not
  // WINDOW^2): same_q is exact, and older_q orders the slots totally.
  SameExact: assert property (@(posedge clk_i) disable iff (!rst_ni) same_exact());
  AgeOrder: assert property (@(posedge clk_i) disable iff (!rst_ni) age_order());
  // The window fills (the stream waits for pixels, not for a full pipeline).
  WindowFull: cover property (@(posedge clk_i) disable iff (!rst_ni) &valid_q);
  OnePick: assert property (@(posedge clk_i) disable iff (!rst_ni) $onehot0(pick));
  // K's slot is not refilled before M takes its fragment.
  PickedSlotHeld: assert property (@(posedge clk_i) disable iff (!rst_ni)
      |pick_q |-> (pick_q & valid_q) == '0);

  function automatic logic same_exact();
    same_exact = 1'b1;
    for (int unsigned i = 0; i < WINDOW; i++) begin
      for (int unsigned j = 0; j < WINDOW; j++) begin
        if (valid_q[i] && i != j &&
            same_q[i*WINDOW + j] != (valid_q[j] && older_q[i*WINDOW + j] &&
                                     slot_addr(j) == slot_addr(i))) begin
          same_exact = 1'b0;
        end
      end
    end
  endfunction
  function automatic logic age_order();
    age_order = 1'b1;
    for (int unsigned i = 0; i < WINDOW; i++) begin
      for (int unsigned j = 0; j < WINDOW; j++) begin
        if (valid_q[i] && valid_q[j] && i != j &&
            older_q[i*WINDOW + j] == older_q[j*WINDOW + i]) begin
          age_order = 1'b0;
        end
      end
    end
  endfunction
  function automatic logic [ADDR_W-1:0] slot_addr(int unsigned i);
    slot_addr = addr_q[i*ADDR_W +: ADDR_W];
  endfunction
  function automatic logic [WINDOW-1:0] eq_addr(int unsigned i);
    for (int unsigned j = 0; j < WINDOW; j++) begin
      eq_addr[j] = slot_addr(j) == slot_addr(i);
    end
  endfunction
`endif
`endif

endmodule
