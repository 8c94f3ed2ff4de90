// zb_color: the colour side of the pipeline (docs/rtl.md "Pipeline"), X5..X11. The colour plane
// is read at E5 (X5's address) and its word registered in X6 (the RAM's clock-to-out and the
// plane's resolve get a cycle of their own); zb_forward gives X7 the pixel's newest word;
// zb_blend blends X7..X11; the colour is written at E11 when the fragment passed and the mask
// lets a channel through, except in accumulate mode (zb_accum writes its own word instead,
// with zb_blend's products).
module zb_color #(
  parameter bit LAYERS_ON = 1'b0,  // layers mode writes the layers, not the colour (zb_layers)
  parameter int WORDS       = 4096,
  parameter int BEAT        = 8,
  parameter int COV_SAMPLES = 16,
  parameter int K_W         = 8    // zb_blend's k: the accumulate blend's w (zb_weight)
) (
  input  logic                              clk_i,
  input  logic                              rst_ni,
  input  zb_pkg::blend_mode_e               blend_i,
  input  logic [3:0]                        color_mask_i,
  // Tile port of the colour plane (zb_plane).
  input  logic                              tile_req_i,
  input  logic                              tile_we_i,
  input  logic                              tile_clear_i,
  input  logic                              tile_en_i,
  input  logic [$clog2(WORDS / BEAT)-1:0]   tile_addr_i,
  input  logic [BEAT*32-1:0]                tile_wcolor_i,
  output logic [BEAT*32-1:0]                tile_rcolor_o,
  // The pipeline: valid bits, addresses and pass bits of the stages this side uses.
  input  logic                              x5_valid_i,
  input  logic                              x6_valid_i,
  input  logic                              x10_valid_i,
  input  logic                              x11_valid_i,
  input  logic [$clog2(WORDS)-1:0]          x5_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x6_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x10_addr_i,
  input  logic [$clog2(WORDS)-1:0]          x11_addr_i,
  input  logic                              x10_pass_i,
  input  logic                              x11_pass_i,
  // X7: zb_blend's operands (zb_operands).
  input  logic [31:0]                       x7_k_i,
  input  logic [39:0]                       x7_k3_i,
  input  logic [31:0]                       x7_add_i,
  input  logic [4*(8+$clog2(COV_SAMPLES+1))-1:0] x7_q_i,
  // X5: the accumulate blend's operands (zb_weight's w, 3w; zb_operands' p), and in X8 their
  // products p_c * w, for zb_accum.
  input  logic [K_W-1:0]                    x5_w_i,
  input  logic [K_W+1:0]                    x5_w3_i,
  input  logic [31:0]                       x5_p_i,
  output logic [4*(K_W+8)-1:0]              x8_prod_o,
  // X11's colour write as the plane takes it, for zb_rop's retire port.
  output logic                              x11_cwe_o,
  output logic [31:0]                       x11_wcolor_o
);

  logic [31:0] cmem_rdata, x11_color, x7_dst;
  logic        color_on, x10_cwe, x11_cwe;

  assign color_on = (color_mask_i != 4'h0) & (blend_i != zb_pkg::BlendAccumulate) &
                    !(LAYERS_ON && blend_i == zb_pkg::BlendLayers);
  assign x10_cwe  = x10_valid_i & x10_pass_i & color_on;
  assign x11_cwe  = x11_valid_i & x11_pass_i & color_on;

  zb_plane #(
    .WIDTH    (32),
    .WORDS    (WORDS),
    .BEAT     (BEAT),
    .FORWARDED(1'b1)
  ) u_color_plane (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .tile_req_i  (tile_req_i),
    .tile_we_i   (tile_we_i),
    .tile_en_i   (tile_en_i),
    .tile_clear_i(tile_clear_i),
    .tile_addr_i (tile_addr_i),
    .tile_wdata_i(tile_wcolor_i),
    .tile_rdata_o(tile_rcolor_o),
    .pipe_re_i   (x5_valid_i),
    .pipe_raddr_i(x5_addr_i),
    .pipe_we_i   (x11_cwe),
    .pipe_waddr_i(x11_addr_i),
    .pipe_wdata_i(x11_color),
    .rdata_o     (cmem_rdata)
  );

  zb_forward #(
    .WIDTH (32),
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
    .x10_we_i   (x10_cwe),
    .x11_we_i   (x11_cwe),
    .x11_wdata_i(x11_color),
    .x6_rdata_i (cmem_rdata),
    .x7_word_o  (x7_dst)
  );

  assign x11_cwe_o    = x11_cwe;
  assign x11_wcolor_o = x11_color;

  zb_blend #(
    .COV_SAMPLES(COV_SAMPLES),
    .K_W        (K_W)
  ) u_blend (
    .clk_i  (clk_i),
    .mode_i (blend_i),
    .mask_i (color_mask_i),
    .dst_i  (x7_dst),
    .k_i    (x7_k_i),
    .k3_i   (x7_k3_i),
    .add_i  (x7_add_i),
    .q_i    (x7_q_i),
    .w_i    (x5_w_i),
    .w3_i   (x5_w3_i),
    .p_i    (x5_p_i),
    .color_o(x11_color),
    .prod_o (x8_prod_o)
  );

endmodule
