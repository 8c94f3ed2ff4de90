// zb_wave_probe: the testbench's side of a waveform, beside zb_rop's signals in the same FST
// (scope tb). No logic: the driver sets these inputs each cycle and they are traced.
//   frag_index, frag_prim: the fragment offered on zb_rop's input this cycle (its index in the
//     pass; all ones with frag_valid_i low); frag_valid_i && frag_ready_o is its accept
//   x4_/x11_: the fragment whose writes land at this cycle's rising edge, as the lock-step
//     monitor names it, and the golden model's writes for it (depth with dwe, coverage with
//     vwe, colour with cwe, the accumulation word with awe: acc R, G, B, A at [32c +: 32], the
//     layers word with lwe: as zb_rop's mon_wlayers_o, slot j at [j (D + 32) +: D + 32])
//   mismatch: this cycle's rising edge holds the first wrong write
/* verilator lint_off UNUSEDSIGNAL */
module zb_wave_probe (
  input logic [31:0] pass_no,
  input logic [31:0] frag_index,
  input logic [31:0] frag_prim,
  input logic        x4_retire,
  input logic [31:0] x4_index,
  input logic        x4_golden_dwe,
  input logic [31:0] x4_golden_depth,
  input logic        x4_golden_vwe,
  input logic [31:0] x4_golden_cov,
  input logic        x11_retire,
  input logic [31:0] x11_index,
  input logic        x11_golden_cwe,
  input logic [31:0] x11_golden_color,
  input logic        x11_golden_awe,
  input logic [127:0] x11_golden_acc,
  input logic [31:0] x11_golden_reveal,
  input logic        x11_golden_lwe,
  input logic [511:0] x11_golden_layers,  // 8 slots of at most 64 bits: every LAYERS and width
  input logic        mismatch
);
endmodule
/* verilator lint_on UNUSEDSIGNAL */
