// Formal (docs/formal.md, group layers): zb_layers_insert keeps a pixel's layers in order. For
// every pixel word it may read (its layers sorted by key, the occupied slots first, at most K
// of them) and every fragment, the word it writes three cycles later is again sorted, occupied
// first and at most K (docs/datapath.md "8. Layers": a merged layer's key never falls below its
// front's). K is any of 1..LAYERS, a new one each cycle; the fragment any layer, alpha 0 too.
// k-induction: the unit holds no state but its stages. The defect run (scripts/formal.sh
// --defect) forces a merge into every write: the proof must fail.
module zb_layers_check #(
  parameter int unsigned DEPTH_BITS = 8,
  parameter int unsigned LAYERS     = 2,
  localparam int unsigned LW        = DEPTH_BITS + 32,
  localparam int unsigned WW        = LAYERS * LW
) (
  input logic          clk_i,
  input logic          rst_ni,
  input logic [3:0]    kk_i,
  input logic [WW-1:0] word_i,
  input logic [LW-1:0] f_i
);
  logic [WW-1:0] word_o;

  zb_layers_insert #(
    .DEPTH_BITS(DEPTH_BITS),
    .LAYERS    (LAYERS)
  ) dut (
    .clk_i     (clk_i),
    .rst_ni    (rst_ni),
    .kk_i      (kk_i),
    .x7_word_i (word_i),
    .x8_f_i    (f_i),
    .we_i      (1'b1),
    .x11_word_o(word_o)
  );

  // A word well formed for K: sorted among its occupied slots (A != 0), those first, at most K.
  function automatic logic well_formed(logic [WW-1:0] w, logic [3:0] k);
    well_formed = 1'b1;
    for (int unsigned j = 0; j < LAYERS; j++) begin
      if (w[j*LW + 24 +: 8] != 8'h00) begin
        if (4'(j) >= k) well_formed = 1'b0;
        if (j > 0 && (w[(j-1)*LW + 24 +: 8] == 8'h00 || w[j*LW +: LW] < w[(j-1)*LW +: LW]))
          well_formed = 1'b0;
      end
    end
  endfunction

  // The word is read at X7 and registered in X8 (the tap), where the fragment and K join it.
  // formal-tap: tap_x8_word dut.x8_word_q
  logic [WW-1:0] tap_x8_word;
  logic [3:0]    k_q [1:3];  // K of the fragments in X9..X11
  logic [2:0]    valid_q = 3'b000;  // X9..X11 hold a fragment that entered after reset
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      valid_q <= '0;
    end else begin
      valid_q <= {valid_q[1:0], 1'b1};
    end
    k_q[1] <= kk_i;
    k_q[2] <= k_q[1];
    k_q[3] <= k_q[2];
  end

  always_comb begin
    if (rst_ni) begin
      KInRange: assume (kk_i >= 4'd1 && 32'(kk_i) <= LAYERS);
      // The word in X8 is the one read for this fragment's K (constant over a pass): well formed.
      WordFormed: assume (well_formed(tap_x8_word, kk_i));
      if (valid_q[2]) begin
        LayersSortedAtMostK: assert (well_formed(word_o, k_q[3]));
      end
    end
  end

endmodule
