// zb_coverage_composite: the four depth cases of US 5,123,085 claim 1, the decisions of
// docs/datapath.md "Coverage blend". Combinational; used in zb_rop's X3, where the stored
// depth and coverage are known. With k = cov_i (the polygon pixel's covered samples),
// cs = stored_cov_i and N = COV_SAMPLES:
//   combined = min(N, k + cs)
//   nearer  (z <  Zs):                weight k,      depth z,  coverage combined
//   farther (z >  Zs):                weight N - cs, depth Zs, coverage combined
//   equal, k + cs >= N (full):        weight N,      depth Zs, coverage N
//   equal, k + cs <  N (not full):    weight k,      depth z,  coverage combined
// The colour unit (zb_blend, mode 3) then forms (w * Cf + (N - w) * Cs + N/2) >> log2(N): the
// first proportionate blend for w = k, the second for w = N - cs (the background keeps its cs
// samples), the polygon colour for w = N. Requires k <= N and cs <= N (zb_rop asserts both).
// The depth comparison comes in as its two flags, registered a stage earlier by zb_rop.
module zb_coverage_composite #(
  parameter int COV_SAMPLES = 16,  // N: 1, 2, 4, 8 or 16
  localparam int CovW       = $clog2(COV_SAMPLES + 1)
) (
  input  logic                  lt_i,          // polygon depth z < background depth Zs
  input  logic                  eq_i,          // z == Zs
  input  logic [CovW-1:0]       cov_i,         // k
  input  logic [CovW-1:0]       stored_cov_i,  // cs
  output logic                  nearer_o,      // z < Zs: the only case that changes the depth
  output logic [CovW-1:0]       weight_o,      // w: samples of the polygon colour
  output logic [CovW-1:0]       cov_o          // coverage of the composited pixel
);

  localparam logic [CovW-1:0] Full = CovW'(COV_SAMPLES);

  logic [CovW:0] sum;
  logic          lt, eq, full;

  assign sum  = {1'b0, cov_i} + {1'b0, stored_cov_i};
  assign full = sum >= {1'b0, Full};
  assign lt   = lt_i;
  assign eq   = eq_i;

  assign nearer_o = lt;
  assign cov_o    = full ? Full : sum[CovW-1:0];

  always_comb begin
    weight_o = cov_i;
    unique case ({lt, eq})
      2'b10:   weight_o = cov_i;                 // nearer: first blend, by k
      2'b00:   weight_o = Full - stored_cov_i;   // farther: second blend, background keeps cs
      2'b01:   weight_o = full ? Full : cov_i;   // equal: polygon colour when full, else first
      default: weight_o = cov_i;                 // lt and eq together cannot happen
    endcase
  end

endmodule
