// zb_conf_scoreboard: the golden model as a lock-step scoreboard of zb_conf_tb, through DPI-C
// (zb_golden_pkg). The testbench names each fragment as it offers it; the golden model computes
// its writes at once (it is in order, and a pixel's fragments retire in order). Every retire the
// DUT reports is then held to the writes of the next fragment waiting at its pixel and stage;
// the first difference stops the run with the fragment, the cycle, the pixel and both values.
// A retire with no fragment waiting is extra; a fragment not retired when the tile drains is
// missing. The colour side's retire carries the accumulation word too (accumulate mode),
// compared when the DUT has the plane (accum_i).
module zb_conf_scoreboard
  import zb_golden_pkg::*;
#(
  parameter int TILE_W    = 64,
  parameter int TILE_H    = 64,
  parameter int ACC_BITS  = 16,
  parameter int REV_BITS  = 8,
  parameter int MAX_FRAGS = 1 << 18  // fragments of one pass in one tile
) (
  input logic        clk_i,
  input logic        accum_i,  // the DUT has the accumulation plane: its writes are compared
  input logic        ret_d_valid_i,
  input logic [31:0] ret_d_pixel_i,
  input logic        ret_dwe_i,
  input logic [31:0] ret_wdepth_i,
  input logic        ret_vwe_i,
  input logic [7:0]  ret_wcov_i,
  input logic        ret_c_valid_i,
  input logic [31:0] ret_c_pixel_i,
  input logic        ret_cwe_i,
  input logic [31:0] ret_wcolor_i,
  input logic        ret_awe_i,
  input logic [4*ACC_BITS+REV_BITS-1:0] ret_wacc_i
);

  localparam int Words = TILE_W * TILE_H;
  localparam int None  = 32'hffff_ffff;

  chandle      golden;
  int unsigned pass_no, tile_x0, tile_y0, n, checked;
  // Per offered fragment of the tile: its index in the pass, its pixel, the golden writes, and
  // the next fragment to its pixel.
  int unsigned frag_index [MAX_FRAGS];
  int unsigned frag_pixel [MAX_FRAGS];
  int unsigned exp_wrote  [MAX_FRAGS];
  int unsigned exp_depth  [MAX_FRAGS];
  int unsigned exp_cov    [MAX_FRAGS];
  int unsigned exp_rgba   [MAX_FRAGS];
  int unsigned exp_acc    [MAX_FRAGS][5];  // acc R, G, B, A, revealage
  int unsigned next_frag  [MAX_FRAGS];
  // Per tile pixel: the next fragment to retire at X4 (depth side) and at X11 (colour side).
  int unsigned head_d [Words];
  int unsigned head_c [Words];
  int unsigned tail   [Words];

  function automatic void check(input int status, input string call);
    if (status != ZB_OK)
      $fatal(1, "zb_conf: golden model: %s: %s", call, zb_golden_last_error(golden));
  endfunction

  function automatic void mismatch(input string stage, input int unsigned pixel,
                                   input int unsigned k, input string rtl, input string gold);
    $display("zb_conf: MISMATCH at cycle %0d: pass %0d fragment %0s, pixel (%0d, %0d), %s:",
             $time / 10, pass_no, k == None ? "none" : $sformatf("%0d", frag_index[k]),
             tile_x0 + pixel % TILE_W, tile_y0 + pixel / TILE_W, stage);
    $display("zb_conf:   rtl    %s", rtl);
    $display("zb_conf:   golden %s", gold);
    $fatal(1, "zb_conf: the first wrong write");
  endfunction

  string arith;

  function automatic void begin_frame(input int unsigned width, input int unsigned height,
                                      input int unsigned depth_bits, input int unsigned samples,
                                      input int unsigned clear_rgba, input int weight_bits);
    check(zb_golden_create(golden, width, height, depth_bits, samples, clear_rgba), "create");
    check(zb_golden_set_wboit(golden, ACC_BITS, REV_BITS, weight_bits), "set_wboit");
    // The DUT's declared arithmetic (conformance.py from the profile): +zb_arith=NAME.
    if ($value$plusargs("zb_arith=%s", arith))
      check(zb_golden_set_arithmetic(golden, arith), "set_arithmetic");
    pass_no = 0;
    checked = 0;
  endfunction

  // `index`: the pass's place in the stream (on resident tiles a pass is begun once a tile).
  function automatic void begin_pass(input logic [15:0] state, input int unsigned index);
    pass_no = index;
    check(zb_golden_begin_pass(golden, 32'(state)), "begin_pass");
  endfunction

  function automatic void end_pass();
    longint unsigned in_, passed, dr, dw, cr, cw;
    check(zb_golden_end_pass(golden, in_, passed, dr, dw, cr, cw), "end_pass");
    $display("zb_conf: pass %0d: golden counters: %0d in, %0d passed, depth %0d reads %0d writes, colour %0d reads %0d writes",
             pass_no, in_, passed, dr, dw, cr, cw);
  endfunction

  function automatic void frame_op(input logic [3:0] kind, input logic [31:0] value,
                                   input logic [31:0] depth);
    check(zb_golden_frame_op(golden, int'(kind), value, depth), "frame_op");
  endfunction

  function automatic void begin_tile(input int unsigned x0, input int unsigned y0);
    tile_x0 = x0;
    tile_y0 = y0;
    n = 0;
    for (int unsigned p = 0; p < Words; p++) begin
      head_d[p] = None;
      head_c[p] = None;
      tail[p]   = None;
    end
  endfunction

  // The fragment the testbench offers next (index in the pass): its golden writes.
  function automatic void accept(input int unsigned index, input logic [15:0] x,
                                 input logic [15:0] y, input logic [31:0] z,
                                 input logic [31:0] rgba, input logic [7:0] cov);
    int unsigned p, wrote, wz, wc, wrgba;
    if (n == MAX_FRAGS) $fatal(1, "zb_conf: more than %0d fragments in a tile (MAX_FRAGS)", MAX_FRAGS);
    check(zb_golden_push(golden, int'(x), int'(y), z, rgba, int'(cov), wrote, wz, wc, wrgba),
          $sformatf("push of fragment %0d", index));
    p = (32'(y) - tile_y0) * TILE_W + (32'(x) - tile_x0);
    frag_index[n] = index;
    frag_pixel[n] = p;
    exp_wrote[n]  = wrote;
    exp_depth[n]  = wz;
    exp_cov[n]    = wc;
    exp_rgba[n]   = wrgba;
    // The word this fragment wrote is the pixel's now: the golden model is in order.
    for (int k = 0; k < 5; k++) begin
      exp_acc[n][k] = 0;
      if ((wrote & ZB_WROTE_ACCUM) != 0)
        check(zb_golden_read(golden, ZB_PLANE_ACC_R + k, int'(x), int'(y), exp_acc[n][k]),
              "read of the accumulation word");
    end
    next_frag[n]  = None;
    // Each side's head is None once it has retired every fragment offered so far: the new one
    // is then its head at once, and otherwise reached through the list.
    if (tail[p] != None) next_frag[tail[p]] = n;
    if (head_d[p] == None) head_d[p] = n;
    if (head_c[p] == None) head_c[p] = n;
    tail[p] = n;
    n++;
  endfunction

  function automatic string depth_side(input bit dwe, input int unsigned z, input bit vwe,
                                       input int unsigned c);
    return $sformatf("depth write %0d (0x%08x), coverage write %0d (%0d)", dwe, dwe ? z : 0,
                     vwe, vwe ? c : 0);
  endfunction

  function automatic string color_side(input bit cwe, input int unsigned rgba);
    return $sformatf("colour write %0d (rgba 0x%08x)", cwe, cwe ? rgba : 0);
  endfunction

  // The retire's accumulation word in the golden model's parts.
  function automatic int unsigned ret_acc(input int k);
    return k < 4 ? 32'(ret_wacc_i[k*ACC_BITS +: ACC_BITS]) : 32'(ret_wacc_i[4*ACC_BITS +: REV_BITS]);
  endfunction

  function automatic string accum_side(input bit awe, input int unsigned r, input int unsigned g,
                                       input int unsigned b, input int unsigned a,
                                       input int unsigned rev);
    return awe ? $sformatf("accumulation write 1 (acc 0x%0x 0x%0x 0x%0x 0x%0x, revealage 0x%0x)",
                           r, g, b, a, rev)
               : "accumulation write 0";
  endfunction

  // A depth-side retire (X4): its depth and coverage writes against the golden model's.
  function automatic void retire_d();
    int unsigned p, k;
    bit ew, ev;
    p = ret_d_pixel_i % Words;
    k = ret_d_valid_i ? head_d[p] : None;
    if (k == None)
      mismatch("X4", p, k, depth_side(ret_dwe_i, ret_wdepth_i, ret_vwe_i, 32'(ret_wcov_i)),
               "no fragment waiting at this pixel (an extra retire)");
    ew = (exp_wrote[k] & ZB_WROTE_DEPTH) != 0;
    ev = (exp_wrote[k] & ZB_WROTE_COVERAGE) != 0;
    if (ret_dwe_i != ew || ret_vwe_i != ev || (ew && ret_wdepth_i != exp_depth[k]) ||
        (ev && 32'(ret_wcov_i) != exp_cov[k]))
      mismatch("X4", p, k, depth_side(ret_dwe_i, ret_wdepth_i, ret_vwe_i, 32'(ret_wcov_i)),
               depth_side(ew, exp_depth[k], ev, exp_cov[k]));
    head_d[p] = next_frag[k];
    checked++;
  endfunction

  // A colour-side retire (X11): its colour write against the golden model's.
  function automatic void retire_c();
    int unsigned p, k;
    bit ew, ea, same;
    p = ret_c_pixel_i % Words;
    k = ret_c_valid_i ? head_c[p] : None;
    if (k == None)
      mismatch("X11", p, k, color_side(ret_cwe_i, ret_wcolor_i),
               "no fragment waiting at this pixel (an extra retire)");
    ew = (exp_wrote[k] & ZB_WROTE_COLOR) != 0;
    if (ret_cwe_i != ew || (ew && ret_wcolor_i != exp_rgba[k]))
      mismatch("X11", p, k, color_side(ret_cwe_i, ret_wcolor_i), color_side(ew, exp_rgba[k]));
    ea = (exp_wrote[k] & ZB_WROTE_ACCUM) != 0;
    same = 1'b1;
    for (int f = 0; f < 5; f++) same &= !ea || ret_acc(f) == exp_acc[k][f];
    if (accum_i && (ret_awe_i != ea || !same))
      mismatch("X11", p, k, accum_side(ret_awe_i, ret_acc(0), ret_acc(1), ret_acc(2), ret_acc(3), ret_acc(4)),
               accum_side(ea, exp_acc[k][0], exp_acc[k][1], exp_acc[k][2], exp_acc[k][3], exp_acc[k][4]));
    head_c[p] = next_frag[k];
    checked++;
  endfunction

  // The planes take the retire port's writes at this edge: read it before the edge's updates.
  always @(posedge clk_i) begin
    if (golden != null && (ret_d_valid_i || ret_dwe_i || ret_vwe_i)) retire_d();
    if (golden != null && (ret_c_valid_i || ret_cwe_i || (accum_i && ret_awe_i))) retire_c();
  end

  // The tile has drained: every fragment offered has retired on both sides.
  function automatic void end_tile();
    for (int unsigned k = 0; k < n; k++) begin
      if (head_d[frag_pixel[k]] == k)
        mismatch("X4", frag_pixel[k], k, "no retire", "the fragment's writes (a missing retire)");
      if (head_c[frag_pixel[k]] == k)
        mismatch("X11", frag_pixel[k], k, "no retire", "the fragment's writes (a missing retire)");
    end
  endfunction

  final begin
    if (golden != null) begin
      $display("zb_conf: lock-step: %0d retires compared with the golden model", checked);
      zb_golden_destroy(golden);
    end
  end

endmodule
