// zb_ref_rop: a second, deliberately plain ROP for the conformance kit (conformance/ref/README.md),
// written from docs/datapath.md alone. One fragment at a time through a small FSM (wait, read the
// pixel, depth test, blend one channel a cycle, write), a tile memory of plain arrays loaded and
// stored a pixel a clock, and every handshake it drives dropped at random (a xorshift generator
// seeded by STALL_SEED or +zb_ref_seed=N, rate STALL_RATE or +zb_ref_stall=N of 256), so that a
// testbench that assumes zb_rop's timing fails on it.
//
// Profile (profile.json): depth test (all eight functions), depth write, colour mask, blend
// replace (0) and alpha (1). The coverage and peel planes are storage only: loaded and stored
// unchanged. A fragment of a pass outside the profile (blend 2 to 7, or the peel test) is
// killed: it writes nothing.
//
// With ZB_REF_FULL (profile_full.json) it has the whole datapath: every blend mode (additive,
// the coverage blend, under, accumulate into the accumulation plane, layers into LAYERS slots a
// pixel, resolved by a store with st_resolve_i), the peel test and the coverage plane; only
// blend 7 (invalid) is killed.
//
// Defects for the kit's own tests: ZB_REF_INJECT_BLEND_BUG drops the 0x80 rounding term of the
// unorm multiply in the alpha blend; ZB_REF_INJECT_HANG never raises frag_ready_o again once
// HangAfter fragments are taken. The ZB_REF_DEFECT_* defines are the defect catalogue
// (defects.json, README.md "Defect catalogue"): each changes only the lines it guards.
module zb_ref_rop #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 16,
  parameter int TILE_H      = 16,
  parameter logic [31:0] STALL_SEED = 32'h2545_f491,  // +zb_ref_seed=N overrides it
  parameter int STALL_RATE = 64,                      // of 256; +zb_ref_stall=N overrides it
  // The accumulate blend's widths (datapath.md "Parameters"): used with ZB_REF_FULL only.
  parameter int ACC_BITS    = 16,
  parameter int REV_BITS    = 8,
  /* verilator lint_off UNUSEDPARAM */
  parameter int WEIGHT_BITS = 4,
  parameter int LAYERS      = 4,                      // layers a pixel, 1 to 8 (ZB_REF_FULL only)
  /* verilator lint_on UNUSEDPARAM */
  parameter int COV_W = $clog2(COV_SAMPLES + 1),      // derived: the coverage count's width
  parameter int ACC_W = 4 * ACC_BITS + REV_BITS       // derived: {r, acc_A, acc_B, acc_G, acc_R}
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  // The pass state register (datapath.md "The pass state"), written while idle_o.
  input  logic                  state_we_i,
  input  logic [12:0]           state_i,
  input  logic [2:0]            state_layers_i,  // the pass state's [15:13], K - 1 (ZB_REF_FULL)
  // The resident tile's origin in frame pixels.
  input  logic [15:0]           tile_x0_i,
  input  logic [15:0]           tile_y0_i,
  // Tile load: TILE_W * TILE_H pixels in raster order, one per ld_valid_i && ld_ready_o.
  input  logic                  ld_valid_i,
  output logic                  ld_ready_o,
  input  logic [31:0]           ld_color_i,
  input  logic [DEPTH_BITS-1:0] ld_depth_i,
  input  logic [COV_W-1:0]      ld_cov_i,
  input  logic [DEPTH_BITS-1:0] ld_peel_i,
  input  logic [ACC_W-1:0]      ld_acc_i,   // read with ZB_REF_FULL only
  // Fragments in frame coordinates, inside the tile.
  input  logic                  frag_valid_i,
  output logic                  frag_ready_o,
  input  logic [15:0]           frag_x_i,
  input  logic [15:0]           frag_y_i,
  input  logic [DEPTH_BITS-1:0] frag_z_i,
  input  logic [31:0]           frag_rgba_i,
  input  logic [COV_W-1:0]      frag_cov_i, // read with ZB_REF_FULL only (the coverage blend)
  // No fragment in flight, no load or store under way; rises a random number of cycles late.
  output logic                  idle_o,
  // Tile store: a pulse while idle; pixel 0 is offered in the cycle right after the edge that
  // takes it (resolving the layers: LAYERS cycles later), then one pixel each cycle st_valid_o
  // is high, in raster order.
  input  logic                  st_start_i,
  input  logic                  st_resolve_i,  // with st_start_i: resolve the layers (ZB_REF_FULL)
  output logic                  st_valid_o,
  output logic [31:0]           st_color_o,
  output logic [DEPTH_BITS-1:0] st_depth_o,
  output logic [COV_W-1:0]      st_cov_o,
  output logic [DEPTH_BITS-1:0] st_peel_o,
  output logic [ACC_W-1:0]      st_acc_o,   // zero without ZB_REF_FULL
  output logic [3:0]            layers_o    // LAYERS with ZB_REF_FULL, else 0 (no layers)
);

  localparam int Words = TILE_W * TILE_H;
  localparam int AddrW = Words > 1 ? $clog2(Words) : 1;
  localparam int CntW  = $clog2(Words + 1);  // counts 0 .. Words
  localparam int D     = DEPTH_BITS;

  // ---------------------------------------------------------------------------------------
  // datapath.md "3. Blend": m(x, y) = (t + (t >> 8) + 0x80) >> 8, t = x * y. The sum is at
  // most 65025 + 254 + 128 < 2^16.
  // ---------------------------------------------------------------------------------------
  function automatic logic [7:0] unorm_mul(input logic [7:0] x, input logic [7:0] y);
    logic [15:0] t, s;
    t = 16'(x) * 16'(y);
`ifdef ZB_REF_INJECT_BLEND_BUG
    s = t + (t >> 8);  // the defect: truncates where it should round
`elsif ZB_REF_DEFECT_UNORM_EXACT_ROUND
    // The defect: the textbook x*y/255 rounded to nearest, not m (24 pairs round up where m
    // rounds down, e.g. 152 x 229).
    s = t + 16'h0080;
    s = s + (s >> 8);
