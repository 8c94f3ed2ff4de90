// tb_golden_dpi: zb_golden_pkg through Verilator's DPI-C. A model is created, fragments are
// pushed, and every write it reports is held to a value computed by hand from docs/datapath.md
// (the arithmetic is in the comments). Ends with $finish when every check holds, $stop (exit 1
// from dpi_main.cpp) when one fails. +zb_expect_wrong changes one expected value, to show the
// test fails on a wrong value.
module tb_golden_dpi;
  import zb_golden_pkg::*;

  int errors = 0;

  function automatic void expect_value(input string what, input int unsigned golden,
                                       input int unsigned want);
    if (golden != want) begin
      $display("FAIL %s: golden=%08h expected=%08h", what, golden, want);
      errors++;
    end
  endfunction

  function automatic void expect_count(input string what, input longint unsigned golden,
                                       input longint unsigned want);
    if (golden != want) begin
      $display("FAIL %s: golden=%0d expected=%0d", what, golden, want);
      errors++;
    end
  endfunction

  function automatic void expect_ok(input chandle h, input string what, input int status);
    if (status != ZB_OK) begin
      $display("FAIL %s: status %0d: %s", what, status, zb_golden_last_error(h));
      errors++;
    end
  endfunction

  initial begin : run
    chandle h;
    int status;
    int unsigned wrote, depth, cov, rgba, value;
    longint unsigned in, passed, depth_reads, depth_writes, color_reads, color_writes;
    bit [7:0] want_red;

    // The pass state register: [0] depth_test, [3:1] func, [4] write, [7:5] blend, [11:8] mask.
    // less = 1, alpha = 1: 1 | 1 << 1 | 1 << 4 | 1 << 5 | 15 << 8 = 0xf33; coverage = 3: 0xf73.
    expect_value("zb_pass_state alpha", zb_pass_state(1'b1, 3'd1, 1'b1, 3'd1, 4'hf, 1'b0), 32'hf33);
    expect_value("zb_pass_state coverage", zb_pass_state(1'b1, 3'd1, 1'b1, 3'd3, 4'hf, 1'b0), 32'hf73);
    expect_value("zb_rgba", zb_rgba(8'd16, 8'd32, 8'd64, 8'd128), 32'h80402010);

    // Errors come back as a status and a line: a bad width, then a push outside a pass.
    status = zb_golden_create(h, 0, 2, 24, 16, 32'h0);
    if (status != ZB_EARG || h != null || zb_golden_last_error(null) == "") begin
      $display("FAIL create 0x2: status %0d, error '%s'", status, zb_golden_last_error(null));
      errors++;
    end

    // A 4x2 frame, 24-bit depth, 16 samples, cleared to (16, 32, 64, 128).
    expect_ok(null, "create", zb_golden_create(h, 4, 2, 24, 16, 32'h80402010));
    status = zb_golden_push(h, 0, 0, 0, 0, 0, wrote, depth, cov, rgba);
    if (status != ZB_EORDER || zb_golden_last_error(h) == "") begin
      $display("FAIL push outside a pass: status %0d, error '%s'", status, zb_golden_last_error(h));
      errors++;
    end

    // Alpha blend of (200, 100, 50, 128) over (16, 32, 64, 128), m(x, y) = (t + (t >> 8) + 0x80)
    // >> 8 with t = x * y, c' = m(s, 128) + m(d, 127):
    //   r: m(200, 128) = (25600 + 100 + 128) >> 8 = 100; m(16, 127) = (2032 + 7 + 128) >> 8 = 8; 108
    //   g: m(100, 128) = (12800 + 50 + 128) >> 8 = 50; m(32, 127) = (4064 + 15 + 128) >> 8 = 16; 66
    //   b: m(50, 128) = (6400 + 25 + 128) >> 8 = 25; m(64, 127) = (8128 + 31 + 128) >> 8 = 32; 57
    //   a: m(128, 128) = (16384 + 64 + 128) >> 8 = 64; m(128, 127) = (16256 + 63 + 128) >> 8 = 64; 128
    want_red = $test$plusargs("zb_expect_wrong") ? 8'd109 : 8'd108;
    expect_ok(h, "begin alpha", zb_golden_begin_pass(h, 32'hf33));
    expect_ok(h, "push alpha", zb_golden_push(h, 1, 0, 32'h100, zb_rgba(8'd200, 8'd100, 8'd50, 8'd128),
                                              16, wrote, depth, cov, rgba));
    expect_value("alpha: wrote", wrote, ZB_WROTE_DEPTH | ZB_WROTE_COLOR);
    expect_value("alpha: depth", depth, 32'h100);
    expect_value("alpha: colour", rgba, {8'd128, 8'd57, 8'd66, want_red});
    // Behind it (0x200 is not less than 0x100): killed, nothing written.
    expect_ok(h, "push behind", zb_golden_push(h, 1, 0, 32'h200, 32'hffffffff, 16, wrote, depth,
                                               cov, rgba));
    expect_value("behind: wrote", wrote, 0);
    expect_ok(h, "end alpha", zb_golden_end_pass(h, in, passed, depth_reads, depth_writes,
                                                 color_reads, color_writes));
    // Counters (docs/datapath.md "Counters"): both read depth, one passed and wrote depth and
    // colour, reading the destination (the blend is not replace).
    expect_count("alpha: fragments in", in, 2);
    expect_count("alpha: fragments passed", passed, 1);
    expect_count("alpha: depth reads", depth_reads, 2);
    expect_count("alpha: depth writes", depth_writes, 1);
    expect_count("alpha: colour reads", color_reads, 1);
    expect_count("alpha: colour writes", color_writes, 1);

    // Coverage blend, N = 16, of red (255, 0, 0, 255) covering k = 4 samples of the cleared pixel
    // (cs = 0, far depth): nearer, w = k: c' = (4 * Cf + 12 * Cs + 8) >> 4:
    //   r: (1020 + 192 + 8) >> 4 = 76; g: (0 + 384 + 8) >> 4 = 24; b: (0 + 768 + 8) >> 4 = 48;
    //   a: (1020 + 1536 + 8) >> 4 = 160. Depth 0x300, coverage min(16, 4 + 0) = 4.
    expect_ok(h, "begin coverage", zb_golden_begin_pass(h, 32'hf73));
    expect_ok(h, "push nearer", zb_golden_push(h, 2, 1, 32'h300, 32'hff0000ff, 4, wrote, depth,
                                               cov, rgba));
    expect_value("nearer: wrote", wrote, ZB_WROTE_DEPTH | ZB_WROTE_COVERAGE | ZB_WROTE_COLOR);
    expect_value("nearer: depth", depth, 32'h300);
    expect_value("nearer: coverage", cov, 4);
    expect_value("nearer: colour", rgba, {8'd160, 8'd48, 8'd24, 8'd76});
    // Blue at the same depth covering the other 12 samples: equal and full (4 + 12 >= 16), so
    // the polygon's colour, coverage 16, depth unchanged (not written).
    expect_ok(h, "push equal", zb_golden_push(h, 2, 1, 32'h300, 32'hffff0000, 12, wrote, depth,
                                              cov, rgba));
    expect_value("equal full: wrote", wrote, ZB_WROTE_COVERAGE | ZB_WROTE_COLOR);
    expect_value("equal full: coverage", cov, 16);
    expect_value("equal full: colour", rgba, 32'hffff0000);
    expect_ok(h, "end coverage", zb_golden_end_pass(h, in, passed, depth_reads, depth_writes,
                                                    color_reads, color_writes));
    // Every coverage fragment passes and reads and writes colour; only the nearer wrote depth.
    expect_count("coverage: fragments in", in, 2);
    expect_count("coverage: fragments passed", passed, 2);
    expect_count("coverage: depth reads", depth_reads, 2);
    expect_count("coverage: depth writes", depth_writes, 1);
    expect_count("coverage: colour reads", color_reads, 2);
    expect_count("coverage: colour writes", color_writes, 2);

    // The planes hold the writes; an untouched pixel holds the clear.
    expect_ok(h, "read", zb_golden_read(h, ZB_PLANE_DEPTH, 1, 0, value));
    expect_value("depth (1, 0)", value, 32'h100);
    expect_ok(h, "read", zb_golden_read(h, ZB_PLANE_COVERAGE, 2, 1, value));
    expect_value("coverage (2, 1)", value, 16);
    expect_ok(h, "read", zb_golden_read(h, ZB_PLANE_COLOR, 3, 1, value));
    expect_value("colour (3, 1)", value, 32'h80402010);
    // Frame operations: a depth clear to 0xffffffff is clamped to the far depth 0xffffff.
    expect_ok(h, "clear depth", zb_golden_frame_op(h, ZB_OP_CLEAR_DEPTH, 0, 32'hffffffff));
    expect_ok(h, "read", zb_golden_read(h, ZB_PLANE_DEPTH, 2, 1, value));
    expect_value("depth after clear", value, 32'hffffff);
    zb_golden_destroy(h);

    if (errors != 0) begin
      $display("tb_golden_dpi: %0d checks failed", errors);
      $stop;
    end else begin
      $display("tb_golden_dpi: every check holds");
      $finish;
    end
  end

endmodule
