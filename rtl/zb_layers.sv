// zb_layers: mlab-K's layers (docs/datapath.md "8. Layers"), X5..X11 beside zb_color, with the
// colour plane's timing. Its plane holds per pixel LAYERS slots, slot j at [j*LW +: LW], a
// layer {z, A, R, G, B} (B at bit 0): as a number, the order layers are kept in (nearer first,
// then the colour word), so one compare orders two layers. A = 0 is an empty slot; fast clear
// empties a pixel. The pass's K (1..LAYERS) is k_m1_i + 1. Read at E5, the newest word in X7
// (zb_forward), written at E11 in layers mode when the fragment passed and the mask is not 0.
// The plane never crosses the tile port: the port only fast-clears it, and a store's read with
// the resolve reads it for zb_resolve_layers (tile_rlayers_o).
//   X8   per slot: occupied and not after the fragment (le); the three products a merge may need
//        on zb_mul8 (stage 1): f under slot K-1, slot K-1 under f, slot K-1 under slot K-2
//   X9   the word with the fragment inserted (its slot K-1 the merge's front when K are full);
//        products, stage 2
//   X10  m of the product the insert chose, added to the front, saturated: slot K-1 merged
//   X11  the word's flops drive the write data (and zb_forward's bypass), no logic after them
module zb_layers #(
  parameter int WORDS      = 4096,
  parameter int BEAT       = 8,
  parameter int DEPTH_BITS = 24,
  parameter int LAYERS     = 4,
  localparam int LW        = DEPTH_BITS + 32,  // a layer
  localparam int WW        = LAYERS * LW       // a pixel's word
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  input  logic                            layers_mode_i,  // blend = layers
  input  logic [3:0]                      color_mask_i,
  input  logic [2:0]                      k_m1_i,         // K - 1
  // Tile port: fast clear (tile_en_i with tile_clear_i) and reads for the resolve.
  input  logic                            tile_req_i,
  input  logic                            tile_we_i,
  input  logic                            tile_clear_i,
  input  logic                            tile_en_i,
  input  logic [$clog2(WORDS / BEAT)-1:0] tile_addr_i,
  output logic [BEAT*WW-1:0]              tile_rlayers_o,
  // The pipeline.
  input  logic                            m_valid_i,
  input  logic [DEPTH_BITS-1:0]           m_z_i,
  input  logic                            x5_valid_i,
  input  logic                            x6_valid_i,
  input  logic                            x10_valid_i,
  input  logic                            x11_valid_i,
  input  logic [$clog2(WORDS)-1:0]        x5_addr_i,
  input  logic [$clog2(WORDS)-1:0]        x6_addr_i,
  input  logic [$clog2(WORDS)-1:0]        x10_addr_i,
  input  logic [$clog2(WORDS)-1:0]        x11_addr_i,
  input  logic                            x10_pass_i,
  input  logic                            x11_pass_i,
  input  logic [31:0]                     x5_p_i,         // {a, m(b, a), m(g, a), m(r, a)}
  // X11's write as the plane takes it, for zb_rop's retire port.
  output logic                            x11_lwe_o,
  output logic [WW-1:0]                   x11_wlayers_o
);

  localparam int L = LAYERS;

`ifndef SYNTHESIS
  if (LAYERS < 1 || LAYERS > 8) begin : g_bad_layers
    `ZB_PARAM_ERROR("zb_layers: LAYERS must be 1..8");
  end
`endif

  logic [WW-1:0] lmem_rdata, x7_word, x11_word_q;
  logic          layers_on, x10_lwe, x11_lwe;
  logic [3:0]    kk;  // K, at most LAYERS

  assign layers_on = layers_mode_i & (color_mask_i != 4'h0);
  assign x10_lwe   = x10_valid_i & x10_pass_i & layers_on;
  assign x11_lwe   = x11_valid_i & x11_pass_i & layers_on;
  assign kk        = ({1'b0, k_m1_i} >= 4'(L)) ? 4'(L) : {1'b0, k_m1_i} + 4'd1;

  zb_plane #(
    .WIDTH    (WW),
    .WORDS    (WORDS),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_layers_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (1'b0),              // never loaded
    .tile_en_i   (tile_en_i),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i('0),                // cleared empty
    .tile_rdata_o(tile_rlayers_o),
    .pipe_re_i   (x5_valid_i),
    .pipe_raddr_i(x5_addr_i),
    .pipe_we_i   (x11_lwe),
    .pipe_waddr_i(x11_addr_i),
    .pipe_wdata_i(x11_word_q),
    .rdata_o     (lmem_rdata)
  );

`ifdef ZB_INJECT_LAYERS_BUG
  // Deliberate defect for checker tests, on with the plusarg +zb_bug_layers: the bypass is never
  // taken, so a fragment issued Span cycles after one to its pixel inserts into the word before.
  logic bug_on, x10_lwe_fwd;
  initial bug_on = $test$plusargs("zb_bug_layers") != 0;
  assign x10_lwe_fwd = x10_lwe & ~bug_on;
`endif

  zb_forward #(
    .WIDTH (WW),
    .ADDR_W($clog2(WORDS))
  ) u_forward (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .x5_valid_i (x5_valid_i),
    .x6_valid_i (x6_valid_i),
    .x5_addr_i  (x5_addr_i),
    .x6_addr_i  (x6_addr_i),
    .x10_addr_i (x10_addr_i),
    .x11_addr_i (x11_addr_i),
`ifdef ZB_INJECT_LAYERS_BUG
    .x10_we_i   (x10_lwe_fwd),
