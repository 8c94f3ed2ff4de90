// zb_ref_pipe: the pipelined variant of the second reference DUT (conformance/ref/README.md),
// written from docs/datapath.md alone. An in-order pipeline that takes a fragment every cycle
// when no hazard stops it:
//
//   S1 accept    the fragment registered, its tile pixel computed
//   S2 read      the stored colour and depth read (at the edge S1 -> S2), forwarded from S3 and
//                S4 when they hold a write to the same pixel
//   S3 result    depth test, blend, colour mask computed in S2's cycle, registered
//   S4 write     the registered write, into the tile at the edge that leaves S4
//
// A fragment's writes reach the tile three edges after its read, so a later fragment on the
// same pixel reads too early at distances 1 to 3 (datapath.md "The fragment": a pixel's
// fragments must see each other's writes): at distance 1 the result is not computed yet and
// the later fragment waits a cycle in S1 (which makes it distance 2); at 2 and 3 the write is
// forwarded from S3 or S4.
//
// Profile (profile_pipe.json): blend replace (0), alpha (1) and additive (2), every depth
// function, depth write, colour mask, every width. No peel test, no coverage blend, no under or
// accumulate blend (those fragments are killed), no accumulation plane; the coverage and peel
// planes are storage only. Its ports answer without random stalls: the store answers in the
// first cycle after st_start_i, idle_o rises in the cycle after the last write.
//
// The ZB_REF_DEFECT_* defines are the defect catalogue (defects.json, README.md "Defect
// catalogue"): each changes only the lines it guards.
module zb_ref_pipe #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 16,
  parameter int TILE_H      = 16,
  parameter int COV_W = $clog2(COV_SAMPLES + 1)  // derived: the coverage count's width
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  state_we_i,
  input  logic [12:0]           state_i,
  input  logic [15:0]           tile_x0_i,
  input  logic [15:0]           tile_y0_i,
  input  logic                  ld_valid_i,
  output logic                  ld_ready_o,
  input  logic [31:0]           ld_color_i,
  input  logic [DEPTH_BITS-1:0] ld_depth_i,
  input  logic [COV_W-1:0]      ld_cov_i,
  input  logic [DEPTH_BITS-1:0] ld_peel_i,
  input  logic                  frag_valid_i,
  output logic                  frag_ready_o,
  input  logic [15:0]           frag_x_i,
  input  logic [15:0]           frag_y_i,
  input  logic [DEPTH_BITS-1:0] frag_z_i,
  input  logic [31:0]           frag_rgba_i,
  output logic                  idle_o,
  input  logic                  st_start_i,
  output logic                  st_valid_o,
  output logic [31:0]           st_color_o,
  output logic [DEPTH_BITS-1:0] st_depth_o,
  output logic [COV_W-1:0]      st_cov_o,
  output logic [DEPTH_BITS-1:0] st_peel_o
);

  localparam int Words = TILE_W * TILE_H;
  localparam int AddrW = Words > 1 ? $clog2(Words) : 1;
  localparam int CntW  = $clog2(Words + 1);
  localparam int D     = DEPTH_BITS;

  // m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x * y (datapath.md "3. Blend").
  function automatic logic [7:0] unorm_mul(input logic [7:0] x, input logic [7:0] y);
    logic [15:0] t, s;
    t = 16'(x) * 16'(y);
`ifdef ZB_REF_DEFECT_UNORM_NO_HI
    s = t + 16'h0080;  // the defect: x * y / 256 rounded, the t >> 8 term left out
`else
    s = t + (t >> 8) + 16'h0080;
`endif
    return 8'(s >> 8);
  endfunction

  function automatic logic depth_pass(input logic [2:0] func, input logic [D-1:0] z,
                                      input logic [D-1:0] stored);
    case (func)
      3'd0:    return 1'b0;
      3'd1:    return z <  stored;
      3'd2:    return z == stored;
`ifdef ZB_REF_DEFECT_LEQUAL_AS_LESS
      3'd3:    return z <  stored;   // the defect: lequal decoded as less
`else
      3'd3:    return z <= stored;
`endif
      3'd4:    return z >  stored;
      3'd5:    return z != stored;
      3'd6:    return z >= stored;
      default: return 1'b1;
    endcase
  endfunction

  // One channel: replace, alpha (min(255, m(s, a) + m(d, 255 - a))) or additive
  // (min(255, d + m(s, a))); the alpha channel with s = a.
  function automatic logic [7:0] blend_chan(input logic [2:0] mode, input logic [7:0] s,
                                            input logic [7:0] d, input logic [7:0] a);
    logic [8:0] sum;
    case (mode)
      3'd1:    sum = 9'(unorm_mul(s, a)) + 9'(unorm_mul(d, 8'd255 - a));
      3'd2:    sum = 9'(d) + 9'(unorm_mul(s, a));
      default: sum = 9'(s);
    endcase
