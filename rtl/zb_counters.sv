// zb_counters: NUM saturating event counters of CNT_W bits. Counter i adds 1 at each rising
// edge where inc_i[i] is set; at all ones it stays there. A cycle with clear_i set makes every
// counter 0 at its edge (that cycle's events are not counted).
// "At all ones" is a flop (sat_q), set by the increment that reaches all ones, so the counter's
// enable is not behind a CNT_W-bit comparison of its own value.
module zb_counters #(
  parameter int NUM   = 9,
  parameter int CNT_W = 32
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,   // asynchronous, active low
  input  logic                 clear_i,
  input  logic [NUM-1:0]       inc_i,
  output logic [NUM*CNT_W-1:0] cnt_o     // counter i at [i*CNT_W +: CNT_W]
);

  localparam logic [CNT_W-1:0] CntMax = {CNT_W{1'b1}};

  // The next value is written in the flop block itself: clear_i and inc_i come from ports, and
  // a simulator evaluates logic on ports at every evaluation, flops only at the edge.
  for (genvar i = 0; i < NUM; i++) begin : g_cnt
    logic [CNT_W-1:0] cnt_q;
    logic             sat_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        cnt_q <= '0;
        sat_q <= 1'b0;
      end else if (clear_i) begin
        cnt_q <= '0;
        sat_q <= 1'b0;
      end else if (inc_i[i] && !sat_q) begin
        cnt_q <= cnt_q + {{(CNT_W-1){1'b0}}, 1'b1};
        sat_q <= cnt_q == CntMax - {{(CNT_W-1){1'b0}}, 1'b1};
      end
    end

    assign cnt_o[i*CNT_W +: CNT_W] = cnt_q;

`ifndef SYNTHESIS
`ifndef ZB_NO_SVA
    // A counter never wraps: at all ones it stays there until cleared.
    CntSaturates: assert property (@(posedge clk_i) disable iff (!rst_ni)
        (!clear_i && cnt_q == CntMax) |=> (cnt_q == CntMax));
    // The flag is exactly "at all ones".
    SatFlagExact: assert property (@(posedge clk_i) disable iff (!rst_ni)
        sat_q == (cnt_q == CntMax));
`endif
`endif
  end

endmodule