`else
    .x10_we_i   (x10_lwe),
`endif
    .x11_we_i   (x11_lwe),
    .x11_wdata_i(x11_word_q),
    .x6_rdata_i (lmem_rdata),
    .x7_word_o  (x7_word)
  );

  // ---------------------------------------------------------------------------------------
  // The fragment's layer: z from M, p from zb_operands at X5, both to X8.
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] z_q [1:8];  // z_q[k]: the fragment in Xk
  logic [31:0]           p_q [6:8];
  always_ff @(posedge clk_i) begin
    z_q[1] <= m_z_i;
    for (int unsigned k = 2; k <= 8; k++) begin
      z_q[k] <= z_q[k-1];
    end
    p_q[6] <= x5_p_i;
    p_q[7] <= p_q[6];
    p_q[8] <= p_q[7];
  end
  logic unused_in;
  assign unused_in = ^{m_valid_i, tile_we_i};

  logic [LW-1:0] x8_f;  // {z, A, R, G, B}
  assign x8_f = {z_q[8], p_q[8][31:24], p_q[8][7:0], p_q[8][15:8], p_q[8][23:16]};

  // ---------------------------------------------------------------------------------------
  // X8: where the fragment goes; the merge's products.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x8_word_q;
  always_ff @(posedge clk_i) begin
    x8_word_q <= x7_word;
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
  always_comb begin
    for (int unsigned j = 0; j < L; j++) begin
      x8_le[j] = (slot_a(x8_word_q, j) != 8'h00) && (slot(x8_word_q, j) <= x8_f);
    end
    x8_last = x8_word_q[31:0];
    x8_prev = x8_word_q[31:24];
    for (int unsigned j = 1; j < L; j++) begin
      if (4'(j) == kk - 4'd1) begin
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
    assign inv  = 8'hff - (g == 0 ? x8_last[31:24] : g == 1 ? x8_f[31:24] : x8_prev);
    assign inv3 = {2'b00, inv} + {1'b0, inv, 1'b0};
    assign back = g == 0 ? x8_f[31:0] : x8_last;
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
  logic          x8_full, x8_insert;
  logic [1:0]    x8_pick;  // which merge
  logic          x9_merge_q, x10_merge_q;
  logic [1:0]    x9_pick_q, x10_pick_q;
  logic [3:0]    x9_kk_q, x10_kk_q;

  always_comb begin
    x8_full   = 1'b0;
    x8_pick   = 2'd2;
    x8_insert = p_q[8][31:24] != 8'h00;
    for (int unsigned j = 0; j < L; j++) begin
      if (4'(j) == kk - 4'd1) begin
        x8_full = slot_a(x8_word_q, j) != 8'h00;
        if (x8_le[j]) x8_pick = 2'd0;
        else if (j == 0 || x8_le[j == 0 ? 0 : j - 1]) x8_pick = 2'd1;
      end
    end
    for (int unsigned j = 0; j < L; j++) begin
      if (!x8_insert || (x8_full && 4'(j) >= kk) || x8_le[j]) begin
        x9_word_d[j*LW +: LW] = slot(x8_word_q, j);
      end else if (j == 0 || x8_le[j == 0 ? 0 : j - 1]) begin
        x9_word_d[j*LW +: LW] = x8_f;
      end else begin
        x9_word_d[j*LW +: LW] = slot(x8_word_q, j == 0 ? 0 : j - 1);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    x9_word_q   <= x9_word_d;
    x9_merge_q  <= x8_insert & x8_full;
    x9_pick_q   <= x8_pick;
    x9_kk_q     <= kk;
    x10_word_q  <= x9_word_q;
    x10_merge_q <= x9_merge_q;
    x10_pick_q  <= x9_pick_q;
    x10_kk_q    <= x9_kk_q;
  end

  // ---------------------------------------------------------------------------------------
  // X10: slot K-1 := front + m(back, 255 - A_front), saturated, the front's depth.
  // ---------------------------------------------------------------------------------------
  logic [WW-1:0] x11_word_d;
  logic [LW-1:0] x10_front;
  logic [15:0]   x10_tc;
  logic [9:0]    x10_u;
  logic [8:0]    x10_sum;
  logic [7:0]    x10_m;
  logic [7:0]    unused_u;
  assign unused_u = x10_u[7:0];
  always_comb begin
    x11_word_d = x10_word_q;
    x10_front  = '0;
    x10_tc     = '0;
    x10_u      = '0;
    x10_m      = '0;
    x10_sum    = '0;
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
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    x11_word_q <= x11_word_d;
  end

  assign x11_lwe_o     = x11_lwe;
  assign x11_wlayers_o = x11_word_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
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
      if (4'(j) >= x10_kk_q && slot_a(x11_word_q, j) != 8'h00) x11_sorted = 1'b0;
    end
  end
  LayersSorted: assert property (@(posedge clk_i) disable iff (!rst_ni)
      x11_lwe |-> x11_sorted);
  LayersMerge: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x11_lwe && $past(x10_merge_q));
`endif
`endif

endmodule