`else
    s = t + (t >> 8) + 16'h0080;
`endif
    return 8'(s >> 8);
  endfunction

  // A declared arithmetic other than zblend's (docs/datapath.md "Declared arithmetic"): the
  // alpha and additive blends divide their sum once. ZB_REF_ARITH_SUM_ROUND255 (t / 255 rounded
  // half up: c = t + 128, (c + (c >> 8)) >> 8), _CEIL256 ((t + 255) >> 8), _FLOOR256 (t >> 8);
  // the profile says which ("arithmetic"). The quotient is at most 9 bits (the additive sum
  // reaches 2 * 65025).
`ifdef ZB_REF_ARITH_SUM_ROUND255
  `define ZB_REF_ARITH_SUM
`elsif ZB_REF_ARITH_SUM_CEIL256
  `define ZB_REF_ARITH_SUM
`elsif ZB_REF_ARITH_SUM_FLOOR256
  `define ZB_REF_ARITH_SUM
`endif
`ifdef ZB_REF_ARITH_SUM
  function automatic logic [8:0] sum_div(input logic [17:0] t);
    logic [17:0] c;
`ifdef ZB_REF_ARITH_SUM_ROUND255
`ifdef ZB_REF_DEFECT_ARITH_NO_HALF
    c = t;  // the defect: the half before the division forgotten, t / 255 truncated
`else
    c = t + 18'h80;
`endif
    c = (c + (c >> 8)) >> 8;
