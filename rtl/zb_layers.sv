// zb_layers: mlab-K's layers (docs/datapath.md "8. Layers"), X5..X11 beside zb_color, with the
// colour plane's timing. Its plane holds per pixel LAYERS slots, slot j at [j*LW +: LW], a
// layer {z, A, R, G, B} (B at bit 0): as a number, the order layers are kept in (nearer first,
// then the colour word), so one compare orders two layers. A = 0 is an empty slot; fast clear
// empties a pixel. The pass's K (1..LAYERS) is k_m1_i + 1. Read at E5, the newest word in X7
// (zb_forward), written at E11 in layers mode when the fragment passed and the mask is not 0.
// The plane never crosses the tile port: the port only fast-clears it, and a store's read with
// the resolve reads it for zb_resolve_layers (tile_rlayers_o).
// X8..X11, the insert and the merge, are zb_layers_insert's.
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
  logic [BEAT*WW-1:0] no_layers;  // the fast clear's value: every slot empty
  assign no_layers = '0;
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
    .tile_we_i   (tile_we_i),         // a load is no read here; tile_en_i is never set on one
    .tile_en_i   (tile_en_i),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(no_layers),         // cleared empty
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

  logic [LW-1:0] x8_f;  // {z, A, R, G, B}
  assign x8_f = {z_q[8], p_q[8][31:24], p_q[8][7:0], p_q[8][15:8], p_q[8][23:16]};


  zb_layers_insert #(
    .DEPTH_BITS(DEPTH_BITS),
    .LAYERS    (LAYERS)
  ) u_insert (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .kk_i      (kk),
    .x7_word_i (x7_word),
    .x8_f_i    (x8_f),
    .we_i      (x11_lwe),
    .x11_word_o(x11_word_q)
  );

  assign x11_lwe_o     = x11_lwe;
  assign x11_wlayers_o = x11_word_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
  LayersCleared: cover property (@(posedge clk_i) disable iff (!rst_ni) tile_clear_i && tile_en_i);
  LayersRead: cover property (@(posedge clk_i) disable iff (!rst_ni)
      tile_req_i && !tile_we_i && tile_en_i);
`endif
`endif

endmodule
