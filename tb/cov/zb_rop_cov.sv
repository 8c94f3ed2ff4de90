// zb_rop_cov: the functional coverage plan's bins (tb/cov/coverage_plan.json), as cover
// properties bound to zb_rop (zb_rop_cov_bind.sv) in the coverage build only. Verilator 5.006
// has no covergroups: each bin is a cover property, a cross is a nest of generate loops, and
// the loops' indices are the plan's dimensions, in order. Label = the plan entry's "cover".
// Inputs are zb_rop's ports and internal signals, read only.
module zb_rop_cov #(
  parameter int WINDOW      = 8,
  parameter int TILE_W      = 64,
  parameter int TILE_H      = 64,
  parameter int BEAT        = 8,
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  localparam int AddrW      = $clog2(TILE_W * TILE_H),
  localparam int BeatAW     = $clog2(TILE_W * TILE_H / BEAT),
  localparam int CovW       = $clog2(COV_SAMPLES + 1),
  localparam int HitW       = 3     // the window's hit bits a slot (zb_rop's Span - 1)
) (
  input logic                        clk_i,
  input logic                        rst_ni,
  input zb_pkg::pass_state_t         state_q,
  input logic                        state_we_i,
  input logic                        cnt_clear_i,
  input logic                        x4_valid,
  input logic                        frag_valid_i,
  input logic                        frag_ready_o,
  input logic                        stall_i,
  input logic [15:0]                 tile_x0_i,
  input logic [15:0]                 tile_y0_i,
  // I's fragment as the window takes it (i_valid && w_ready): the accept order.
  input logic                        i_valid,
  input logic                        w_ready,
  input logic [AddrW-1:0]            i_addr,
  input logic [DEPTH_BITS-1:0]       i_z,
  input logic [7:0]                  i_alpha,
  input logic [CovW-1:0]             i_cov,
  input logic                        tile_req_i,
  input logic                        tile_we_i,
  input logic                        tile_clear_i,
  input logic                        tile_copy_i,
  input logic                        tile_resolve_i,
  input logic                        tile_wboit_i,
  input zb_pkg::planes_t             tile_planes_i,
  input logic [BeatAW-1:0]           tile_addr_i,
  input logic [WINDOW-1:0]           win_valid,
  input logic [WINDOW-1:0]           win_pick,
  input logic [WINDOW-1:0]           win_ins,
  input logic [WINDOW*HitW-1:0]      win_hit,
  input logic [WINDOW*WINDOW-1:0]    win_same,
  input logic [WINDOW*WINDOW-1:0]    win_older,
  input logic                        x9_acc,        // X9 holds a passing accumulate fragment
  input logic [3:0]                  acc_sat,       // X9's channel sums, carry out
  input logic                        x3_valid,      // X3: the depth decision's inputs
  input logic                        x3_lt,
  input logic                        x3_eq,
  input logic                        x3_behind,
  input logic [CovW-1:0]             x3_cov,
  input logic [CovW-1:0]             x3_cs,
  input logic                        cwe,           // X11's colour write
  input logic [31:0]                 wcolor,
  input logic [8:0]                  cnt_sat,       // zb_rop's event counters at all ones
  input logic [1:0]                  tile_cnt_sat   // the tile-beat counters at all ones
);

  localparam int Dist = WINDOW + 1;  // same-pixel distances 1..WINDOW+1 (the last: past it)

  // ---------------------------------------------------------------------------------------
  // Pass state: depth (off, or the function) x depth write x blend x colour mask x peel test,
  // sampled with each fragment's depth decision (X4).
  // ---------------------------------------------------------------------------------------
  // The state as one index, the generate loops' order; each bin an immediate cover under one
  // sample condition, which Verilator tests once a cycle for all 3456 (a concurrent cover
  // each would evaluate every bin every cycle: 7 times the simulation's time).
  logic [3:0]  depth_bin;
  logic [11:0] state_idx;
  assign depth_bin = state_q.depth_test ? 4'(state_q.depth_func) + 4'd1 : 4'd0;
  assign state_idx = 12'(depth_bin) * 12'd384 + 12'(state_q.depth_write) * 12'd192 +
                     12'(state_q.blend) * 12'd32 + 12'(state_q.color_mask) * 12'd2 +
                     12'(state_q.peel_test);
  for (genvar d = 0; d < 9; d++) begin : g_depth
    for (genvar w = 0; w < 2; w++) begin : g_dw
      for (genvar b = 0; b < 6; b++) begin : g_blend
        for (genvar m = 0; m < 16; m++) begin : g_mask
          for (genvar p = 0; p < 2; p++) begin : g_peel
            always_ff @(posedge clk_i) begin
              // (layers mode, blend 6, has its own bins: zb_layers' covers)
              if (rst_ni && x4_valid && state_q.blend != zb_pkg::BlendLayers) begin
                PassState: cover (state_idx == 12'(d * 384 + w * 192 + b * 32 + m * 2 + p));
              end
            end
          end
        end
      end
    end
  end

  // ---------------------------------------------------------------------------------------
  // Outcomes: each depth function meeting each relation of fragment to stored depth (less,
  // equal, greater), the peel compare both ways, the coverage blend's relation x whether the
  // two coverage counts overflow N, and each colour blend writing a channel at 0 and at 255.
  // ---------------------------------------------------------------------------------------
  logic [1:0] rel;
  logic       cov_mode;
  assign rel      = x3_lt ? 2'd0 : (x3_eq ? 2'd1 : 2'd2);
  assign cov_mode = state_q.blend == zb_pkg::BlendCoverage;
  for (genvar f = 0; f < 8; f++) begin : g_func
    for (genvar r = 0; r < 3; r++) begin : g_rel
      DepthCompare: cover property (@(posedge clk_i) disable iff (!rst_ni)
          x3_valid && state_q.depth_test && !cov_mode && state_q.depth_func == 3'(f) &&
          rel == 2'(r));
    end
  end
  PeelBehind: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x3_valid && state_q.peel_test && !cov_mode && x3_behind);
  PeelNotBehind: cover property (@(posedge clk_i) disable iff (!rst_ni)
      x3_valid && state_q.peel_test && !cov_mode && !x3_behind);
  for (genvar r = 0; r < 3; r++) begin : g_cov_rel
    CoverageFits: cover property (@(posedge clk_i) disable iff (!rst_ni)
        x3_valid && cov_mode && rel == 2'(r) &&
        {1'b0, x3_cov} + {1'b0, x3_cs} <= (CovW + 1)'(COV_SAMPLES));
    CoverageOverflows: cover property (@(posedge clk_i) disable iff (!rst_ni)
        x3_valid && cov_mode && rel == 2'(r) &&
        {1'b0, x3_cov} + {1'b0, x3_cs} > (CovW + 1)'(COV_SAMPLES));
  end
  logic written_zero, written_full;
  always_comb begin
    written_zero = 1'b0;
    written_full = 1'b0;
    for (int unsigned c = 0; c < 4; c++) begin
      written_zero |= state_q.color_mask[c] && wcolor[8*c +: 8] == 8'h00;
      written_full |= state_q.color_mask[c] && wcolor[8*c +: 8] == 8'hff;
    end
  end
  for (genvar b = 0; b < 5; b++) begin : g_blend_out
    BlendWritesZero: cover property (@(posedge clk_i) disable iff (!rst_ni)
        cwe && state_q.blend == 3'(b) && written_zero);
    BlendWritesFull: cover property (@(posedge clk_i) disable iff (!rst_ni)
        cwe && state_q.blend == 3'(b) && written_full);
  end

  // ---------------------------------------------------------------------------------------
  // Fragment corners, as the window takes the fragment.
  // ---------------------------------------------------------------------------------------
  logic take;
  assign take = i_valid & w_ready;
  FragDepthZero:  cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_z == '0);
  FragDepthMax:   cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_z == '1);
  FragAlphaZero:  cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_alpha == 8'd0);
  FragAlphaFull:  cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_alpha == 8'hff);
  FragCovZero:    cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_cov == '0);
  FragCovOne:     cover property (@(posedge clk_i) disable iff (!rst_ni) take && i_cov == CovW'(1));
  FragCovFull:    cover property (@(posedge clk_i) disable iff (!rst_ni)
      take && i_cov == CovW'(COV_SAMPLES));
  for (genvar c = 0; c < 4; c++) begin : g_acc
    AccumSaturates: cover property (@(posedge clk_i) disable iff (!rst_ni)
        x9_acc && acc_sat[c]);
  end

  // Where in the tile: row band (top, inside, bottom) x column band (left, inside, right).
  localparam int XW = $clog2(TILE_W);
  logic [1:0] col_band, row_band;
  always_comb begin
    col_band = i_addr[XW-1:0] == '0 ? 2'd0 : (i_addr[XW-1:0] == '1 ? 2'd2 : 2'd1);
    row_band = i_addr[AddrW-1:XW] == '0 ? 2'd0 : (i_addr[AddrW-1:XW] == '1 ? 2'd2 : 2'd1);
  end
  for (genvar r = 0; r < 3; r++) begin : g_row
    for (genvar c = 0; c < 3; c++) begin : g_col
      FragInTile: cover property (@(posedge clk_i) disable iff (!rst_ni)
          take && row_band == 2'(r) && col_band == 2'(c));
    end
  end

  // ---------------------------------------------------------------------------------------
  // Ordering: a fragment's distance to the last earlier one to its pixel, in fragments taken,
  // crossed with what happened between the two: nothing, a cycle without a fragment offered
  // (gap), stall_i, or the port refusing an offer on its own (window full).
  // ---------------------------------------------------------------------------------------
  logic [AddrW-1:0] hist_addr [Dist];
  logic [Dist-1:0]  hist_valid, hist_gap, hist_stall, hist_full;
  logic             ev_gap, ev_stall, ev_full;
  assign ev_gap   = !frag_valid_i;
  assign ev_stall = stall_i;
  assign ev_full  = frag_valid_i && !frag_ready_o && !stall_i && !tile_req_i && !tile_clear_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      hist_valid <= '0;
      hist_gap   <= '0;
      hist_stall <= '0;
      hist_full  <= '0;
    end else if (take) begin
      hist_valid <= {hist_valid[Dist-2:0], 1'b1};
      hist_gap   <= {hist_gap[Dist-2:0], 1'b0} | {Dist{ev_gap}};
      hist_stall <= {hist_stall[Dist-2:0], 1'b0} | {Dist{ev_stall}};
      hist_full  <= {hist_full[Dist-2:0], 1'b0} | {Dist{ev_full}};
    end else begin
      hist_gap   <= hist_gap | {Dist{ev_gap}};
      hist_stall <= hist_stall | {Dist{ev_stall}};
      hist_full  <= hist_full | {Dist{ev_full}};
    end
  end
  always_ff @(posedge clk_i) begin
    if (take) begin
      hist_addr[0] <= i_addr;
      for (int unsigned k = 1; k < Dist; k++) hist_addr[k] <= hist_addr[k-1];
    end
  end

  // nearest[k]: entry k is the nearest earlier fragment to this one's pixel.
  logic [Dist-1:0] match, nearest;
  always_comb begin
    for (int unsigned k = 0; k < Dist; k++) match[k] = hist_valid[k] && hist_addr[k] == i_addr;
    nearest = match & ~(match - 1'b1);
  end
  for (genvar k = 0; k < Dist; k++) begin : g_dist
    SamePixelCalm: cover property (@(posedge clk_i) disable iff (!rst_ni)
        take && nearest[k] && !hist_gap[k] && !hist_stall[k] && !hist_full[k] &&
        !ev_gap && !ev_stall && !ev_full);
    // An event in the take's own cycle counts too: the window takes from the input stage, so
    // the port may already be idle (the stream's last fragment) when the pair is taken.
    SamePixelGap: cover property (@(posedge clk_i) disable iff (!rst_ni)
        take && nearest[k] && (hist_gap[k] || ev_gap));
    SamePixelStall: cover property (@(posedge clk_i) disable iff (!rst_ni)
        take && nearest[k] && (hist_stall[k] || ev_stall));
    SamePixelFull: cover property (@(posedge clk_i) disable iff (!rst_ni)
        take && nearest[k] && (hist_full[k] || ev_full));
  end

  // Every window slot: taken, waiting for its pixel (the pipeline or an older slot has it),
  // the same under stall_i, and picked past an older waiting fragment.
  for (genvar s = 0; s < WINDOW; s++) begin : g_slot
    logic waits;
    assign waits = win_valid[s] && (|win_hit[s*HitW +: HitW] || |win_same[s*WINDOW +: WINDOW]);
    SlotTaken: cover property (@(posedge clk_i) disable iff (!rst_ni) take && win_ins[s]);
    SlotWaits: cover property (@(posedge clk_i) disable iff (!rst_ni) waits);
    SlotWaitsStalled: cover property (@(posedge clk_i) disable iff (!rst_ni) waits && stall_i);
    SlotPickedPastOlder: cover property (@(posedge clk_i) disable iff (!rst_ni)
        win_pick[s] && |(win_valid & win_older[s*WINDOW +: WINDOW]));
  end

  // ---------------------------------------------------------------------------------------
  // Tiles and frame operations. A read of the tile port reads every plane (a store); loads and
  // clears take the planes of tile_planes_i.
  // ---------------------------------------------------------------------------------------
  logic       load, read;
  logic [4:0] planes;
  assign load   = tile_req_i && tile_we_i;
  assign read   = tile_req_i && !tile_we_i;
  assign planes = tile_planes_i;

  TileOriginFirst: cover property (@(posedge clk_i) disable iff (!rst_ni)
      take && tile_x0_i == '0 && tile_y0_i == '0);
  TileOriginRow: cover property (@(posedge clk_i) disable iff (!rst_ni)
      take && tile_x0_i != '0 && tile_y0_i == '0);
  TileOriginColumn: cover property (@(posedge clk_i) disable iff (!rst_ni)
      take && tile_x0_i == '0 && tile_y0_i != '0);
  TileOriginInner: cover property (@(posedge clk_i) disable iff (!rst_ni)
      take && tile_x0_i != '0 && tile_y0_i != '0);

  // Since the last load or clear: a fragment taken; since the last read of beat 0: anything
  // that could change the planes (a load, a clear, a fragment).
  logic touched_q, read0_q, was_read_q, was_load_q;
  logic [4:0] was_clear_q, cleared_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      touched_q   <= 1'b0;
      read0_q     <= 1'b0;
      was_read_q  <= 1'b0;
      was_load_q  <= 1'b0;
      was_clear_q <= '0;
      cleared_q   <= '0;
    end else begin
      if (load || tile_clear_i) touched_q <= 1'b0;
      else if (take) touched_q <= 1'b1;
      if (read && tile_addr_i == '0) read0_q <= 1'b1;
      else if (load || tile_clear_i || take) read0_q <= 1'b0;
      was_read_q  <= read;
      was_load_q  <= load;
      was_clear_q <= tile_clear_i ? planes : '0;
      // cleared_q[p]: plane p fast-cleared, no read since (a load of it is "cleared, loaded").
      for (int unsigned p = 0; p < 5; p++) begin
        if (tile_clear_i && planes[p]) cleared_q[p] <= 1'b1;
        else if (read || (load && planes[p])) cleared_q[p] <= 1'b0;
      end
    end
  end

  StoreUntouched: cover property (@(posedge clk_i) disable iff (!rst_ni)
      read && tile_addr_i == '0 && !touched_q);
  StoreTwice: cover property (@(posedge clk_i) disable iff (!rst_ni)
      read && tile_addr_i == '0 && read0_q);
  StoreFirstBeat: cover property (@(posedge clk_i) disable iff (!rst_ni) read && tile_addr_i == '0);
  StoreLastBeat: cover property (@(posedge clk_i) disable iff (!rst_ni) read && tile_addr_i == '1);
  StateWrite: cover property (@(posedge clk_i) disable iff (!rst_ni) state_we_i);
  CounterClear: cover property (@(posedge clk_i) disable iff (!rst_ni) cnt_clear_i);
  ClearPlanes: cover property (@(posedge clk_i) disable iff (!rst_ni)
      tile_clear_i && !$onehot(planes) && planes != '0);

  // Per plane: colour, depth, coverage, peel, accumulation (tile_planes_i's bits).
  for (genvar p = 0; p < 5; p++) begin : g_plane
    logic clear;
    assign clear = tile_clear_i && planes[p];
    PlaneClear: cover property (@(posedge clk_i) disable iff (!rst_ni) clear);
    PlaneLoadFirstBeat: cover property (@(posedge clk_i) disable iff (!rst_ni)
        load && planes[p] && tile_addr_i == '0);
    PlaneLoadLastBeat: cover property (@(posedge clk_i) disable iff (!rst_ni)
        load && planes[p] && tile_addr_i == '1);
    PlaneClearedThenLoaded: cover property (@(posedge clk_i) disable iff (!rst_ni)
        load && planes[p] && cleared_q[p]);
    PlaneClearAfterStore: cover property (@(posedge clk_i) disable iff (!rst_ni)
        clear && was_read_q);
    PlaneStoreAfterClear: cover property (@(posedge clk_i) disable iff (!rst_ni)
        read && was_clear_q[p]);
    PlaneClearAfterLoad: cover property (@(posedge clk_i) disable iff (!rst_ni)
        clear && was_load_q);
    PlaneLoadAfterClear: cover property (@(posedge clk_i) disable iff (!rst_ni)
        load && was_clear_q[p]);
  end

  // Tile operations (docs/rtl.md "Tile operations"): a copy (depth to peel) or a resolve (under
  // the background, or of the accumulation) starting at beat 0, next to a load, a store, a clear (the cycle before) or
  // after fragments since the last load or clear; a pass boundary with the tile resident.
  logic [2:0] op_start;
  logic       was_plain_read_q;
  assign op_start = {read && tile_wboit_i, read && tile_resolve_i, read && tile_copy_i} &
                    {3{tile_addr_i == '0}};
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) was_plain_read_q <= 1'b0;
    else was_plain_read_q <= read && !tile_copy_i && !tile_resolve_i && !tile_wboit_i;
  end
  for (genvar o = 0; o < 3; o++) begin : g_tileop
    TileOpAfterLoad: cover property (@(posedge clk_i) disable iff (!rst_ni)
        op_start[o] && was_load_q);
    TileOpAfterStore: cover property (@(posedge clk_i) disable iff (!rst_ni)
        op_start[o] && was_plain_read_q);
    TileOpAfterClear: cover property (@(posedge clk_i) disable iff (!rst_ni)
        op_start[o] && was_clear_q != '0);
    TileOpAfterFragment: cover property (@(posedge clk_i) disable iff (!rst_ni)
        op_start[o] && touched_q);
  end
  PassBoundaryResident: cover property (@(posedge clk_i) disable iff (!rst_ni)
      state_we_i && touched_q);

  // Renamed copies (docs/rtl.md "Renamed copies"): a fast clear of depth with tile_copy_i, the
  // cycle after a load, after a read (a sweep's or a store's), with fragments taken since the
  // tile's last load or clear (right after a pass), and with a read next (the store after a
  // run's last renamed copy).
  logic rename, was_rename_q;
  assign rename = tile_clear_i && tile_copy_i;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) was_rename_q <= 1'b0;
    else was_rename_q <= rename;
  end
  RenamedAfterLoad: cover property (@(posedge clk_i) disable iff (!rst_ni)
      rename && was_load_q);
  RenamedAfterRead: cover property (@(posedge clk_i) disable iff (!rst_ni)
      rename && was_read_q);
  RenamedAfterFragment: cover property (@(posedge clk_i) disable iff (!rst_ni)
      rename && touched_q);
  RenamedThenRead: cover property (@(posedge clk_i) disable iff (!rst_ni)
      read && was_rename_q);

  // Counters at all ones: the nine event counters, then the tile loads and stores.
  logic [10:0] sat;
  assign sat = {tile_cnt_sat, cnt_sat};
  for (genvar i = 0; i < 11; i++) begin : g_cnt
    CounterSaturated: cover property (@(posedge clk_i) disable iff (!rst_ni) sat[i]);
  end

endmodule
