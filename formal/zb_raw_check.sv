// Formal (docs/formal.md, group raw): per-pixel read-after-write through zb_rop, bounded model
// check, with the shadow-word technique: for an arbitrary pixel P ($anyconst) the harness keeps
// the last depth, coverage and colour written to P (from the retire port's writes, in retire
// order). What a fragment to P reads (depth and coverage after X1's forwarding mux, colour
// after X7's forwarding and bypass mux) must equal that word once every older fragment has
// written, i.e. when the reader itself retires (X4 for depth and coverage, X11 for colour; P's
// fragments retire in issue order). The tile port is idle, so P's word before its first write
// is the RAM's (constant): the first read of P defines it.
module zb_raw_check #(
  parameter int unsigned DEPTH_BITS  = 8,
  parameter int unsigned TILE_W      = 2,
  parameter int unsigned TILE_H      = 2,
  parameter int unsigned CNT_W       = 2,
  parameter int unsigned COV_SAMPLES = 1,
  parameter int unsigned WINDOW      = 2,
  parameter int unsigned BEAT        = 2
) (
  input logic                            clk_i,
  input logic                            rst_ni,
  input logic                            state_we_i,
  input zb_pkg::pass_state_t             state_i,
  input logic [15:0]                     tile_x0_i,
  input logic [15:0]                     tile_y0_i,
  input logic                            frag_valid_i,
  input logic [15:0]                     frag_x_i,
  input logic [15:0]                     frag_y_i,
  input logic [DEPTH_BITS-1:0]           frag_z_i,
  input logic [31:0]                     frag_rgba_i,
  input logic [$clog2(COV_SAMPLES+1)-1:0] frag_cov_i,
  input logic                            stall_i,
  input logic                            tile_req_i,
  input logic                            tile_we_i,
  input logic                            tile_clear_i,
  input zb_pkg::planes_t                 tile_planes_i,
  input logic [$clog2(TILE_W*TILE_H/BEAT)-1:0] tile_addr_i,
  input logic [BEAT*32-1:0]              tile_wcolor_i,
  input logic [BEAT*DEPTH_BITS-1:0]      tile_wdepth_i,
  input logic [BEAT*$clog2(COV_SAMPLES+1)-1:0] tile_wcov_i,
  input logic [BEAT*DEPTH_BITS-1:0]      tile_wpeel_i,
  input logic                            cnt_clear_i
);
  localparam int unsigned AddrW = $clog2(TILE_W * TILE_H);
  localparam int unsigned XW    = $clog2(TILE_W);
  localparam int unsigned YW    = $clog2(TILE_H);
  localparam int unsigned CovW  = $clog2(COV_SAMPLES + 1);
  localparam int unsigned CntW  = 6;   // harness counters: more than the fragments in flight

  logic                  frag_ready, busy;
  logic                  mon_x4_valid, mon_dwe, mon_vwe, mon_x11_valid, mon_cwe;
  logic [AddrW-1:0]      mon_x4_addr, mon_x11_addr;
  logic [DEPTH_BITS-1:0] mon_wdepth;
  logic [CovW-1:0]       mon_wcov;
  logic [31:0]           mon_wcolor;

  zb_rop #(
    .DEPTH_BITS (DEPTH_BITS),
    .TILE_W     (TILE_W),
    .TILE_H     (TILE_H),
    .CNT_W      (CNT_W),
    .COV_SAMPLES(COV_SAMPLES),
    .WINDOW     (WINDOW),
    .BEAT       (BEAT)
  ) dut (
    .clk_i, .rst_ni, .state_we_i, .state_i, .tile_x0_i, .tile_y0_i, .frag_valid_i,
    .frag_ready_o(frag_ready),
    .frag_x_i, .frag_y_i, .frag_z_i, .frag_rgba_i, .frag_cov_i, .stall_i,
    .tile_req_i, .tile_we_i, .tile_clear_i, .tile_planes_i, .tile_addr_i, .tile_wcolor_i,
    .tile_wdepth_i, .tile_wcov_i, .tile_wpeel_i,
    .tile_rcolor_o(), .tile_rdepth_o(), .tile_rcov_o(), .tile_rpeel_o(),
    .busy_o(busy),
    .cnt_clear_i,
    .cnt_frag_in_o(), .cnt_frag_passed_o(), .cnt_frag_killed_o(), .cnt_depth_reads_o(),
    .cnt_depth_writes_o(), .cnt_color_reads_o(), .cnt_color_writes_o(),
    .cnt_stall_cycles_o(), .cnt_cycles_o(), .cnt_tile_loads_o(), .cnt_tile_stores_o(),
    .mon_x4_valid_o (mon_x4_valid),
    .mon_x4_addr_o  (mon_x4_addr),
    .mon_dwe_o      (mon_dwe),
    .mon_wdepth_o   (mon_wdepth),
    .mon_vwe_o      (mon_vwe),
    .mon_wcov_o     (mon_wcov),
    .mon_x11_valid_o(mon_x11_valid),
    .mon_x11_addr_o (mon_x11_addr),
    .mon_cwe_o      (mon_cwe),
    .mon_wcolor_o   (mon_wcolor)
  );

  // The read side, after flattening (docs/formal.md "Taps").
  // formal-tap: tap_x1_zs dut.u_depth.x1_zs
  // formal-tap: tap_x1_cs dut.u_depth.x1_cs
  // formal-tap: tap_x7_dst dut.u_color.x7_dst
  logic [DEPTH_BITS-1:0] tap_x1_zs;
  logic [CovW-1:0]       tap_x1_cs;
  logic [31:0]           tap_x7_dst;

  // ---------------------------------------------------------------------------------------
  // The driver's contract; the tile port stays idle (P's word comes from the RAM).
  // ---------------------------------------------------------------------------------------
  logic first_q = 1'b1;
  always_ff @(posedge clk_i) first_q <= 1'b0;

  logic        accept;
  logic [15:0] dx, dy;
  assign accept = frag_valid_i && frag_ready;
  assign dx     = frag_x_i - tile_x0_i;
  assign dy     = frag_y_i - tile_y0_i;

  always_comb begin
    ResetFirstCycle: assume (rst_ni == !first_q);
    StateWriteIdle: assume (!state_we_i || !busy);
    BlendCodeValid: assume (!state_we_i || state_i.blend <= zb_pkg::BlendUnder);
    TilePortUnused: assume (!tile_req_i && !tile_clear_i);
    FragInTile: assume (!accept || (dx < 16'(TILE_W) && dy < 16'(TILE_H)));
    FragCoverageInRange: assume (!accept || frag_cov_i <= CovW'(COV_SAMPLES));
  end

  (* anyconst *) logic [AddrW-1:0] pix;   // P

  // ---------------------------------------------------------------------------------------
  // What each fragment read, carried to its retire stage: depth and coverage X1 -> X4, colour
  // X7 -> X11 (the stages advance every cycle, so the word read in X1 three cycles ago is the
  // read of the fragment now in X4, and so on).
  // ---------------------------------------------------------------------------------------
  logic [DEPTH_BITS-1:0] rz2_q, rz3_q, rz4_q;
  logic [CovW-1:0]       rc2_q, rc3_q, rc4_q;
  logic [31:0]           rk8_q, rk9_q, rk10_q, rk11_q;

  always_ff @(posedge clk_i) begin
    rz2_q  <= tap_x1_zs;
    rz3_q  <= rz2_q;
    rz4_q  <= rz3_q;
    rc2_q  <= tap_x1_cs;
    rc3_q  <= rc2_q;
    rc4_q  <= rc3_q;
    rk8_q  <= tap_x7_dst;
    rk9_q  <= rk8_q;
    rk10_q <= rk9_q;
    rk11_q <= rk10_q;
  end

  // ---------------------------------------------------------------------------------------
  // The shadow words of P: the last value written, or (before any write) the first read.
  // ---------------------------------------------------------------------------------------
  logic                  x4_p, x11_p;
  logic                  sz_valid_q, sc_valid_q, sk_valid_q;
  logic [DEPTH_BITS-1:0] sz_q;
  logic [CovW-1:0]       sc_q;
  logic [31:0]           sk_q;
  assign x4_p  = mon_x4_valid && mon_x4_addr == pix;
  assign x11_p = mon_x11_valid && mon_x11_addr == pix;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      sz_valid_q <= 1'b0;
      sc_valid_q <= 1'b0;
      sk_valid_q <= 1'b0;
    end else begin
      if (x4_p) begin
        sz_valid_q <= 1'b1;
        sc_valid_q <= 1'b1;
      end
      if (x11_p) sk_valid_q <= 1'b1;
    end
  end
  always_ff @(posedge clk_i) begin
    // A retiring fragment that does not write leaves the word it read (which, once the
    // shadow is valid, the assertions below hold equal to it).
    if (x4_p)  sz_q <= mon_dwe ? mon_wdepth : rz4_q;
    if (x4_p)  sc_q <= mon_vwe ? mon_wcov : rc4_q;
    if (x11_p) sk_q <= mon_cwe ? mon_wcolor : rk11_q;
  end

  always_comb begin
    if (rst_ni) begin
      // A fragment reads the last word its pixel's older fragments wrote.
      DepthReadAfterWrite: assert (!(x4_p && sz_valid_q) || rz4_q == sz_q);
      CovReadAfterWrite: assert (!(x4_p && sc_valid_q) || rc4_q == sc_q);
      ColorReadAfterWrite: assert (!(x11_p && sk_valid_q) || rk11_q == sk_q);
    end
  end
endmodule