`ifdef ZB_REF_DEFECT_ADDITIVE_NO_SAT
    if (mode == 3'd2) return 8'(sum);  // the defect: the additive sum wraps instead of saturating
`endif
    return sum > 9'd255 ? 8'd255 : 8'(sum);
  endfunction

  // ---------------------------------------------------------------------------------------
  // The tile and the pass state.
  // ---------------------------------------------------------------------------------------
  logic [31:0]      color_mem [Words];
  logic [D-1:0]     depth_mem [Words];
  logic [COV_W-1:0] cov_mem   [Words];
  logic [D-1:0]     peel_mem  [Words];

  logic [12:0] state_q;
  logic        depth_test, depth_write, in_profile;
  logic [2:0]  depth_func, blend;
  logic [3:0]  color_mask;
  assign depth_test  = state_q[0];
  assign depth_func  = state_q[3:1];
  assign depth_write = state_q[4];
  assign blend       = state_q[7:5];
  assign color_mask  = state_q[11:8];
  assign in_profile  = blend <= 3'd2 && !state_q[12];

  // ---------------------------------------------------------------------------------------
  // The pipeline registers.
  // ---------------------------------------------------------------------------------------
  logic             a_valid, b_valid, c_valid, d_valid;
  logic [AddrW-1:0] a_addr, b_addr, c_addr, d_addr;
  logic [D-1:0]     a_z, b_z, c_z, d_z, b_dz;
  logic [31:0]      a_rgba, b_rgba, b_dc, c_col, d_col;
  logic             a_in, b_in, c_zwe, c_cwe, d_zwe, d_cwe;

  logic [AddrW-1:0] ld_ptr_q, ld_ptr_d;
  logic             st_busy_q, st_busy_d, st_valid_q, st_read, ld_take, frag_take, hold;
  logic             pipe_busy;

  // Distance 1: the fragment in S2 has not computed its writes yet; the one in S1 waits.
  assign hold      = a_valid && b_valid && a_addr == b_addr;
  assign pipe_busy = a_valid || b_valid || c_valid || d_valid;
  assign ld_take   = ld_valid_i && ld_ready_o;
  assign frag_take = frag_valid_i && frag_ready_o;
  assign ld_ready_o   = !st_busy_q && !pipe_busy;
  assign frag_ready_o = !hold && !st_busy_q && ld_ptr_q == '0;

  // S1: the tile pixel, (y - y0) * TILE_W + (x - x0).
  logic [15:0] lx, ly;
  assign lx = frag_x_i - tile_x0_i;
  assign ly = frag_y_i - tile_y0_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_valid <= 1'b0;
      b_valid <= 1'b0;
      c_valid <= 1'b0;
      d_valid <= 1'b0;
    end else begin
      if (!hold) a_valid <= frag_take;
      b_valid <= a_valid && !hold;
      c_valid <= b_valid;
      d_valid <= c_valid;
    end
  end

  // S2's read, forwarded: S3 is the younger write, so it wins over S4.
  logic [D-1:0] rd_z;
  logic [31:0]  rd_c;
  logic         fw3_z, fw3_c, fw4_z, fw4_c;
`ifdef ZB_REF_DEFECT_FORWARD_IGNORES_WE
  // The defect: the forward is selected on the pixel alone, not on the write enables, so a
  // killed or masked fragment's computed values are forwarded as if written.
  assign fw3_z = c_valid && c_addr == a_addr;
  assign fw3_c = fw3_z;
  assign fw4_z = d_valid && d_addr == a_addr;
  assign fw4_c = fw4_z;
`else
  assign fw3_z = c_valid && c_zwe && c_addr == a_addr;
  assign fw3_c = c_valid && c_cwe && c_addr == a_addr;
  assign fw4_z = d_valid && d_zwe && d_addr == a_addr;
  assign fw4_c = d_valid && d_cwe && d_addr == a_addr;
`endif
  always_comb begin
    rd_z = depth_mem[a_addr];
    rd_c = color_mem[a_addr];
`ifndef ZB_REF_DEFECT_HAZARD_DIST3
    if (fw4_z) rd_z = d_z;
    if (fw4_c) rd_c = d_col;
`endif
`ifndef ZB_REF_DEFECT_HAZARD_DIST2
    if (fw3_z) rd_z = c_z;
    if (fw3_c) rd_c = c_col;
`endif
  end
`ifdef ZB_REF_DEFECT_HAZARD_DIST3
  // The defect: no forward from S4; a read in the edge S4 writes gets the old value.
  logic unused_fw4;
  assign unused_fw4 = fw4_z | fw4_c;
`endif
`ifdef ZB_REF_DEFECT_HAZARD_DIST2
  // The defect: no forward from S3; a read two behind a write gets the old value.
  logic unused_fw3;
  assign unused_fw3 = fw3_z | fw3_c;
`endif

  // S2 -> S3: the test, the blend and the mask.
  logic       zpass, pass, zwe, cwe;
  logic [31:0] blended, masked;
  assign zpass = !depth_test || depth_pass(depth_func, b_z, b_dz);
  assign pass  = in_profile && b_in && zpass;
`ifdef ZB_REF_DEFECT_ZWRITE_TEST_OFF
  assign zwe   = pass && depth_write;  // the defect: the write enable without the test's
`elsif ZB_REF_DEFECT_ZWRITE_KILLED
  assign zwe   = in_profile && b_in && depth_test && depth_write;  // the defect: not gated by pass
`else
  assign zwe   = pass && depth_test && depth_write;
