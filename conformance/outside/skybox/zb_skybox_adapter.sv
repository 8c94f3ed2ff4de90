// zb_conf_adapter around Vortex Skybox's output-merger unit, VX_om_unit (hw/rtl/om/, from the
// Skybox checkout given to conformance.py with --checkout: Apache-2.0,
// github.com/vortexgpgpu/skybox at d06a9982cb317f4b8c117537ee1f743165131272; none of its lines
// are here). Adapter interface version 7 (docs/conformance.md "The adapter"). See README.md
// beside this file.
//
// The whole OM unit is driven, as the GPU drives it, through its three interfaces:
//   - the DCR bus (VX_dcr_bus_if): after each state write the adapter issues the OM's 18 DCR
//     writes, one a clock, so VX_om_dcr derives its own depth, stencil and blend enables;
//   - the request bus (VX_om_bus_if, one lane): a fragment's tile-local position, colour,
//     24-bit depth, mask 1, face 1;
//   - the cache bus (VX_mem_bus_if, OCACHE_NUM_REQS = 1 word port): the adapter is the memory.
//     It holds the tile and serves the OM's word reads and byte-masked word writes from it: the
//     colour buffer at word 0 (pitch TILE_W * 4 bytes, Skybox's rgba_t word: B in byte 0, G 1,
//     R 2, A 3), the depth/stencil buffer at word ZBASE (depth in bits [23:0], stencil [31:24]).
//
// Same-pixel order: the OM unit issues a fragment's read when it takes the fragment and its
// write several clocks later (depth/stencil and blend pipelines), and compares no addresses,
// so a later fragment to the same pixel would read the old value. The adapter holds such a
// fragment back until the earlier one's write request has entered the OM's memory request
// buffer (the reads and writes reach memory in that buffer's order). It sees that event on
// two signals inside VX_om_unit (mem_req_valid/ready/rw, ds_blend_write): hierarchical reads.
//
// Converted here: zblend's pass state to the OM's DCRs (depth function codes, the colour mask
// to the colour word's byte mask, blend replace/alpha/additive as GL factors); zblend's colour
// packing (r in the low byte) to and from rgba_t's (b in the low byte). Coverage and peel:
// the OM has neither; the adapter keeps and returns what was loaded. No accumulation plane,
// no layers, no retire port. The OM's reset is stretched to 16 clocks and idle_o waits 32
// quiet clocks after the last memory traffic (README.md, "The adapter").
`include "VX_om_define.vh"

/* verilator lint_off DECLFILENAME */
module zb_conf_adapter import VX_gpu_pkg::*; import VX_om_pkg::*; #(
  parameter int DEPTH_BITS  = 24,
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

  localparam int SbDepth = `VX_OM_DEPTH_BITS;  // 24 in Skybox (VX_types.vh)
  localparam int NPix    = TILE_W * TILE_H;
  localparam int IdxW    = $clog2(NPix);
  localparam int Pitch   = TILE_W * 4;         // bytes a row, both buffers
  localparam int ZBlk    = 1024;               // the depth buffer's base, in 64-byte blocks
  localparam int ZBase   = ZBlk * 16;          // ... in 32-bit words
  localparam int NDcr    = 18;
  localparam int NHold   = 8;                  // fragments read and not yet written, at most
  localparam int Quiet   = 32;                 // clocks without memory traffic before idle
  localparam int RstLen  = 16;                 // the OM's reset, clocks
  localparam int RspQ    = 16;

  initial begin
    if (DEPTH_BITS != SbDepth)
      $display("zb_skybox_adapter: warning: DEPTH_BITS %0d, but Skybox's depth buffer is %0d bits: only depth_bits.24 tests are meaningful",
               DEPTH_BITS, SbDepth);
    if (OCACHE_NUM_REQS != 1)
      $fatal(1, "zb_skybox_adapter: OCACHE_NUM_REQS %0d; the adapter serves one word port (build with NUM_THREADS=1)",
             OCACHE_NUM_REQS);
  end

  // ---- reset: the OM's, stretched (the testbench's is 2 clocks) --------------------------------
  logic [4:0] rst_cnt;
  logic       om_reset;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rst_cnt <= '0;
    else if (rst_cnt != 5'(RstLen)) rst_cnt <= rst_cnt + 5'd1;
  end
  assign om_reset = (rst_cnt != 5'(RstLen));

  // ---- the tile ---------------------------------------------------------------------------------
  logic [31:0]        t_color [NPix];  // zblend packing (r in the low byte)
  logic [SbDepth-1:0] t_depth [NPix];
  logic [7:0]         t_sten  [NPix];  // Skybox's stencil byte: 0 at each load, never written
  logic [7:0]         t_cov   [NPix];
  logic [31:0]        t_peel  [NPix];

  function automatic logic [31:0] to_sb(input logic [31:0] c);   // r|g<<8|b<<16|a<<24 -> {a,r,g,b}
    return {c[31:24], c[7:0], c[15:8], c[23:16]};
  endfunction
  function automatic logic [31:0] from_sb(input logic [31:0] c); // {a,r,g,b} -> r|g<<8|b<<16|a<<24
    return {c[31:24], c[7:0], c[15:8], c[23:16]};
  endfunction

  // ---- pass state -> DCR writes ------------------------------------------------------------------
  logic        s_dtest, s_dwrite;
  logic [2:0]  s_dfunc, s_blend;
  logic [3:0]  s_mask;  // zblend: bit 0 R, 1 G, 2 B, 3 A
  logic        cfg_ok;  // a state has been written to the OM
  logic        seq_busy;
  logic [4:0]  seq_i;

  // zblend 0 never, 1 less, 2 equal, 3 lequal, 4 greater, 5 notequal, 6 gequal, 7 always;
  // Skybox (VX_types.vh) ALWAYS 0, NEVER 1, LESS 2, LEQUAL 3, EQUAL 4, GEQUAL 5, GREATER 6,
  // NOTEQUAL 7.
  logic [2:0] sb_dfunc;
  always_comb begin
    case (s_dfunc)
      3'd0: sb_dfunc = 3'd1;
      3'd1: sb_dfunc = 3'd2;
      3'd2: sb_dfunc = 3'd4;
      3'd3: sb_dfunc = 3'd3;
      3'd4: sb_dfunc = 3'd6;
      3'd5: sb_dfunc = 3'd7;
      3'd6: sb_dfunc = 3'd5;
      default: sb_dfunc = 3'd0;
    endcase
  end

  // GL factors, Skybox's codes: ZERO 0, ONE 1, SRC_A 6, ONE_MINUS_SRC_A 7; mode ADD 0.
  logic [3:0] f_src, f_dst;
  always_comb begin
    f_src = 4'd1;
    f_dst = 4'd0;
    case (s_blend)
      3'd1: begin f_src = 4'd6; f_dst = 4'd7; end  // alpha: SRC_ALPHA, ONE_MINUS_SRC_ALPHA
      3'd2: begin f_src = 4'd6; f_dst = 4'd1; end  // additive: SRC_ALPHA, ONE
      default: ;                                   // replace: ONE, ZERO (the OM's blend off)
    endcase
  end

  // The colour word's bytes: B 0, G 1, R 2, A 3.
  logic [3:0] sb_cmask;
  assign sb_cmask = {s_mask[3], s_mask[0], s_mask[1], s_mask[2]};

  logic [`VX_DCR_ADDR_WIDTH-1:0] dcr_addr;
  logic [31:0]                   dcr_data;
  always_comb begin
    dcr_addr = '0;
    dcr_data = '0;
    case (seq_i)
      5'd0:  begin dcr_addr = `VX_DCR_OM_CBUF_ADDR;         dcr_data = 32'd0; end
      5'd1:  begin dcr_addr = `VX_DCR_OM_CBUF_PITCH;        dcr_data = 32'(Pitch); end
      5'd2:  begin dcr_addr = `VX_DCR_OM_CBUF_WRITEMASK;    dcr_data = 32'(sb_cmask); end
      5'd3:  begin dcr_addr = `VX_DCR_OM_ZBUF_ADDR;         dcr_data = 32'(ZBlk); end
      5'd4:  begin dcr_addr = `VX_DCR_OM_ZBUF_PITCH;        dcr_data = 32'(Pitch); end
      // the write mask before the function: VX_om_dcr derives depth_enable at each of the two
      // writes from the value written and the other register's current value
      5'd5:  begin dcr_addr = `VX_DCR_OM_DEPTH_WRITEMASK;   dcr_data = 32'(s_dtest && s_dwrite); end
      5'd6:  begin dcr_addr = `VX_DCR_OM_DEPTH_FUNC;        dcr_data = {29'd0, s_dtest ? sb_dfunc : 3'd0}; end
      5'd7:  begin dcr_addr = `VX_DCR_OM_STENCIL_ZPASS;     dcr_data = 32'd0; end        // KEEP
      5'd8:  begin dcr_addr = `VX_DCR_OM_STENCIL_ZFAIL;     dcr_data = 32'd0; end        // KEEP
      5'd9:  begin dcr_addr = `VX_DCR_OM_STENCIL_FAIL;      dcr_data = 32'd0; end        // KEEP
      5'd10: begin dcr_addr = `VX_DCR_OM_STENCIL_REF;       dcr_data = 32'd0; end
      5'd11: begin dcr_addr = `VX_DCR_OM_STENCIL_MASK;      dcr_data = 32'h00ff00ff; end
      5'd12: begin dcr_addr = `VX_DCR_OM_STENCIL_WRITEMASK; dcr_data = 32'd0; end
      5'd13: begin dcr_addr = `VX_DCR_OM_STENCIL_FUNC;      dcr_data = 32'd0; end        // ALWAYS
      5'd14: begin dcr_addr = `VX_DCR_OM_BLEND_FUNC;
                   dcr_data = {4'd0, f_dst, 4'd0, f_dst, 4'd0, f_src, 4'd0, f_src}; end
      5'd15: begin dcr_addr = `VX_DCR_OM_BLEND_MODE;        dcr_data = 32'd0; end        // ADD, ADD
      5'd16: begin dcr_addr = `VX_DCR_OM_BLEND_CONST;       dcr_data = 32'd0; end
      5'd17: begin dcr_addr = `VX_DCR_OM_LOGIC_OP;          dcr_data = 32'd3; end        // COPY
      default: ;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s_dtest <= 1'b0; s_dfunc <= 3'd0; s_dwrite <= 1'b0; s_blend <= 3'd0; s_mask <= 4'hf;
      seq_busy <= 1'b0; seq_i <= '0; cfg_ok <= 1'b0;
    end else if (state_we_i) begin
      s_dtest  <= state_i[0];
      s_dfunc  <= state_i[3:1];
      s_dwrite <= state_i[4];
      s_blend  <= state_i[7:5];
      s_mask   <= state_i[11:8];
      seq_busy <= 1'b1;
      seq_i    <= '0;
    end else if (seq_busy) begin
      seq_i <= seq_i + 5'd1;
      if (seq_i == 5'(NDcr - 1)) begin
        seq_busy <= 1'b0;
        cfg_ok   <= 1'b1;
      end
    end
  end

  // ---- the OM unit --------------------------------------------------------------------------------
  VX_dcr_bus_if dcr_bus_if();
  assign dcr_bus_if.write_valid = seq_busy && !om_reset;
  assign dcr_bus_if.write_addr  = dcr_addr;
  assign dcr_bus_if.write_data  = dcr_data;

  VX_om_bus_if #(.NUM_LANES(1)) om_bus_if();

  VX_mem_bus_if #(
    .DATA_SIZE (OCACHE_WORD_SIZE),
    .TAG_WIDTH (OCACHE_TAG_WIDTH)
  ) cache_bus_if[OCACHE_NUM_REQS]();

  VX_om_unit #(
    .INSTANCE_ID ("zb-om"),
    .NUM_LANES   (1)
  ) u_om (
    .clk          (clk_i),
    .reset        (om_reset),
    .cache_bus_if (cache_bus_if),
    .dcr_bus_if   (dcr_bus_if),
    .om_bus_if    (om_bus_if)
  );

  // ---- fragments in, the same-pixel hold ----------------------------------------------------------
  logic [15:0]     lx, ly;
  logic [IdxW-1:0] f_idx;
  assign lx    = frag_x_i - tile_x0_i;
  assign ly    = frag_y_i - tile_y0_i;
  assign f_idx = IdxW'(ly * 16'(TILE_W) + lx);

  // Fragments whose read the OM has issued and whose write request has not yet entered its
  // memory request buffer, in order (the OM keeps order: one lane, in-order pipelines).
  logic [NHold-1:0] h_v;
  logic [IdxW-1:0]  h_idx [NHold];
  logic [2:0]       h_head, h_tail;
  logic             hazard, h_full;
  always_comb begin
    hazard = 1'b0;
    for (int i = 0; i < NHold; i++)
      if (h_v[i] && h_idx[i] == f_idx) hazard = 1'b1;
  end
  assign h_full = &h_v;

  logic storing, open;
  assign open = cfg_ok && !seq_busy && !storing && !om_reset;

  assign om_bus_if.req_valid          = frag_valid_i && open && !hazard && !h_full;
  assign om_bus_if.req_data.uuid      = '0;
  assign om_bus_if.req_data.mask      = 1'b1;
  assign om_bus_if.req_data.pos_x     = `VX_OM_DIM_BITS'(lx);
  assign om_bus_if.req_data.pos_y     = `VX_OM_DIM_BITS'(ly);
  assign om_bus_if.req_data.color     = to_sb(frag_rgba_i);
  assign om_bus_if.req_data.depth     = frag_z_i[SbDepth-1:0];
  assign om_bus_if.req_data.face      = 1'b1;
  assign frag_ready_o = open && !hazard && !h_full && (om_bus_if.req_ready == 1'b1);

  // The OM's own request into its memory request buffer (VX_om_unit: mem_req_valid, _ready, _rw;
  // ds_blend_write is a fragment's write after the depth/stencil and blend stages).
  logic rd_fire, wb_fire, om_busy;
  assign rd_fire = u_om.mem_req_valid && u_om.mem_req_ready && !u_om.mem_req_rw;
  assign wb_fire = u_om.ds_blend_write && u_om.mem_req_ready;
  assign om_busy = u_om.mem_req_valid || u_om.mem_req_valid_unqual_r;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      h_v <= '0; h_head <= '0; h_tail <= '0;
      for (int i = 0; i < NHold; i++) h_idx[i] <= '0;
    end else begin
      if (wb_fire) begin
        h_v[h_head] <= 1'b0;
        h_head      <= h_head + 3'd1;
      end
      if (rd_fire) begin
        h_v[h_tail]   <= 1'b1;
        h_idx[h_tail] <= f_idx;  // rd_fire is the fragment's own take
        h_tail        <= h_tail + 3'd1;
      end
    end
  end

  // ---- the memory: the OM's cache port served from the tile ---------------------------------------
  logic                          mreq_fire, mreq_color;
  logic [OCACHE_ADDR_WIDTH-1:0]  maddr;
  logic [IdxW-1:0]               midx;
  logic [31:0]                   mrd, mwr_old, mwr_new;
  logic [3:0]                    mbe;
  logic [OCACHE_TAG_WIDTH-1:0]   q_tag  [RspQ];
  logic [31:0]                   q_data [RspQ];
  logic [$clog2(RspQ)-1:0]       q_head, q_tail;
  logic [$clog2(RspQ):0]         q_cnt;

  assign maddr      = cache_bus_if[0].req_data.addr;
  assign mreq_color = (maddr < OCACHE_ADDR_WIDTH'(ZBase));
  assign midx       = mreq_color ? IdxW'(maddr) : IdxW'(maddr - OCACHE_ADDR_WIDTH'(ZBase));
  assign mbe        = cache_bus_if[0].req_data.byteen;
  assign mrd        = mreq_color ? to_sb(t_color[midx]) : {t_sten[midx], t_depth[midx]};
  assign mwr_old    = mrd;
  always_comb
    for (int b = 0; b < 4; b++)
      mwr_new[8*b +: 8] = mbe[b] ? cache_bus_if[0].req_data.data[8*b +: 8] : mwr_old[8*b +: 8];

  assign cache_bus_if[0].req_ready     = (q_cnt < ($clog2(RspQ)+1)'(RspQ - 1));
  assign mreq_fire                     = cache_bus_if[0].req_valid && cache_bus_if[0].req_ready;
  assign cache_bus_if[0].rsp_valid     = (q_cnt != '0);
  assign cache_bus_if[0].rsp_data.data = q_data[q_head];
  assign cache_bus_if[0].rsp_data.tag  = q_tag[q_head];

  // ---- load, store, and the memory's writes --------------------------------------------------------
  logic [IdxW-1:0] ld_cnt, st_cnt;
  logic [5:0]      quiet;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ld_cnt  <= '0;
      st_cnt  <= '0;
      storing <= 1'b0;
      q_head  <= '0;
      q_tail  <= '0;
      q_cnt   <= '0;
      quiet   <= '0;
    end else begin
      if (ld_valid_i && ld_ready_o) begin
        t_color[ld_cnt] <= ld_color_i;
        t_depth[ld_cnt] <= ld_depth_i[SbDepth-1:0];
        t_sten[ld_cnt]  <= 8'd0;
        t_cov[ld_cnt]   <= ld_cov_i;
        t_peel[ld_cnt]  <= ld_peel_i;
        ld_cnt          <= (ld_cnt == IdxW'(NPix - 1)) ? '0 : ld_cnt + 1'b1;
      end
      if (mreq_fire) begin
        if (cache_bus_if[0].req_data.rw) begin
          if (mreq_color) t_color[midx] <= from_sb(mwr_new);
          else begin
            t_depth[midx] <= mwr_new[SbDepth-1:0];
            t_sten[midx]  <= mwr_new[31:24];
          end
        end else begin
          q_tag[q_tail]  <= cache_bus_if[0].req_data.tag;
          q_data[q_tail] <= mrd;
          q_tail         <= q_tail + 1'b1;
        end
      end
      q_cnt <= q_cnt + ($clog2(RspQ)+1)'(mreq_fire && !cache_bus_if[0].req_data.rw)
                     - ($clog2(RspQ)+1)'(cache_bus_if[0].rsp_valid && cache_bus_if[0].rsp_ready);
      if (cache_bus_if[0].rsp_valid && cache_bus_if[0].rsp_ready) q_head <= q_head + 1'b1;
      if (om_bus_if.req_valid || cache_bus_if[0].req_valid || om_busy || (h_v != '0) || seq_busy)
        quiet <= '0;
      else if (quiet != 6'(Quiet)) quiet <= quiet + 6'd1;
      if (st_start_i && !storing) begin
        storing <= 1'b1;
        st_cnt  <= '0;
      end else if (storing) begin
        st_cnt <= st_cnt + 1'b1;
        if (st_cnt == IdxW'(NPix - 1)) storing <= 1'b0;
      end
    end
  end

  assign ld_ready_o = !storing && !seq_busy && !om_reset;
  assign idle_o     = !storing && !seq_busy && !om_reset && (ld_cnt == '0) && (h_v == '0)
                      && (q_cnt == '0) && (quiet == 6'(Quiet));
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
                    frag_cov_i, COV_SAMPLES, cache_bus_if[0].req_data.atype};
  // conformance.py --define ZB_SKYBOX_TRACE: one line per event into sim.log (state writes, the
  // OM's reads and write-backs, its buffer's output, the cache port), as used for README.md.
`ifdef ZB_SKYBOX_TRACE
  int unsigned cyc = 0;
  always_ff @(posedge clk_i) begin
    cyc <= cyc + 1;
    if (state_we_i) $display("sbt %0d: state %04x", cyc, state_i);
    if (rd_fire) $display("sbt %0d: READ  idx %0d", cyc, f_idx);
    if (om_bus_if.req_valid && om_bus_if.req_ready && !rd_fire) $display("sbt %0d: TAKE-NOREAD idx %0d", cyc, f_idx);
    if (wb_fire) $display("sbt %0d: WB    x%0d y%0d dsm%b cm%b", cyc, u_om.mem_req_pos_x[0], u_om.mem_req_pos_y[0], u_om.mem_req_ds_mask, u_om.mem_req_c_mask);
    if (mreq_fire) $display("sbt %0d: CACHE %s %0h be%b tag%0h", cyc, cache_bus_if[0].req_data.rw ? "W" : "R", maddr, mbe, cache_bus_if[0].req_data.tag);
    if (u_om.mem_req_valid_unqual_r && u_om.mem_req_ready_r) $display("sbt %0d: BUF-OUT rw%b deg%b", cyc, u_om.mem_req_rw_r, u_om.is_degenerate_req);
  end
`endif
endmodule
