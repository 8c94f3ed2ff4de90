// zb_conf_adapter around Rasterix's per-fragment pipeline (PerFragmentPipeline, from the Rasterix
// checkout given to conformance.py with --checkout: GPL-3.0, github.com/ToNi3141/Rasterix at
// e8a5c860e497461d09adc0f7041669e89df097bd; none of its lines are here). Adapter interface
// version 7 (docs/conformance.md "The adapter"). See NOTES.md beside this file.
//
// Rasterix's pipeline has no tile memory of its own: in Rasterix the framebuffer streams
// (StreamConcatFifo) hand it each fragment's stored colour, depth and stencil beside the
// fragment, and its write-back goes to FramebufferWriter, which applies the colour and depth
// masks. Here the adapter plays that framebuffer: it holds the tile, reads the pixel in the cycle
// the fragment enters the pipeline, and writes the pipeline's output back with the masks.
//
// What the adapter converts:
//   - pass state: zblend's depth function code to Rasterix's TestFunc code, depth test enable,
//     depth write as Rasterix's depth mask, blend replace as blending disabled and blend alpha as
//     GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA (additive as GL_SRC_ALPHA / GL_ONE), colour mask;
//     alpha test and stencil test off.
//   - colour: zblend packs r in the low byte, Rasterix in the high one (R [31:24] ... A [7:0]).
//   - depth: Rasterix's depth buffer is 16 bits; its fragment depth input is 32 bits, clamped to
//     16 (clampDepth: bits [31:16] zero means below 1.0). Only DEPTH_BITS = 16 is meaningful.
//   - same-pixel hazards: Rasterix reads the destination before the fragment enters and writes
//     4 clocks later; its command parser waits for the pipeline to empty between triangles. The
//     adapter holds a fragment back while an earlier one to the same pixel is in flight.
//
// Coverage, peel: Rasterix has neither; the adapter keeps and returns what was loaded (the tests
// that use them are NOT SUPPORTED by the profile). No accumulation plane, no layers, no retire port.
/* verilator lint_off DECLFILENAME */
module zb_conf_adapter #(
  parameter int DEPTH_BITS  = 16,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 16,
  parameter int TILE_H      = 16,
  /* verilator lint_off UNUSEDPARAM */
  parameter int BEAT        = 8,
  parameter int WEIGHT_BITS = 4,
  /* verilator lint_on UNUSEDPARAM */
  parameter int ACC_BITS    = 16,
  parameter int REV_BITS    = 8
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        state_we_i,
  input  logic [12:0] state_i,
  input  logic [2:0]  state_layers_i,
  input  logic [15:0] tile_x0_i,
  input  logic [15:0] tile_y0_i,
  input  logic        ld_valid_i,
  output logic        ld_ready_o,
  input  logic [31:0] ld_color_i,
  input  logic [31:0] ld_depth_i,
  input  logic [7:0]  ld_cov_i,
  input  logic [31:0] ld_peel_i,
  input  logic [4*ACC_BITS+REV_BITS-1:0] ld_acc_i,
  input  logic        frag_valid_i,
  output logic        frag_ready_o,
  input  logic [15:0] frag_x_i,
  input  logic [15:0] frag_y_i,
  input  logic [31:0] frag_z_i,
  input  logic [31:0] frag_rgba_i,
  input  logic [7:0]  frag_cov_i,
  output logic        idle_o,
  input  logic        st_start_i,
  input  logic        st_resolve_i,
  output logic        st_valid_o,
  output logic [31:0] st_color_o,
  output logic [31:0] st_depth_o,
  output logic [7:0]  st_cov_o,
  output logic [31:0] st_peel_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] st_acc_o,
  output logic [4:0]  planes_o,
  output logic [3:0]  layers_o,
  output logic        ret_d_valid_o,
  output logic [31:0] ret_d_pixel_o,
  output logic        ret_dwe_o,
  output logic [31:0] ret_wdepth_o,
  output logic        ret_vwe_o,
  output logic [7:0]  ret_wcov_o,
  output logic        ret_c_valid_o,
  output logic [31:0] ret_c_pixel_o,
  output logic        ret_cwe_o,
  output logic [31:0] ret_wcolor_o,
  output logic        ret_awe_o,
  output logic [4*ACC_BITS+REV_BITS-1:0] ret_wacc_o
);

  localparam int RxDepth = 16;  // Rasterix's DEPTH_WIDTH (a localparam 16 in all its cores)
  localparam int NPix    = TILE_W * TILE_H;
  localparam int IdxW    = $clog2(NPix);
  localparam int Lat     = 4;   // PerFragmentPipeline's latency, input edge to m_frag_* valid

  initial begin
    if (DEPTH_BITS != RxDepth)
      $display("zb_rasterix_adapter: warning: DEPTH_BITS %0d, but Rasterix's depth buffer is 16 bits: only depth_bits.16 tests are meaningful",
               DEPTH_BITS);
  end

  // ---- the tile (the framebuffer's role) -------------------------------------------------------
  logic [31:0]        t_color [NPix];  // zblend packing (r in the low byte)
  logic [RxDepth-1:0] t_depth [NPix];
  logic [7:0]         t_cov   [NPix];
  logic [31:0]        t_peel  [NPix];

  // ---- pass state, converted to Rasterix's registers -------------------------------------------
  logic        s_dtest, s_dwrite;
  logic [2:0]  s_dfunc, s_blend;
  logic [3:0]  s_mask;  // zblend: bit 0 R, 1 G, 2 B, 3 A

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s_dtest <= 1'b0; s_dfunc <= 3'd0; s_dwrite <= 1'b0; s_blend <= 3'd0; s_mask <= 4'hf;
    end else if (state_we_i) begin
      s_dtest  <= state_i[0];
      s_dfunc  <= state_i[3:1];
      s_dwrite <= state_i[4];
      s_blend  <= state_i[7:5];
      s_mask   <= state_i[11:8];
    end
  end

  // zblend 0 never, 1 less, 2 equal, 3 lequal, 4 greater, 5 notequal, 6 gequal, 7 always;
  // Rasterix (RegisterAndDescriptorDefines.vh) ALWAYS 0, NEVER 1, LESS 2, ... GEQUAL 7.
  logic [2:0] rx_dfunc;
  always_comb begin
    case (s_dfunc)
      3'd0:    rx_dfunc = 3'd1;
      3'd7:    rx_dfunc = 3'd0;
      default: rx_dfunc = s_dfunc + 3'd1;
    endcase
  end

  // Blend factors, Rasterix's codes: ZERO 0, ONE 1, SRC_ALPHA 6, ONE_MINUS_SRC_ALPHA 7.
  logic       rx_blend_en;
  logic [3:0] rx_sfactor, rx_dfactor;
  always_comb begin
    rx_blend_en = 1'b0;
    rx_sfactor  = 4'd1;
    rx_dfactor  = 4'd0;
    case (s_blend)
      3'd1: begin rx_blend_en = 1'b1; rx_sfactor = 4'd6; rx_dfactor = 4'd7; end  // alpha
      3'd2: begin rx_blend_en = 1'b1; rx_sfactor = 4'd6; rx_dfactor = 4'd1; end  // additive
      default: ;                                                              // replace
    endcase
  end

  // conf (OP_RENDER_CONFIG_FRAGMENT_PIPELINE): [2:0] depth func, [5:3] alpha func, [13:6] alpha
  // ref, [14] depth mask, [15] mask A, [16] B, [17] G, [18] R, [22:19] sfactor, [26:23] dfactor.
  // confFeatureEnable: [0] fog, [1] blending, [2] depth test, [3] alpha test, [4] stencil.
  logic [31:0] rx_conf, rx_enable;
  assign rx_conf = {5'd0, rx_dfactor, rx_sfactor, s_mask[0], s_mask[1], s_mask[2], s_mask[3],
                    s_dwrite, 8'd0, 3'd0 /* ALWAYS */, rx_dfunc};
  assign rx_enable = {29'd0, s_dtest, rx_blend_en, 1'b0};

  // ---- load, store ------------------------------------------------------------------------------
  logic [IdxW-1:0] ld_cnt, st_cnt;
  logic            storing;

  // ---- fragments in flight (for the same-pixel hold and idle_o) ---------------------------------
  logic [Lat-1:0]  trk_v;
  logic [IdxW-1:0] trk_idx [Lat];

  logic [15:0]     lx, ly;
  logic [IdxW-1:0] f_idx;
  logic            hazard, take;
  assign lx    = frag_x_i - tile_x0_i;
  assign ly    = frag_y_i - tile_y0_i;
  assign f_idx = IdxW'(ly * 16'(TILE_W) + lx);
  always_comb begin
    hazard = 1'b0;
    for (int i = 0; i < Lat; i++)
      if (trk_v[i] && trk_idx[i] == f_idx) hazard = 1'b1;
  end
  assign frag_ready_o = !storing && !(frag_valid_i && hazard);
  assign take         = frag_valid_i && frag_ready_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      trk_v <= '0;
      for (int i = 0; i < Lat; i++) trk_idx[i] <= '0;
    end else begin
      trk_v[0]   <= take;
      trk_idx[0] <= f_idx;
      for (int i = 1; i < Lat; i++) begin
        trk_v[i]   <= trk_v[i-1];
        trk_idx[i] <= trk_idx[i-1];
      end
    end
  end

  // ---- Rasterix's per-fragment pipeline ---------------------------------------------------------
  function automatic logic [31:0] to_rx(input logic [31:0] c);   // r|g<<8|b<<16|a<<24 -> RGBA
    return {c[7:0], c[15:8], c[23:16], c[31:24]};
  endfunction
  function automatic logic [31:0] from_rx(input logic [31:0] c); // RGBA -> r|g<<8|b<<16|a<<24
    return {c[7:0], c[15:8], c[23:16], c[31:24]};
  endfunction

  logic                 pf_tvalid;
  logic [IdxW-1:0]      pf_addr;
  logic [31:0]          pf_color;
  logic                 pf_color_strb, pf_depth_strb;
  logic [RxDepth-1:0]   pf_depth;
  logic [3:0]           pf_stencil;
  logic                 pf_stencil_strb, pf_last, pf_processed, pf_ready;
  logic [15:0]          pf_sx, pf_sy;

  PerFragmentPipeline #(
    .FRAMEBUFFER_INDEX_WIDTH(IdxW),
    .SCREEN_POS_WIDTH       (16),
    .DEPTH_WIDTH            (RxDepth),
    .STENCIL_WIDTH          (4),
    .SUB_PIXEL_WIDTH        (8)
  ) u_pfp (
    .aclk                   (clk_i),
    .resetn                 (rst_ni),
    .conf                   (rx_conf),
    .confFeatureEnable      (rx_enable),
    .confStencilBufferConfig(32'd0),
    .s_frag_tready          (pf_ready),
    .s_frag_tlast           (1'b0),
    .s_frag_tkeep           (1'b1),
    .s_frag_tvalid          (take),
    .s_frag_tcolor          (to_rx(frag_rgba_i)),
    // 16-bit unorm depth as Rasterix's 32-bit fragment depth (bits [31:16] zero: below 1.0).
    .s_frag_tdepth          ({16'd0, frag_z_i[15:0]}),
    .s_frag_tindex          (f_idx),
    .s_frag_tscreenPosX     (frag_x_i),
    .s_frag_tscreenPosY     (frag_y_i),
    .s_frag_color_tdata     (to_rx(t_color[f_idx])),
    .s_frag_depth_tdata     (t_depth[f_idx]),
    .s_frag_stencil_tdata   (4'd0),
    .fragmentProcessed      (pf_processed),
    .m_frag_tready          (1'b1),
    .m_frag_taddr           (pf_addr),
    .m_frag_tvalid          (pf_tvalid),
    .m_frag_tlast           (pf_last),
    .m_frag_tscreenPosX     (pf_sx),
    .m_frag_tscreenPosY     (pf_sy),
    .m_frag_color_tdata     (pf_color),
    .m_frag_color_tstrb     (pf_color_strb),
    .m_frag_depth_tdata     (pf_depth),
    .m_frag_depth_tstrb     (pf_depth_strb),
    .m_frag_stencil_tdata   (pf_stencil),
    .m_frag_stencil_tstrb   (pf_stencil_strb)
  );

  // Write-back, as Rasterix's FramebufferWriter does with its masks: the colour per channel under
  // the colour mask, the depth under the depth mask. trk_v[Lat-1] is the adapter's own (reset)
  // record of a fragment leaving now; pf_tvalid is Rasterix's.
  logic        wb;
  logic [31:0] wb_color, old_color;
  assign wb        = trk_v[Lat-1] && pf_tvalid;
  assign wb_color  = from_rx(pf_color);
  assign old_color = t_color[pf_addr];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ld_cnt  <= '0;
      st_cnt  <= '0;
      storing <= 1'b0;
    end else begin
      if (ld_valid_i && ld_ready_o) begin
        t_color[ld_cnt] <= ld_color_i;
        t_depth[ld_cnt] <= ld_depth_i[RxDepth-1:0];
        t_cov[ld_cnt]   <= ld_cov_i;
        t_peel[ld_cnt]  <= ld_peel_i;
        ld_cnt          <= (ld_cnt == IdxW'(NPix - 1)) ? '0 : ld_cnt + 1'b1;
      end
      if (wb && pf_color_strb)
        for (int c = 0; c < 4; c++)
          t_color[pf_addr][8*c +: 8] <= s_mask[c] ? wb_color[8*c +: 8] : old_color[8*c +: 8];
      if (wb && pf_depth_strb && s_dwrite)
        t_depth[pf_addr] <= pf_depth;
      if (st_start_i && !storing) begin
        storing <= 1'b1;
        st_cnt  <= '0;
      end else if (storing) begin
        st_cnt <= st_cnt + 1'b1;
        if (st_cnt == IdxW'(NPix - 1)) storing <= 1'b0;
      end
    end
  end

  assign ld_ready_o = !storing;
  assign idle_o     = !storing && (ld_cnt == '0) && (trk_v == '0);
  assign st_valid_o = storing;
  assign st_color_o = t_color[st_cnt];
  assign st_depth_o = 32'(t_depth[st_cnt]);
  assign st_cov_o   = t_cov[st_cnt];
  assign st_peel_o  = t_peel[st_cnt];
  assign st_acc_o   = '0;
  assign planes_o   = 5'b01111;  // colour, depth, coverage, peel (the last two only kept)
  assign layers_o   = 4'd0;

  assign ret_d_valid_o = 1'b0;
  assign ret_d_pixel_o = '0;
  assign ret_dwe_o     = 1'b0;
  assign ret_wdepth_o  = '0;
  assign ret_vwe_o     = 1'b0;
  assign ret_wcov_o    = '0;
  assign ret_c_valid_o = 1'b0;
  assign ret_c_pixel_o = '0;
  assign ret_cwe_o     = 1'b0;
  assign ret_wcolor_o  = '0;
  assign ret_awe_o     = 1'b0;
  assign ret_wacc_o    = '0;

  logic unused;
  assign unused = ^{state_i[12], state_layers_i, st_resolve_i, ld_acc_i, ld_depth_i, frag_z_i,
                    frag_cov_i, pf_processed, pf_ready, pf_last, pf_sx, pf_sy, pf_stencil,
                    pf_stencil_strb, COV_SAMPLES};
endmodule
