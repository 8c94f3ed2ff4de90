// zb_ref_rop: a second, deliberately plain ROP for the conformance kit (conformance/ref/README.md),
// written from docs/datapath.md alone. One fragment at a time through a small FSM (wait, read the
// pixel, depth test, blend one channel a cycle, write), a tile memory of plain arrays loaded and
// stored a pixel a clock, and every handshake it drives dropped at random (a xorshift generator
// seeded by STALL_SEED or +zb_ref_seed=N, rate STALL_RATE or +zb_ref_stall=N of 256), so that a
// testbench that assumes zb_rop's timing fails on it.
//
// Profile: depth test (all eight functions), depth write, colour mask, blend replace (0) and
// alpha (1). The coverage and peel planes are storage only: loaded and stored unchanged. A
// fragment of a pass outside the profile (blend 2 to 7, or the peel test) is killed: it writes
// nothing.
//
// Defects for the kit's own tests: ZB_REF_INJECT_BLEND_BUG drops the 0x80 rounding term of the
// unorm multiply in the alpha blend; ZB_REF_INJECT_HANG never raises frag_ready_o again once
// HangAfter fragments are taken.
module zb_ref_rop #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 16,
  parameter int TILE_H      = 16,
  parameter logic [31:0] STALL_SEED = 32'h2545_f491,  // +zb_ref_seed=N overrides it
  parameter int STALL_RATE = 64,                      // of 256; +zb_ref_stall=N overrides it
  parameter int COV_W = $clog2(COV_SAMPLES + 1)       // derived: the coverage count's width
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  // The pass state register (datapath.md "The pass state"), written while idle_o.
  input  logic                  state_we_i,
  input  logic [12:0]           state_i,
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
  // Fragments in frame coordinates, inside the tile.
  input  logic                  frag_valid_i,
  output logic                  frag_ready_o,
  input  logic [15:0]           frag_x_i,
  input  logic [15:0]           frag_y_i,
  input  logic [DEPTH_BITS-1:0] frag_z_i,
  input  logic [31:0]           frag_rgba_i,
  // No fragment in flight, no load or store under way; rises a random number of cycles late.
  output logic                  idle_o,
  // Tile store: a pulse while idle; pixel 0 is offered in the cycle right after the edge that
  // takes it, then one pixel each cycle st_valid_o is high, in raster order.
  input  logic                  st_start_i,
  output logic                  st_valid_o,
  output logic [31:0]           st_color_o,
  output logic [DEPTH_BITS-1:0] st_depth_o,
  output logic [COV_W-1:0]      st_cov_o,
  output logic [DEPTH_BITS-1:0] st_peel_o
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
`else
    s = t + (t >> 8) + 16'h0080;
`endif
    return 8'(s >> 8);
  endfunction

  // One channel of the alpha blend: min(255, m(s, a) + m(d, 255 - a)); the alpha channel is the
  // same with s = a.
  function automatic logic [7:0] blend_alpha(input logic [7:0] s, input logic [7:0] d,
                                             input logic [7:0] a);
    logic [8:0] sum;
    sum = 9'(unorm_mul(s, a)) + 9'(unorm_mul(d, 8'd255 - a));
    return sum > 9'd255 ? 8'd255 : 8'(sum);
  endfunction

  // datapath.md "1. Depth test": z (left) against the stored depth (right), unsigned.
  function automatic logic depth_pass(input logic [2:0] func, input logic [D-1:0] z,
                                      input logic [D-1:0] stored);
    case (func)
      3'd0:    return 1'b0;          // never
      3'd1:    return z <  stored;   // less
      3'd2:    return z == stored;   // equal
      3'd3:    return z <= stored;   // lequal
      3'd4:    return z >  stored;   // greater
      3'd5:    return z != stored;   // notequal
      3'd6:    return z >= stored;   // gequal
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

  // The pass state's fields.
  logic [12:0] state_q;
  logic        depth_test, depth_write, peel_test;
  logic [2:0]  depth_func, blend;
  logic [3:0]  color_mask;
  assign depth_test  = state_q[0];
  assign depth_func  = state_q[3:1];
  assign depth_write = state_q[4];
  assign blend       = state_q[7:5];
  assign color_mask  = state_q[11:8];
  assign peel_test   = state_q[12];

  // ---------------------------------------------------------------------------------------
  // The fragment FSM: one fragment from its acceptance to its write, nothing overlapped.
  // ---------------------------------------------------------------------------------------
  typedef enum logic [2:0] { FWait, FRead, FTest, FBlend, FWrite } fsm_e;
  fsm_e             fsm_q, fsm_d;
  logic [AddrW-1:0] addr_q, frag_addr;
  logic [D-1:0]     z_q, dst_z_q;
  logic [31:0]      src_q, dst_q;               // the fragment's colour, the stored one
  logic [31:0]      src_sh_q, dst_sh_q, out_q;  // the blend's operands and result, a byte a cycle
  logic [1:0]       chan_q;
  logic             zwe_q, frag_take, ld_take, pass, in_profile;

  assign frag_take  = frag_valid_i && frag_ready_o;
  assign ld_take    = ld_valid_i && ld_ready_o;
  // The tile pixel: (y - y0) * TILE_W + (x - x0).
  logic [15:0] frag_lx, frag_ly;
  assign frag_lx    = frag_x_i - tile_x0_i;
  assign frag_ly    = frag_y_i - tile_y0_i;
  assign frag_addr  = AddrW'(32'(frag_ly) * 32'(TILE_W) + 32'(frag_lx));
  assign in_profile = blend <= 3'd1 && !peel_test;
  assign pass       = in_profile && (!depth_test || depth_pass(depth_func, z_q, dst_z_q));

  always_comb begin
    fsm_d = fsm_q;
    case (fsm_q)
      FWait:   if (frag_take) fsm_d = FRead;
      FRead:   fsm_d = FTest;
      FTest:   if (!pass) fsm_d = FWait;  // killed: nothing written
               else if (blend == 3'd1) fsm_d = FBlend;
               else fsm_d = FWrite;
      FBlend:  if (chan_q == 2'd3) fsm_d = FWrite;
      FWrite:  fsm_d = FWait;
      default: fsm_d = FWait;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      fsm_q   <= FWait;
      state_q <= '0;
      chan_q  <= '0;
      zwe_q   <= 1'b0;
    end else begin
      fsm_q <= fsm_d;
      if (state_we_i) state_q <= state_i;
      if (fsm_q == FTest) begin
        zwe_q  <= depth_test && depth_write;  // datapath.md "2. Depth write"
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
      out_q    <= src_q;  // replace; the alpha blend overwrites it a byte a cycle
    end
    if (fsm_q == FBlend) begin
      // The channel in the operands' low bytes; its result enters out_q at the top, so after
      // four cycles R, G, B and A are in their lanes.
      out_q    <= {blend_alpha(src_sh_q[7:0], dst_sh_q[7:0], src_q[31:24]), out_q[31:8]};
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
  logic [AddrW-1:0] ld_ptr_q, ld_ptr_d;
  logic             st_busy_q, st_busy_d, st_valid_q, st_read;
  logic [CntW-1:0]  st_next_q;  // the next pixel to read out, Words when all are read
  logic [AddrW-1:0] st_addr;
  logic [31:0]      st_color_q;
  logic [D-1:0]     st_depth_q, st_peel_q;
  logic [COV_W-1:0] st_cov_q;

  assign ld_ptr_d  = !ld_take ? ld_ptr_q : ld_ptr_q == AddrW'(Words - 1) ? '0 : ld_ptr_q + 1'b1;
  // A store runs from the edge that takes st_start_i to the edge that takes its last pixel.
  assign st_busy_d = st_busy_q ? st_next_q != CntW'(Words) : st_start_i;
  // The first pixel is read at the edge that takes st_start_i, whatever the stall byte says.
  assign st_read   = st_busy_q ? st_next_q != CntW'(Words) && !stall_st : st_start_i;
  assign st_addr   = st_busy_q ? AddrW'(st_next_q) : '0;

  // Memory writes: the load port, and the fragment's write (never the same cycle: a load pixel
  // is taken only while no fragment is in flight).
  always_ff @(posedge clk_i) begin
    if (ld_take) begin
      color_mem[ld_ptr_q] <= ld_color_i;
      depth_mem[ld_ptr_q] <= ld_depth_i;
      cov_mem[ld_ptr_q]   <= ld_cov_i;
      peel_mem[ld_ptr_q]  <= ld_peel_i;
    end else if (fsm_q == FWrite) begin
      if (zwe_q) depth_mem[addr_q] <= z_q;
      if (color_mask != 4'd0) color_mem[addr_q] <= masked;
    end
  end

  always_ff @(posedge clk_i) begin
    if (st_read) begin
      st_color_q <= color_mem[st_addr];
      st_depth_q <= depth_mem[st_addr];
      st_cov_q   <= cov_mem[st_addr];
      st_peel_q  <= peel_mem[st_addr];
    end
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
      st_valid_q <= st_read;  // a pixel read at this edge is offered until the next
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

endmodule