`endif
  assign cwe   = pass && color_mask != 4'd0;
  for (genvar c = 0; c < 4; c++) begin : g_chan
    logic bit_c, keep;
    assign blended[8*c +: 8] = blend_chan(blend, b_rgba[8*c +: 8], b_dc[8*c +: 8], b_rgba[31:24]);
`ifdef ZB_REF_DEFECT_MASK_BIT_ORDER
    assign bit_c = color_mask[3 - c];  // the defect: the mask read A, B, G, R from bit 0
`else
    assign bit_c = color_mask[c];
`endif
`ifdef ZB_REF_DEFECT_MASK_ALPHA_ALWAYS
    assign keep = bit_c || (c == 3 && color_mask != 4'd0);  // the defect: alpha always written
`else
    assign keep = bit_c;
`endif
    assign masked[8*c +: 8] = keep ? blended[8*c +: 8] : b_dc[8*c +: 8];
  end

  always_ff @(posedge clk_i) begin
    if (frag_take) begin
      a_addr <= AddrW'(32'(ly) * 32'(TILE_W) + 32'(lx));
      a_z    <= frag_z_i;
      a_rgba <= frag_rgba_i;
`ifdef ZB_REF_DEFECT_TILE_LAST_COLUMN
      a_in   <= lx < 16'(TILE_W - 1);  // the defect: an in-tile guard one column short
`else
      a_in   <= 1'b1;  // the testbench sends only fragments inside the tile
`endif
    end
    b_addr <= a_addr;
    b_z    <= a_z;
    b_rgba <= a_rgba;
    b_in   <= a_in;
    b_dz   <= rd_z;
    b_dc   <= rd_c;
    c_addr <= b_addr;
    c_z    <= b_z;
    c_zwe  <= b_valid && zwe;
    c_cwe  <= b_valid && cwe;
    c_col  <= masked;
    d_addr <= c_addr;
    d_z    <= c_z;
    d_zwe  <= c_zwe;
    d_cwe  <= c_cwe;
    d_col  <= c_col;
  end

  // ---------------------------------------------------------------------------------------
  // The tile's writes (the load, or S4), its store.
  // ---------------------------------------------------------------------------------------
  logic [CntW-1:0]  st_next_q;
  logic [AddrW-1:0] st_addr;
  logic [31:0]      st_color_q;
  logic [D-1:0]     st_depth_q, st_peel_q;
  logic [COV_W-1:0] st_cov_q;

  assign ld_ptr_d  = !ld_take ? ld_ptr_q : ld_ptr_q == AddrW'(Words - 1) ? '0 : ld_ptr_q + 1'b1;
  assign st_busy_d = st_busy_q ? st_next_q != CntW'(Words) : st_start_i;
  assign st_read   = st_busy_q ? st_next_q != CntW'(Words) : st_start_i;
  assign st_addr   = st_busy_q ? AddrW'(st_next_q) : '0;

  always_ff @(posedge clk_i) begin
    if (ld_take) begin
      color_mem[ld_ptr_q] <= ld_color_i;
      depth_mem[ld_ptr_q] <= ld_depth_i;
      cov_mem[ld_ptr_q]   <= ld_cov_i;
      peel_mem[ld_ptr_q]  <= ld_peel_i;
    end else if (d_valid) begin
      if (d_zwe) depth_mem[d_addr] <= d_z;
      if (d_cwe) color_mem[d_addr] <= d_col;
    end
    if (st_read) begin
      st_color_q <= color_mem[st_addr];
      st_depth_q <= depth_mem[st_addr];
      st_cov_q   <= cov_mem[st_addr];
      st_peel_q  <= peel_mem[st_addr];
    end
  end

  // idle_o: nothing in the pipeline, no load or store, from the next state.
  logic idle_q, busy_d;
`ifdef ZB_REF_DEFECT_IDLE_EARLY
  // The defect: S4 left out, so idle_o rises while the last write is still to land.
  assign busy_d = (!hold && frag_take) || hold || (a_valid && !hold) || b_valid;
`else
  assign busy_d = (!hold && frag_take) || hold || (a_valid && !hold) || b_valid || c_valid;
`endif

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q    <= '0;
      ld_ptr_q   <= '0;
      st_busy_q  <= 1'b0;
      st_next_q  <= '0;
      st_valid_q <= 1'b0;
      idle_q     <= 1'b0;
    end else begin
      if (state_we_i) state_q <= state_i;
      ld_ptr_q   <= ld_ptr_d;
      st_busy_q  <= st_busy_d;
      st_valid_q <= st_read;
      if (st_read) st_next_q <= st_busy_q ? st_next_q + 1'b1 : CntW'(1);
      idle_q     <= !busy_d && !st_busy_d && ld_ptr_d == '0;
    end
  end

  assign idle_o     = idle_q;
  assign st_valid_o = st_valid_q;
  assign st_color_o = st_color_q;
  assign st_depth_o = st_depth_q;
  assign st_cov_o   = st_cov_q;
  assign st_peel_o  = st_peel_q;

endmodule
