// zb_layers_insert: mlab-K's insert and merge (docs/datapath.md "8. Layers"), X8..X11 of
// zb_layers: the pixel's newest layers word (X7, zb_forward's) and the fragment's layer in, the
// word to write out at X11. A pure pipeline: no state but its stages, so its property (the
// layers stay sorted, occupied first, at most K) is proven on it alone (tb/formal).
//   X8   per slot: occupied and not after the fragment (le); the three products a merge may need
//        on zb_mul8 (stage 1): f under slot K-1, slot K-1 under f, slot K-1 under slot K-2
//   X9   the word with the fragment inserted (its slot K-1 the merge's front when K are full);
//        products, stage 2
//   X10  m of the product the insert chose, added to the front, saturated: slot K-1 merged
//   X11  the word's flops drive the write data (and zb_forward's bypass), no logic after them
module zb_layers_insert #(
  parameter int DEPTH_BITS = 24,
  parameter int LAYERS     = 4,
  localparam int LW        = DEPTH_BITS + 32,  // a layer {z, A, R, G, B}
  localparam int WW        = LAYERS * LW
) (
  input  logic          clk_i,
  input  logic          rst_ni,     // the assertions' and covers' only
  input  logic [3:0]    kk_i,       // K, 1..LAYERS, constant during a pass
  input  logic [WW-1:0] x7_word_i,  // the pixel's layers, sorted, at most K
  input  logic [LW-1:0] x8_f_i,     // the fragment's layer {z, a, m(r, a), m(g, a), m(b, a)}
  input  logic          we_i,       // X11: the word is written (assertions, covers)
  output logic [WW-1:0] x11_word_o
);

  localparam int L = LAYERS;

  // ---------------------------------------------------------------------------------------
  // X8: where the fragment goes; the merge's products.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x8_word_q;
  always_ff @(posedge clk_i) begin
    x8_word_q <= x7_word_i;
  end

  function automatic logic [LW-1:0] slot(logic [WW-1:0] w, int unsigned j);
    slot = w[j*LW +: LW];
  endfunction
  function automatic logic [7:0] slot_a(logic [WW-1:0] w, int unsigned j);
    slot_a = w[j*LW + 24 +: 8];
  endfunction

  logic [L-1:0]  x8_le;      // slot j occupied and not after the fragment
  logic [31:0]   x8_last;  // slot K-1's colour
  logic [7:0]    x8_prev;  // slot K-2's alpha (K-1's when K = 1)
  for (genvar j = 0; j < L; j++) begin : g_le
    assign x8_le[j] = (slot_a(x8_word_q, j) != 8'h00) && (slot(x8_word_q, j) <= x8_f_i);
  end
  always_comb begin
    x8_last = x8_word_q[31:0];
    x8_prev = x8_word_q[31:24];
    for (int unsigned j = 1; j < L; j++) begin
      if (4'(j) == kk_i - 4'd1) begin
        x8_last = x8_word_q[j*LW +: 32];
        x8_prev = slot_a(x8_word_q, j - 1);
      end
    end
  end

  // The three merges, b under f: per channel m(b_c, 255 - A_f), on zb_mul8 (k = 255 - A_f).
  //   0: the fragment under slot K-1;  1: slot K-1 under the fragment;  2: slot K-1 under K-2.
  logic [3*4*16-1:0] x10_t;
  for (genvar g = 0; g < 3; g++) begin : g_merge
    logic [7:0]  inv;
    logic [9:0]  inv3;
    logic [31:0] back;
    assign inv  = 8'hff - (g == 0 ? x8_last[31:24] : g == 1 ? x8_f_i[31:24] : x8_prev);
    assign inv3 = {2'b00, inv} + {1'b0, inv, 1'b0};
    assign back = g == 0 ? x8_f_i[31:0] : x8_last;
    for (genvar c = 0; c < 4; c++) begin : g_chan
      zb_mul8 u_mul (
        .clk_i(clk_i),
        .k_i  (inv),
        .k3_i (inv3),
        .v_i  (back[8*c +: 8]),
        .t_o  (x10_t[16*(4*g + c) +: 16])
      );
    end
  end

  // ---------------------------------------------------------------------------------------
  // X9: the word with the fragment inserted; slot K-1 is the merge's front when K were full.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x9_word_d, x9_word_q, x10_word_q;
  logic          x8_f_iull, x8_insert;
  logic [1:0]    x8_pick;  // which merge
  logic          x9_merge_q, x10_merge_q;
  logic [1:0]    x9_pick_q, x10_pick_q;
  logic [3:0]    x9_kk_q, x10_kk_q;

  always_comb begin
    x8_f_iull   = 1'b0;
    x8_pick   = 2'd2;
    x8_insert = x8_f_i[31:24] != 8'h00;
    for (int unsigned j = 0; j < L; j++) begin
      if (4'(j) == kk_i - 4'd1) begin
        x8_f_iull = slot_a(x8_word_q, j) != 8'h00;
        if (x8_le[j]) x8_pick = 2'd0;
        else if (j == 0 || x8_le[j == 0 ? 0 : j - 1]) x8_pick = 2'd1;
      end
    end
    for (int unsigned j = 0; j < L; j++) begin
      if (!x8_insert || (x8_f_iull && 4'(j) >= kk_i) || x8_le[j]) begin
        x9_word_d[j*LW +: LW] = slot(x8_word_q, j);
      end else if (j == 0 || x8_le[j == 0 ? 0 : j - 1]) begin
        x9_word_d[j*LW +: LW] = x8_f_i;
      end else begin
        x9_word_d[j*LW +: LW] = slot(x8_word_q, j == 0 ? 0 : j - 1);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    x9_word_q   <= x9_word_d;
    x9_merge_q  <= x8_insert & x8_f_iull;
    x9_pick_q   <= x8_pick;
    x9_kk_q     <= kk_i;
    x10_word_q  <= x9_word_q;
    x10_merge_q <= x9_merge_q;
    x10_pick_q  <= x9_pick_q;
    x10_kk_q    <= x9_kk_q;
  end

  // ---------------------------------------------------------------------------------------
  // X10: slot K-1 := front + m(back, 255 - A_front), saturated, the front's depth.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x11_word_d, x11_word_q;
  logic [LW-1:0] x10_front;
  logic [15:0]   x10_tc;
  logic [9:0]    x10_u;
  logic [8:0]    x10_sum;
  logic [7:0]    x10_m;
  logic [7:0]    unused_u;
  logic [3:0]    x10_sat;  // a merge's channel saturated (the coverage plan's)
  assign unused_u = x10_u[7:0];
  always_comb begin
    x11_word_d = x10_word_q;
    x10_front  = '0;
    x10_tc     = '0;
    x10_u      = '0;
    x10_m      = '0;
    x10_sum    = '0;
    x10_sat    = '0;
    for (int unsigned j = 0; j < L; j++) begin
      if (x10_merge_q && 4'(j) == x10_kk_q - 4'd1) begin
        x10_front = slot(x10_word_q, j);
        for (int unsigned c = 0; c < 4; c++) begin
          // m(x, y) = (t + (t >> 8) + 0x80) >> 8 = t[15:8] + ((t[7:0] + t[15:8] + 0x80) >> 8)
          x10_tc  = x10_t[16*(4*32'(x10_pick_q) + c) +: 16];
          x10_u   = {2'b00, x10_tc[7:0]} + {2'b00, x10_tc[15:8]} + 10'h080;
          x10_m   = x10_tc[15:8] + {6'h00, x10_u[9:8]};
          x10_sum = {1'b0, x10_front[8*c +: 8]} + {1'b0, x10_m};
          x11_word_d[j*LW + 8*c +: 8] = x10_sum[8] ? 8'hff : x10_sum[7:0];
          x10_sat[c] = x10_sum[8];
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    x11_word_q <= x11_word_d;
  end


  assign x11_word_o = x11_word_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  // The coverage plan's layers bins (tb/cov/coverage_plan.json "layers_*"), sampled with each
  // fragment's layers write: where it went, whether the pixel was full, equal keys, K in use.
  logic [3:0] x8_pos;
  logic       x8_eq_z, x8_eq_key;
  always_comb begin
    x8_pos    = '0;
    x8_eq_z   = 1'b0;
    x8_eq_key = 1'b0;
    for (int unsigned j = 0; j < L; j++) begin
      x8_pos = x8_pos + 4'(x8_le[j]);
      if (slot_a(x8_word_q, j) != 8'h00 && x8_word_q[j*LW + 32 +: DEPTH_BITS] == x8_f_i[LW-1:32])
      begin
        x8_eq_z = 1'b1;
        if (slot(x8_word_q, j) == x8_f_i) x8_eq_key = 1'b1;
      end
    end
  end
  logic [3:0] cov_pos_q [9:11];
  logic       cov_full_q [9:11], cov_ins_q [9:11], cov_eqz_q [9:11], cov_eqk_q [9:11];
  always_ff @(posedge clk_i) begin
    cov_pos_q[9]  <= x8_pos;
    cov_full_q[9] <= x8_f_iull;
    cov_ins_q[9]  <= x8_insert;
    cov_eqz_q[9]  <= x8_eq_z;
    cov_eqk_q[9]  <= x8_eq_key;
    for (int unsigned k = 10; k <= 11; k++) begin
      cov_pos_q[k]  <= cov_pos_q[k-1];
      cov_full_q[k] <= cov_full_q[k-1];
      cov_ins_q[k]  <= cov_ins_q[k-1];
      cov_eqz_q[k]  <= cov_eqz_q[k-1];
      cov_eqk_q[k]  <= cov_eqk_q[k-1];
    end
  end
  logic x11_ins;
  assign x11_ins = we_i && cov_ins_q[11];
  for (genvar p = 0; p <= L; p++) begin : g_pos
    for (genvar f = 0; f < 2; f++) begin : g_full
      LayersInsert: cover property (@(posedge clk_i) disable iff (!rst_ni)
          x11_ins && cov_pos_q[11] == 4'(p) && cov_full_q[11] == f[0]);
    end
  end
  for (genvar k = 0; k < L; k++) begin : g_k  // K = k + 1
    LayersFullAtK: cover property (@(posedge clk_i) disable iff (!rst_ni)
        x11_ins && cov_full_q[11] && kk_i == 4'(k + 1));
  end
  LayersEqualDepth: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x11_ins && cov_eqz_q[11] && !cov_eqk_q[11]);
  LayersEqualKey: cover property (@(posedge clk_i) disable iff (!rst_ni) x11_ins && cov_eqk_q[11]);
  LayersAlphaZero: cover property (@(posedge clk_i) disable iff (!rst_ni)
      we_i && !cov_ins_q[11]);
  for (genvar c = 0; c < 4; c++) begin : g_sat  // a merge's channel saturating
    LayersMergeSaturates: cover property (@(posedge clk_i) disable iff (!rst_ni) x10_sat[c]);
  end

  logic [3:0] x11_kk_q;  // the K of the fragment in X11
  always_ff @(posedge clk_i) begin
    x11_kk_q <= x10_kk_q;
  end
  // Every write keeps the layers in order, occupied slots first, at most K of them.
  logic          x11_sorted;
  always_comb begin
    x11_sorted = 1'b1;
    for (int unsigned j = 1; j < L; j++) begin
      if (slot_a(x11_word_q, j) != 8'h00 &&
          (slot_a(x11_word_q, j - 1) == 8'h00 ||
           slot(x11_word_q, j) < slot(x11_word_q, j - 1))) begin
        x11_sorted = 1'b0;
      end
      if (4'(j) >= x11_kk_q && slot_a(x11_word_q, j) != 8'h00) x11_sorted = 1'b0;
    end
  end
  LayersSorted: assert property (@(posedge clk_i) disable iff (!rst_ni)
      we_i |-> x11_sorted);
  LayersMerge: cover property (@(posedge clk_i) disable iff (!rst_ni)
      we_i && $past(x10_merge_q));
`endif
`endif

endmodule
