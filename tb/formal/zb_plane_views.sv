// zb_plane in either view, for the proof that its two views are equal where zb_rop looks
// (scripts/equiv.py, docs/rtl.md "Two views"): rdata_o in every cycle, tile_rdata_o in the cycle
// after a tile read (tile_beat_o). Read once with the synthesis view (rtl/zb_plane.sv, the
// banks) and once with ZB_VIEW_SIM and the simulation view (rtl/sim/zb_plane.sv, one array);
// Yosys pairs the two by name. The inv_* outputs are the state both
// views must agree on, each built from that view's own registers (the t_* taps, undriven here:
// equiv.py connects each to the register it names after flattening): every memory word, the
// read register of rdata_o's bank, the beat a tile read left and the write-back's fresh flags.
// With them and the control registers (the same names in both) paired, equiv_induct closes.
module zb_plane_views #(
  parameter int WIDTH     = 4,
  parameter int WORDS     = 8,
  parameter int BEAT      = 2,
  parameter bit FORWARDED = 1'b0,
  parameter bit READ_ONLY = 1'b0,
  parameter int GEN_BITS  = 1,
  localparam int WordW    = WIDTH + (READ_ONLY ? 0 : GEN_BITS),
  localparam int GenLsb   = READ_ONLY ? 0 : WIDTH,
  localparam int BankW    = BEAT > 1 ? $clog2(BEAT) : 1
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          tile_req_i,
  input  logic                          tile_we_i,
  input  logic                          tile_en_i,
  input  logic                          tile_clear_i,
  input  logic [$clog2(WORDS/BEAT)-1:0] tile_addr_i,
  input  logic [BEAT*WIDTH-1:0]         tile_wdata_i,
  input  logic                          pipe_re_i,
  input  logic [$clog2(WORDS)-1:0]      pipe_raddr_i,
  input  logic                          pipe_we_i,
  input  logic [$clog2(WORDS)-1:0]      pipe_waddr_i,
  input  logic [WIDTH-1:0]              pipe_wdata_i,
  output logic [WIDTH-1:0]              rdata_o,
  output logic [BEAT*WIDTH-1:0]         tile_beat_o,     // tile_rdata_o after a tile read
  output logic [WORDS*WordW-1:0]        inv_mem,         // word p: bank p % BEAT, beat p / BEAT
  output logic [WordW-1:0]              inv_prd,         // the word of rdata_o's bank
  output logic [BEAT-1:0]               inv_beat_fresh,  // after a tile read: its fresh words
  output logic [BEAT-1:0]               inv_fresh2       // at W2: the words to write back
);
  logic [BEAT*WIDTH-1:0] trd;
  zb_plane #(
    .WIDTH(WIDTH), .WORDS(WORDS), .BEAT(BEAT), .FORWARDED(FORWARDED), .READ_ONLY(READ_ONLY),
    .GEN_BITS(GEN_BITS)
  ) u_plane (
    .clk_i, .rst_ni, .tile_req_i, .tile_we_i, .tile_en_i, .tile_clear_i, .tile_addr_i,
    .tile_wdata_i, .tile_rdata_o(trd), .pipe_re_i, .pipe_raddr_i, .pipe_we_i, .pipe_waddr_i,
    .pipe_wdata_i, .rdata_o
  );

  // Taps common to both views.
  logic             t_wback, t_wb2, t_plane_fresh;
  logic [GEN_BITS-1:0] t_epoch;
  logic [BankW-1:0] t_rbank;
  logic [BEAT-1:0]  t_fresh2;
  assign tile_beat_o = t_wback ? trd : '0;
  assign inv_fresh2  = t_wb2 && !READ_ONLY ? t_fresh2 : '0;
`ifdef ZB_VIEW_SIM
  logic [WordW-1:0] t_prd;
  logic [BEAT-1:0]  t_tile_fresh;
  assign inv_prd        = t_prd;
  assign inv_beat_fresh = t_wback ? t_tile_fresh : '0;
  logic unused;
  assign unused = ^{t_epoch, t_plane_fresh, t_rbank};
`else
  logic [BEAT*WordW-1:0] t_rdata;  // the banks' read registers
  logic [BEAT-1:0]       fresh;
  for (genvar b = 0; b < BEAT; b++) begin : g_fresh
    assign fresh[b] = READ_ONLY ? t_plane_fresh : t_rdata[b*WordW + GenLsb +: GEN_BITS] != t_epoch;
  end
  assign inv_prd        = t_rdata[(BEAT > 1 ? 32'(t_rbank) : 0)*WordW +: WordW];
  assign inv_beat_fresh = t_wback ? fresh : '0;
`endif

endmodule