`elsif ZB_REF_ARITH_SUM_CEIL256
`ifdef ZB_REF_DEFECT_ARITH_CEIL_AS_ROUND
    c = (t + 18'h80) >> 8;  // the defect: the declared ceil computed as round
`else
    c = (t + 18'hff) >> 8;
`endif
`else
    c = t >> 8;
`endif
    return c > 18'd255 ? 9'd256 : 9'(c);
  endfunction
`endif

  // One channel of the alpha blend: min(255, m(s, a) + m(d, 255 - a)); the alpha channel is the
  // same with s = a.
  function automatic logic [7:0] blend_alpha(input logic [7:0] s, input logic [7:0] d,
                                             input logic [7:0] a);
    logic [8:0] sum;
`ifdef ZB_REF_ARITH_SUM
    logic [7:0] inv;
`endif
`ifdef ZB_REF_DEFECT_ALPHA_OPAQUE_MSB
    if (a[7]) return s;  // the defect: an "opaque" fast path keyed on the alpha's top bit
`endif
`ifdef ZB_REF_ARITH_SUM
    inv = 8'd255 - a;
`ifdef ZB_REF_DEFECT_ARITH_ONE256
    // The defect: 1 - a formed as 256 - a beside a division by 256, where the rule says 255 - a.
    sum = sum_div(18'(16'(s) * 16'(a)) + 18'(16'(16'(d) * (16'(inv) + 16'd1))));
`else
    sum = sum_div(18'(16'(s) * 16'(a)) + 18'(16'(d) * 16'(inv)));
`endif
`else
    sum = 9'(unorm_mul(s, a)) + 9'(unorm_mul(d, 8'd255 - a));
`endif
    return sum > 9'd255 ? 8'd255 : 8'(sum);
  endfunction

  // datapath.md "1. Depth test": z (left) against the stored depth (right), unsigned.
`ifdef ZB_REF_DEFECT_ZCMP_LOW24
  localparam int CmpW = D > 24 ? 24 : D;  // the defect: a comparator sized for the 24-bit default
`else
  localparam int CmpW = D;
`endif
  function automatic logic depth_pass(input logic [2:0] func, input logic [CmpW-1:0] z,
                                      input logic [CmpW-1:0] stored);
    case (func)
      3'd0:    return 1'b0;          // never
      3'd1:    return z <  stored;   // less
      3'd2:    return z == stored;   // equal
      3'd3:    return z <= stored;   // lequal
      3'd4:    return z >  stored;   // greater
`ifdef ZB_REF_DEFECT_FUNC_SWAP_NE_GE
      3'd5:    return z >= stored;   // the defect: notequal and gequal swapped
      3'd6:    return z != stored;
`else
      3'd5:    return z != stored;   // notequal
      3'd6:    return z >= stored;   // gequal
`endif
      default: return 1'b1;          // always
    endcase
  endfunction

  // ---------------------------------------------------------------------------------------
  // Stalls: xorshift32, one step a cycle; each port reads its own byte of it.
  // ---------------------------------------------------------------------------------------
  int unsigned seed, rate;
  initial begin
    if (!$value$plusargs("zb_ref_seed=%d", seed)) seed = STALL_SEED;
    if (!$value$plusargs("zb_ref_stall=%d", rate)) rate = STALL_RATE;
    if (seed == 0) seed = 1;  // xorshift's fixed point
    $display("zb_ref_rop: stall seed %0d, stall rate %0d of 256", seed, rate);
  end

  logic [31:0] rng_q, rng_d;
  always_comb begin
    rng_d = rng_q ^ (rng_q << 13);
    rng_d = rng_d ^ (rng_d >> 17);
    rng_d = rng_d ^ (rng_d << 5);
  end

  logic stall_ld, stall_frag, stall_st, idle_rise;
  assign stall_ld   = 32'(rng_q[7:0]) < rate;
  assign stall_frag = 32'(rng_q[15:8]) < rate;
  assign stall_st   = 32'(rng_q[23:16]) < rate;
  assign idle_rise  = rng_q[25:24] == 2'd0;  // idle_o rises about 4 cycles late

  // ---------------------------------------------------------------------------------------
  // The tile: plain arrays, one word per pixel.
  // ---------------------------------------------------------------------------------------
  logic [31:0]      color_mem [Words];
  logic [D-1:0]     depth_mem [Words];
  logic [COV_W-1:0] cov_mem   [Words];
  logic [D-1:0]     peel_mem  [Words];
`ifdef ZB_REF_FULL
  logic [ACC_W-1:0] acc_mem   [Words];
`endif

  // The pass state's fields.
  logic [12:0] state_q;
  logic        depth_test, depth_write, peel_test;
  logic [2:0]  depth_func, blend;
  logic [3:0]  color_mask;
  assign depth_test  = state_q[0];
  assign depth_func  = state_q[3:1];
  assign depth_write = state_q[4];
  assign blend       = state_q[7:5];
`ifdef ZB_REF_DEFECT_MASK_FIELD_OFFSET
  assign color_mask  = state_q[12:9];  // the defect: the mask read one bit too high
  logic unused_mask_r;
  assign unused_mask_r = state_q[8];
`else
  assign color_mask  = state_q[11:8];
`endif
`ifdef ZB_REF_DEFECT_PEEL_LATCHED_WITH_UNDER
  // The defect: peel_test in its own flop, loaded only by a state word of the under blend (the
  // peeling blend); the depth-only peel passes keep the previous pass's bit.
  logic peel_q, unused_peel_bit;
  assign peel_test = peel_q;
  assign unused_peel_bit = state_q[12];
`else
  assign peel_test   = state_q[12];
`endif

  // ---------------------------------------------------------------------------------------
  // The fragment FSM: one fragment from its acceptance to its write, nothing overlapped.
  // ---------------------------------------------------------------------------------------
  // FLayer and FMerge (ZB_REF_FULL): a layers fragment's walk over its pixel's slots, a slot a
  // cycle, and the merge of the two farthest when the pixel was full.
  typedef enum logic [2:0] { FWait, FRead, FTest, FBlend, FWrite, FLayer, FMerge } fsm_e;
  fsm_e             fsm_q, fsm_d;
  logic [AddrW-1:0] addr_q, frag_addr;
  logic [D-1:0]     z_q, dst_z_q;
  logic [31:0]      src_q, dst_q;               // the fragment's colour, the stored one
  logic [31:0]      src_sh_q, dst_sh_q, out_q;  // the blend's operands and result, a byte a cycle
  logic [1:0]       chan_q;
  logic             zwe_q, cwe_q, frag_take, ld_take, pass, in_profile, zwe_d, cwe_d;
  logic             kill_wr_d;  // a killed fragment that still writes (a defect's path)
  logic             lay_pass, lay_we_d;  // a passing layers fragment; one that inserts (mask not 0)
  logic [AddrW-1:0] ld_ptr_q, ld_ptr_d;

  assign frag_take  = frag_valid_i && frag_ready_o;
  assign ld_take    = ld_valid_i && ld_ready_o;
  // The tile pixel: (y - y0) * TILE_W + (x - x0).
  logic [15:0] frag_lx, frag_ly;
`ifdef ZB_REF_DEFECT_TILE_ORIGIN_X
  assign frag_lx    = frag_x_i;  // the defect: the column from frame coordinates, origin forgotten
  logic unused_x0;
  assign unused_x0 = ^tile_x0_i;
`else
  assign frag_lx    = frag_x_i - tile_x0_i;
`endif
  assign frag_ly    = frag_y_i - tile_y0_i;
  assign frag_addr  = AddrW'(32'(frag_ly) * 32'(TILE_W) + 32'(frag_lx));

  logic zpass;  // the depth test alone
  assign zpass = !depth_test || depth_pass(depth_func, z_q[CmpW-1:0], dst_z_q[CmpW-1:0]);
`ifdef ZB_REF_DEFECT_ZCMP_LOW24
  logic unused_ztop;  // the stored depth's top byte, dropped (the subset reads it nowhere else)
  assign unused_ztop = ^dst_z_q;
`endif

`ifdef ZB_REF_FULL
  // ---------------------------------------------------------------------------------------
  // The rest of the datapath: peel test, coverage blend, under, accumulate.
  // ---------------------------------------------------------------------------------------
  localparam int N    = COV_SAMPLES;
  localparam int L    = $clog2(N);                                // N is a power of two
  localparam int A    = ACC_BITS;
  localparam int R    = REV_BITS;
  localparam int W    = WEIGHT_BITS;
  localparam int S    = W + 20 > A ? W + 20 - A : 0;              // the term's shift
`ifndef ZB_REF_DEFECT_ACC_NO_SAT
  localparam logic [63:0] AccMax = (64'd1 << A) - 64'd1;
`endif
`ifdef ZB_REF_DEFECT_COV_WEIGHT_WIDTH
  localparam int Lw = L > 0 ? L : 1;
`endif

  logic [D-1:0]     peel_rd_q;
  logic [COV_W-1:0] cs_q, k_q, cs_new_q, cs_new_d;
  logic [ACC_W-1:0] acc_rd_q, acc_sh_q, acc_out_q;
  logic [R-1:0]     rev_new_q, rev_new_d;
  logic [31:0]      cw_q, cw_d;       // the coverage blend's w, 0 .. N
  logic [31:0]      wgt_q, wgt_d;     // the accumulate blend's w = a * F
  logic             covwe_q, awe_q, covwe_d, awe_d, ppass, nearer, farther, full;

  // datapath.md "Peel test": strictly behind the peel plane.
`ifdef ZB_REF_DEFECT_PEEL_SIGNED
  assign ppass = $signed(z_q) > $signed(peel_rd_q);  // the defect: depths compared as signed
`else
  assign ppass = z_q > peel_rd_q;
`endif

  // "5. Coverage blend": three ways, with the coverage counts.
  logic [COV_W:0] ksum;  // k + cs, up to 2N
  assign nearer  = z_q < dst_z_q;
  assign farther = z_q > dst_z_q;
  assign ksum    = (COV_W + 1)'(k_q) + (COV_W + 1)'(cs_q);
`ifdef ZB_REF_DEFECT_COV_FULL_COUNT
  assign full    = ksum > (COV_W + 1)'(N);   // the defect: exactly N samples not taken as full
`else
  assign full    = ksum >= (COV_W + 1)'(N);
`endif

  // One channel of the coverage blend: (w * Cf + (N - w) * Cs + N/2) >> L.
  function automatic logic [7:0] blend_cov(input logic [7:0] s, input logic [7:0] d,
                                           input logic [31:0] w);
    logic [31:0] nw, sum;
`ifdef ZB_REF_DEFECT_COV_WEIGHT_WIDTH
    // The defect: N - w held in log2(N) bits, as w "needs" only L bits; N - 0 = N wraps to 0.
    nw = 32'(Lw'(32'(N) - w));
`else
    nw = 32'(N) - w;
`endif
    sum = w * 32'(s) + nw * 32'(d) + 32'(N / 2);
    return 8'(sum >> L);
  endfunction

  // "6. Under blend": R, G, B: min(255, d + m(m(s, a), t)); A: min(255, as + m(a, t)).
  function automatic logic [7:0] blend_under(input logic [7:0] s, input logic [7:0] d,
                                             input logic [7:0] a, input logic [7:0] da,
                                             input logic is_alpha);
    logic [7:0] t, p;
    logic [8:0] sum;
    t = 8'd255 - da;
    if (is_alpha) p = unorm_mul(a, t);
`ifdef ZB_REF_DEFECT_UNDER_REASSOC
    else p = unorm_mul(s, unorm_mul(a, t));  // the defect: s * (a * t), not (s * a) * t
`else
    else p = unorm_mul(unorm_mul(s, a), t);
`endif
    sum = 9'(d) + 9'(p);
    return sum > 9'd255 ? 8'd255 : 8'(sum);
  endfunction

  // "2. additive": min(255, d + m(s, a)).
  function automatic logic [7:0] blend_add(input logic [7:0] s, input logic [7:0] d,
                                           input logic [7:0] a);
    logic [8:0] sum;
`ifdef ZB_REF_ARITH_SUM
    sum = sum_div(18'(16'(s) * 16'(a)) + 18'(16'(d) * 16'd255));
`else
    sum = 9'(d) + 9'(unorm_mul(s, a));
`endif
    return sum > 9'd255 ? 8'd255 : 8'(sum);
  endfunction

  // "7. Accumulate blend", one channel: acc' = min(2^A - 1, acc + ((p * w) >> S)).
  function automatic logic [A-1:0] accumulate(input logic [A-1:0] acc, input logic [7:0] p,
                                              input logic [31:0] w);
    logic [63:0] term;
    term = (64'(p) * 64'(w)) >> S;
`ifdef ZB_REF_DEFECT_ACC_NO_SAT
    return A'(64'(acc) + term);  // the defect: the channel wraps instead of saturating
`else
    return 64'(acc) + term > AccMax ? A'(AccMax) : A'(64'(acc) + term);
`endif
  endfunction

  // The fragment side of the accumulate blend: w = a * max(1, u^3 >> (24 - W)), u the top 8
  // bits of ZMAX - z.
  logic [7:0]    u;
  logic [31:0]   u3, wf;
  assign u    = 8'((~z_q) >> (D - 8));  // ZMAX - z is ~z
  assign u3   = 32'(u) * 32'(u) * 32'(u);
`ifdef ZB_REF_DEFECT_ACC_WEIGHT_FLOOR
  assign wf   = u3 >> (24 - W);  // the defect: no floor of 1; far fragments weigh nothing
`else
  assign wf   = (u3 >> (24 - W)) == 32'd0 ? 32'd1 : u3 >> (24 - W);
`endif
  assign wgt_d = 32'(src_q[31:24]) * wf;

  // The revealage: (r * t + 128) >> 8, t = k + (k >> 7), k = 255 - a.
  logic [8:0]  ta;
  logic [31:0] rt;
`ifdef ZB_REF_DEFECT_REVEAL_256_MINUS_A
  assign ta = 9'd256 - 9'(src_q[31:24]);  // the defect: 1 - a taken as 256 - a
`else
  logic [7:0]  ka;
  assign ka = 8'd255 - src_q[31:24];
  assign ta = 9'(ka) + 9'(ka[7]);  // k + (k >> 7)
`endif
`ifdef ZB_REF_DEFECT_REVEAL_NO_ROUND
  assign rt = 32'(acc_rd_q[4*A +: R]) * 32'(ta);  // the defect: truncates, no + 128
`else
  assign rt = 32'(acc_rd_q[4*A +: R]) * 32'(ta) + 32'd128;
`endif
  assign rev_new_d = R'(rt >> 8);

  // The coverage blend's case (datapath.md's table): w and the new coverage.
  always_comb begin
    logic [COV_W-1:0] combined;
`ifdef ZB_REF_DEFECT_COV_NO_SAT
    combined = COV_W'(ksum);  // the defect: k + cs kept in CovW bits, no min(N, .)
`else
    combined = ksum > (COV_W + 1)'(N) ? COV_W'(N) : COV_W'(ksum);
`endif
    if (nearer) begin
      cw_d = 32'(k_q);
      cs_new_d = combined;
    end else if (farther) begin
`ifdef ZB_REF_DEFECT_COV_FARTHER_WEIGHT
      cw_d = 32'(cs_q);  // the defect: the background's count weighs the fragment
`else
      cw_d = 32'(N) - 32'(cs_q);
`endif
      cs_new_d = combined;
    end else if (full) begin
      cw_d = 32'(N);
      cs_new_d = COV_W'(N);
    end else begin
      cw_d = 32'(k_q);
      cs_new_d = combined;
    end
  end

  assign in_profile = blend <= 3'd6;
  // The coverage blend passes every fragment; the others test depth, then the peel plane.
  assign pass = blend == 3'd3 ? 1'b1 : in_profile && zpass && (!peel_test || ppass);
  always_comb begin
    if (blend == 3'd3) begin
      // Depth moves only in the nearer case, and only with the test and the write on.
`ifdef ZB_REF_DEFECT_COV_ZWRITE_STATE
      zwe_d = nearer;  // the defect: the nearer case writes depth whatever the state says
`else
      zwe_d = nearer && depth_test && depth_write;
`endif
    end else begin
`ifdef ZB_REF_DEFECT_ZWRITE_IGNORES_PEEL
      zwe_d = in_profile && zpass && depth_test && depth_write;  // the defect: before the peel test
`else
      zwe_d = pass && depth_test && depth_write;
`endif
    end
  end
  assign cwe_d   = pass && color_mask != 4'd0 && blend != 3'd5 && blend != 3'd6;
  assign kill_wr_d = !pass && zwe_d;
  assign covwe_d = blend == 3'd3;
`ifdef ZB_REF_DEFECT_ACCUM_MASK_ZERO
  assign awe_d   = pass && blend == 3'd5;  // the defect: the accumulation word ignores the mask
`else
  assign awe_d   = pass && blend == 3'd5 && color_mask != 4'd0;
`endif

  // One channel of the blend, the channel in the operands' low bytes.
  logic [7:0] chan_out;
  assign chan_out =
      blend == 3'd1 ? blend_alpha(src_sh_q[7:0], dst_sh_q[7:0], src_q[31:24]) :
      blend == 3'd2 ? blend_add(src_sh_q[7:0], dst_sh_q[7:0], src_q[31:24]) :
      blend == 3'd3 ? blend_cov(src_sh_q[7:0], dst_sh_q[7:0], cw_q) :
      blend == 3'd4 ? blend_under(src_sh_q[7:0], dst_sh_q[7:0], src_q[31:24], dst_q[31:24],
                                  chan_q == 2'd3) :
      src_sh_q[7:0];  // replace; accumulate writes no colour

  // One accumulation channel: p = m(s, a) for R, G, B, p = a for A.
  logic [7:0] acc_p;
  assign acc_p = chan_q == 2'd3 ? src_q[31:24] : unorm_mul(src_sh_q[7:0], src_q[31:24]);

  always_ff @(posedge clk_i) begin
    if (frag_take) k_q <= frag_cov_i;
    if (fsm_q == FRead) begin
      peel_rd_q <= peel_mem[addr_q];
      cs_q      <= cov_mem[addr_q];
      acc_rd_q  <= acc_mem[addr_q];
    end
    if (fsm_q == FTest) begin
      covwe_q   <= covwe_d;
      awe_q     <= awe_d;
      cs_new_q  <= cs_new_d;
      cw_q      <= cw_d;
      wgt_q     <= wgt_d;
      rev_new_q <= rev_new_d;
      acc_sh_q  <= acc_rd_q;
      acc_out_q <= acc_rd_q;
    end
    if (fsm_q == FBlend) begin
      // As the colour: the lane in acc_sh_q's low bits, its result entering at the top; after
      // four cycles the four channels are in their lanes and the revealage at the top is the
      // one read (replaced at the write).
      acc_out_q <= {acc_out_q[4*A +: R], accumulate(acc_sh_q[A-1:0], acc_p, wgt_q),
                    acc_out_q[A +: 3*A]};
      acc_sh_q  <= acc_sh_q >> A;
    end
  end

  // ---------------------------------------------------------------------------------------
  // "8. Layers": per pixel LAYERS slots {z, A, R, G, B} (B at bit 0), nearest first, so that a
  // slot read as a number is the order's key; A = 0 is an empty slot (every slot after a load).
  // A layers fragment walks slots 0 .. K - 1, a slot a cycle, carrying a layer (its own at
  // first): the carried layer goes into an empty slot, or into the place of a layer whose key is
  // above its own, carrying that one on; so it lands after every layer whose key is at most its
  // own. A layer still carried after slot K - 1 is the farthest of K + 1: FMerge merges it
  // behind slot K - 1.
  // ---------------------------------------------------------------------------------------
  localparam int SW = D + 32;                           // a slot
  localparam int LW = LAYERS > 1 ? $clog2(LAYERS) : 1;  // a slot's index

  logic [SW-1:0] lay_mem [LAYERS][Words];
  logic [2:0]    lay_k1_q;  // the pass state's K - 1
  logic [LW-1:0] lay_j_q, lay_last;
  logic [SW-1:0] carry_q, carry_d, lay_cur, lay_merged;
  logic          lay_take, lay_before, lay_over;

  assign lay_pass = pass && blend == 3'd6;
  assign lay_we_d = lay_pass && color_mask != 4'd0;
  // K - 1, at most LAYERS - 1.
  assign lay_last = 32'(lay_k1_q) > LAYERS - 1 ? LW'(LAYERS - 1) : LW'(lay_k1_q);

  // A fragment's layer: p = m(s, a) a colour channel, A = a.
  function automatic logic [SW-1:0] frag_layer(input logic [D-1:0] z, input logic [31:0] c);
    return {z, c[31:24], unorm_mul(c[7:0], c[31:24]), unorm_mul(c[15:8], c[31:24]),
            unorm_mul(c[23:16], c[31:24])};
  endfunction

  // The merge's product m(p_B, 255 - A_F).
  function automatic logic [7:0] merge_mul(input logic [7:0] x, input logic [7:0] y);
`ifdef ZB_REF_DEFECT_LAYERS_MERGE_ROUND
    logic [15:0] t;
    t = 16'(x) * 16'(y);
    return 8'((t + (t >> 8)) >> 8);  // the defect: no + 0x80, the product truncated
`else
    return unorm_mul(x, y);
`endif
  endfunction

  // Front f over back b as one layer: min(255, f + m(b, 255 - A_f)) every byte, f's depth.
  function automatic logic [SW-1:0] merge_layers(input logic [SW-1:0] f, input logic [SW-1:0] b);
    logic [SW-1:0] r;
    logic [8:0]    sum;
    r = f;
    for (int c = 0; c < 4; c++) begin
      sum = 9'(f[8*c +: 8]) + 9'(merge_mul(b[8*c +: 8], 8'd255 - f[31:24]));
      r[8*c +: 8] = sum > 9'd255 ? 8'd255 : 8'(sum);
    end
    return r;
  endfunction

  assign lay_cur = lay_mem[lay_j_q][addr_q];
`ifdef ZB_REF_DEFECT_LAYERS_EQUAL_ORDER
  // The defect: depths alone, with <=: at equal depth the new layer goes before the others.
  assign lay_before = carry_q[SW-1:32] <= lay_cur[SW-1:32];
`else
  assign lay_before = carry_q < lay_cur;
`endif
  assign lay_take = carry_q[31:24] != 8'd0 && (lay_cur[31:24] == 8'd0 || lay_before);
  assign carry_d  = lay_take ? lay_cur : carry_q;
  assign lay_over = carry_d[31:24] != 8'd0;  // a layer carried past the slot
`ifdef ZB_REF_DEFECT_LAYERS_DROP
  assign lay_merged = lay_mem[lay_last][addr_q];  // the defect: the farthest dropped, not merged
`else
  assign lay_merged = merge_layers(lay_mem[lay_last][addr_q], carry_q);
`endif

  always_ff @(posedge clk_i) begin
    if (fsm_q == FTest) begin
      carry_q <= frag_layer(z_q, src_q);  // alpha 0: an empty layer, never placed
      lay_j_q <= '0;
    end
    if (fsm_q == FLayer) begin
      carry_q <= carry_d;
      lay_j_q <= lay_j_q + LW'(1);
    end
  end

`ifdef ZB_REF_DEFECT_LAYERS_LEFT_OVER
  // The defect's only clear: every slot emptied once, at time 0.
  initial for (int j = 0; j < LAYERS; j++) for (int i = 0; i < Words; i++) lay_mem[j][i] = '0;
`endif
  // A load empties its pixel's slots; the walk and the merge write one slot. Never in the same
  // cycle: a load pixel is taken only with no fragment in flight.
  always_ff @(posedge clk_i) begin
    if (ld_take) begin
`ifdef ZB_REF_DEFECT_LAYERS_LEFT_OVER
      // The defect: the load leaves the layers, so the previous tile's stay.
`else
      for (int j = 0; j < LAYERS; j++) lay_mem[j][ld_ptr_q] <= '0;
`endif
    end else if (fsm_q == FLayer && lay_take) lay_mem[lay_j_q][addr_q] <= carry_q;
    else if (fsm_q == FMerge) lay_mem[lay_last][addr_q] <= lay_merged;
  end

`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
  logic [2:0] lay_k1_w_q;  // held with the rest of the state until a load begins (the defect)
`endif
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lay_k1_q <= '0;
`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
      lay_k1_w_q <= '0;
`endif
    end else begin
`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
      if (state_we_i) lay_k1_w_q <= state_layers_i;
      if (ld_take && ld_ptr_q == '0) lay_k1_q <= lay_k1_w_q;
`else
      if (state_we_i) lay_k1_q <= state_layers_i;
`endif
    end
  end

  // One step of the resolve: min(255, acc + m(p, t)) every channel, in the colour plane's byte
  // order (R at bit 0). Over the opaque colour is the same step with p = o.
  function automatic logic [31:0] under_step(input logic [31:0] acc, input logic [31:0] p,
                                             input logic [7:0] t);
    logic [31:0] r;
    logic [8:0]  sum;
    for (int c = 0; c < 4; c++) begin
      sum = 9'(acc[8*c +: 8]) + 9'(unorm_mul(p[8*c +: 8], t));
      r[8*c +: 8] = sum > 9'd255 ? 8'd255 : 8'(sum);
    end
    return r;
  endfunction
`else
  assign in_profile = blend <= 3'd1 && !peel_test;
  assign pass       = in_profile && zpass;
  assign zwe_d      = depth_test && depth_write;  // datapath.md "2. Depth write"
  assign cwe_d      = color_mask != 4'd0;
  assign kill_wr_d  = 1'b0;
  assign lay_pass   = 1'b0;
  assign lay_we_d   = 1'b0;
  logic [7:0] chan_out;
  assign chan_out = blend_alpha(src_sh_q[7:0], dst_sh_q[7:0], src_q[31:24]);
`endif

  always_comb begin
    fsm_d = fsm_q;
    case (fsm_q)
      FWait:   if (frag_take) fsm_d = FRead;
      FRead:   fsm_d = FTest;
      FTest:   if (lay_we_d) fsm_d = FLayer;
               else if (lay_pass) fsm_d = FWrite;  // colour mask 0: the depth write alone
               else if (pass && blend != 3'd0) fsm_d = FBlend;
               else if (pass || kill_wr_d) fsm_d = FWrite;
               else fsm_d = FWait;  // killed: nothing written
      FBlend:  if (chan_q == 2'd3) fsm_d = FWrite;
      FWrite:  fsm_d = FWait;
`ifdef ZB_REF_FULL
      // After slot K - 1: the merge when a layer is still carried (the pixel held K).
      FLayer:  if (lay_j_q == lay_last && lay_over) fsm_d = FMerge;
               else if (lay_j_q == lay_last) fsm_d = FWrite;
      FMerge:  fsm_d = FWrite;
`endif
      default: fsm_d = FWait;
    endcase
  end

`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
  // The defect: the state word is held in a shadow register and copied into the working one
  // when a tile load begins, so a state write to a resident tile waits for the next load.
  logic [12:0] state_w_q;
`endif

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fsm_q   <= FWait;
      state_q <= '0;
      chan_q  <= '0;
      zwe_q   <= 1'b0;
      cwe_q   <= 1'b0;
`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
      state_w_q <= '0;
`endif
`ifdef ZB_REF_DEFECT_PEEL_LATCHED_WITH_UNDER
      peel_q  <= 1'b0;
`endif
    end else begin
      fsm_q <= fsm_d;
`ifdef ZB_REF_DEFECT_STATE_AT_LOAD
      if (state_we_i) state_w_q <= state_i;
      if (ld_take && ld_ptr_q == '0) state_q <= state_w_q;
`else
      if (state_we_i) state_q <= state_i;
`endif
`ifdef ZB_REF_DEFECT_PEEL_LATCHED_WITH_UNDER
      if (state_we_i && state_i[7:5] == 3'd4) peel_q <= state_i[12];
`endif
      if (fsm_q == FTest) begin
        zwe_q  <= zwe_d;
        cwe_q  <= cwe_d;
        chan_q <= '0;
      end
      if (fsm_q == FBlend) chan_q <= chan_q + 2'd1;
    end
  end

  // Datapath registers, no reset: each is written before it is read.
  always_ff @(posedge clk_i) begin
    if (frag_take) begin
      addr_q <= frag_addr;
      z_q    <= frag_z_i;
      src_q  <= frag_rgba_i;
    end
    if (fsm_q == FRead) begin
      dst_q   <= color_mem[addr_q];
      dst_z_q <= depth_mem[addr_q];
    end
    if (fsm_q == FTest) begin
      src_sh_q <= src_q;
      dst_sh_q <= dst_q;
      out_q    <= src_q;  // replace; a blend overwrites it a byte a cycle
    end
    if (fsm_q == FBlend) begin
      // The channel in the operands' low bytes; its result enters out_q at the top, so after
      // four cycles R, G, B and A are in their lanes.
      out_q    <= {chan_out, out_q[31:8]};
      src_sh_q <= src_sh_q >> 8;
      dst_sh_q <= dst_sh_q >> 8;
    end
  end

  // datapath.md "4. Colour write mask": a channel keeps its stored value where its bit is 0.
  logic [31:0] masked;
  always_comb
    for (int c = 0; c < 4; c++) masked[8*c +: 8] = color_mask[c] ? out_q[8*c +: 8] : dst_q[8*c +: 8];

  // ---------------------------------------------------------------------------------------
  // Load and store.
  // ---------------------------------------------------------------------------------------
  logic             st_busy_q, st_busy_d, st_valid_q, st_read;
  logic             st_hold, st_offer;  // a resolve walk under way; a pixel offered next cycle
  logic [CntW-1:0]  st_next_q;  // the next pixel to read out, Words when all are read
  logic [AddrW-1:0] st_addr;
  logic [31:0]      st_color_q;
  logic [D-1:0]     st_depth_q, st_peel_q;
  logic [COV_W-1:0] st_cov_q;

  assign ld_ptr_d  = !ld_take ? ld_ptr_q : ld_ptr_q == AddrW'(Words - 1) ? '0 : ld_ptr_q + 1'b1;
  // A store runs from the edge that takes st_start_i to the edge that takes its last pixel.
  assign st_busy_d = st_busy_q ? st_next_q != CntW'(Words) || st_hold : st_start_i;
  // The first pixel is read at the edge that takes st_start_i, whatever the stall byte says.
  assign st_read   = st_busy_q ? st_next_q != CntW'(Words) && !stall_st && !st_hold : st_start_i;
  assign st_addr   = st_busy_q ? AddrW'(st_next_q) : '0;

`ifdef ZB_REF_FULL
  // The resolve (st_resolve_i with st_start_i): after a pixel's read, its slots under acc, one
  // a cycle front to back, then its colour under acc is offered; the next read waits for the
  // edge that takes it, as st_color_q holds it.
  logic             rs_on_q, rs_on_d, rs_walk_q, rs_done;
  logic [LW-1:0]    rs_j_q, rs_slot;
  logic [AddrW-1:0] rs_addr_q;
  logic [SW-1:0]    rs_lay;
  logic [31:0]      rs_acc_q, rs_acc_d, rs_color;
  logic [7:0]       rs_t;
  assign rs_on_d = st_busy_q ? rs_on_q : st_start_i && st_resolve_i;
  assign rs_done = rs_walk_q && rs_j_q == LW'(LAYERS - 1);
`ifdef ZB_REF_DEFECT_LAYERS_RESOLVE_ORDER
  assign rs_slot = LW'(LAYERS - 1) - rs_j_q;  // the defect: back to front
`else
  assign rs_slot = rs_j_q;
`endif
  assign rs_lay = lay_mem[rs_slot][rs_addr_q];
`ifdef ZB_REF_DEFECT_LAYERS_TRANS_SAT
  assign rs_t = 8'd0 - rs_acc_q[31:24];  // the defect: 1 - acc_A as 256 - acc_A, 0 at acc_A = 0
`else
  assign rs_t = 8'd255 - rs_acc_q[31:24];
`endif
  // The slot's {A, R, G, B} in the colour plane's order {A, B, G, R}.
  assign rs_acc_d = under_step(rs_acc_q, {rs_lay[31:24], rs_lay[7:0], rs_lay[15:8], rs_lay[23:16]},
                               rs_t);
  assign rs_color = under_step(rs_acc_d, st_color_q, 8'd255 - rs_acc_d[31:24]);
  assign st_hold  = rs_walk_q;
  assign st_offer = rs_on_d ? rs_done : st_read;
  logic unused_rs_z;
  assign unused_rs_z = ^rs_lay[SW-1:32];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rs_on_q   <= 1'b0;
      rs_walk_q <= 1'b0;
    end else begin
      rs_on_q <= rs_on_d;
      if (st_read) rs_walk_q <= rs_on_d;
      else if (rs_done) rs_walk_q <= 1'b0;
    end
  end
  always_ff @(posedge clk_i) begin
    if (st_read) begin
      rs_j_q    <= '0;
      rs_acc_q  <= '0;
      rs_addr_q <= st_addr;
    end else if (rs_walk_q) begin
      rs_j_q   <= rs_j_q + LW'(1);
      rs_acc_q <= rs_acc_d;
    end
  end
`else
  assign st_hold  = 1'b0;
  assign st_offer = st_read;
`endif

  // Memory writes: the load port, and the fragment's write (never the same cycle: a load pixel
  // is taken only while no fragment is in flight).
  always_ff @(posedge clk_i) begin
    if (ld_take) begin
      color_mem[ld_ptr_q] <= ld_color_i;
      depth_mem[ld_ptr_q] <= ld_depth_i;
      cov_mem[ld_ptr_q]   <= ld_cov_i;
      peel_mem[ld_ptr_q]  <= ld_peel_i;
`ifdef ZB_REF_FULL
      acc_mem[ld_ptr_q]   <= ld_acc_i;
`endif
    end else if (fsm_q == FWrite) begin
      if (zwe_q) depth_mem[addr_q] <= z_q;
      if (cwe_q) color_mem[addr_q] <= masked;
`ifdef ZB_REF_FULL
      if (covwe_q) cov_mem[addr_q] <= cs_new_q;
      if (awe_q) acc_mem[addr_q] <= {rev_new_q, acc_out_q[4*A-1:0]};
`endif
    end
  end

`ifdef ZB_REF_FULL
  logic [ACC_W-1:0] st_acc_q;
`endif
`ifdef ZB_REF_DEFECT_STORE_PREFETCH
  // The defect: pixel 0 is prefetched into a register while idle_o is high, so the store's
  // first pixel needs no read; a store taken at the first edge of idle_o gets the prefetch of
  // the idle time before, stale if a fragment wrote pixel 0 since.
  logic [31:0]      pre_color_q;
  logic [D-1:0]     pre_depth_q, pre_peel_q;
  logic [COV_W-1:0] pre_cov_q;
`ifdef ZB_REF_FULL
  logic [ACC_W-1:0] pre_acc_q;
`endif
  always_ff @(posedge clk_i) begin
    if (idle_o) begin
      pre_color_q <= color_mem[0];
      pre_depth_q <= depth_mem[0];
      pre_cov_q   <= cov_mem[0];
      pre_peel_q  <= peel_mem[0];
`ifdef ZB_REF_FULL
      pre_acc_q   <= acc_mem[0];
`endif
    end
  end
`endif

  always_ff @(posedge clk_i) begin
`ifdef ZB_REF_DEFECT_STORE_PREFETCH
    if (st_read && !st_busy_q) begin
      st_color_q <= pre_color_q;
      st_depth_q <= pre_depth_q;
      st_cov_q   <= pre_cov_q;
      st_peel_q  <= pre_peel_q;
`ifdef ZB_REF_FULL
      st_acc_q   <= pre_acc_q;
`endif
    end else
`endif
    if (st_read) begin
      st_color_q <= color_mem[st_addr];
      st_depth_q <= depth_mem[st_addr];
      st_cov_q   <= cov_mem[st_addr];
      st_peel_q  <= peel_mem[st_addr];
`ifdef ZB_REF_FULL
      st_acc_q   <= acc_mem[st_addr];
`endif
    end
`ifdef ZB_REF_FULL
    else if (rs_done) st_color_q <= rs_color;  // the resolved colour, in place of the read one
`endif
  end

  // ---------------------------------------------------------------------------------------
  // Handshakes, all registered: ready for a load pixel or a fragment only with nothing in
  // flight, each dropped when its stall byte says so; idle_o rises late.
  // ---------------------------------------------------------------------------------------
  logic ld_ready_q, frag_ready_q, idle_q, quiet_d, hang;
`ifdef ZB_REF_INJECT_HANG
  localparam int HangAfter = 40;
  int taken_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) taken_q <= 0;
    else if (frag_take) taken_q <= taken_q + 1;
  end
  assign hang = taken_q >= HangAfter;  // the defect: no fragment is taken again
`else
  assign hang = 1'b0;
`endif
  assign quiet_d = fsm_d == FWait && !st_busy_d && ld_ptr_d == '0;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rng_q        <= seed;
      ld_ptr_q     <= '0;
      st_busy_q    <= 1'b0;
      st_next_q    <= '0;
      st_valid_q   <= 1'b0;
      ld_ready_q   <= 1'b0;
      frag_ready_q <= 1'b0;
      idle_q       <= 1'b0;
    end else begin
      rng_q      <= rng_d;
      ld_ptr_q   <= ld_ptr_d;
      st_busy_q  <= st_busy_d;
      st_valid_q <= st_offer;  // a pixel read (or resolved) at this edge is offered until the next
      if (st_read) st_next_q <= st_busy_q ? st_next_q + 1'b1 : CntW'(1);
      ld_ready_q   <= fsm_d == FWait && !st_busy_d && !stall_ld;
      frag_ready_q <= fsm_d == FWait && !st_busy_d && ld_ptr_d == '0 && !stall_frag && !hang;
      idle_q       <= quiet_d && (idle_q || idle_rise);
    end
  end

  assign ld_ready_o   = ld_ready_q;
  assign frag_ready_o = frag_ready_q;
  assign idle_o       = idle_q;
  assign st_valid_o   = st_valid_q;
  assign st_color_o   = st_color_q;
  assign st_depth_o   = st_depth_q;
  assign st_cov_o     = st_cov_q;
  assign st_peel_o    = st_peel_q;
`ifdef ZB_REF_FULL
  assign st_acc_o     = st_acc_q;
  assign layers_o     = 4'(LAYERS);
`else
  assign st_acc_o     = '0;
  assign layers_o     = 4'd0;
  // The subset has no accumulate, coverage or layers blend: these inputs are not read.
  logic unused_full;
  assign unused_full = ^{ld_acc_i, frag_cov_i, state_layers_i, st_resolve_i};
`endif

endmodule
