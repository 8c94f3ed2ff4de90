// A DUT that breaks the adapter's rules on purpose, one way per define, for the testbench's
// checks to catch (tests/conformance/test_kit_cli.sh): BROKEN_ST_VALID offers a store pixel with
// no store under way, BROKEN_X leaves frag_ready_o unknown, BROKEN_HANG never takes a fragment.
// Otherwise it takes everything and stores zeros: a DUT that writes nothing.
module zb_conf_adapter #(
  parameter int DEPTH_BITS  = 24,
  parameter int COV_SAMPLES = 16,
  parameter int TILE_W      = 64,
  parameter int TILE_H      = 64,
  parameter int BEAT        = 8,
  parameter int ACC_BITS    = 16,
  parameter int REV_BITS    = 8,
  parameter int WEIGHT_BITS = 4,
  localparam int AccW = 4 * ACC_BITS + REV_BITS
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            state_we_i,
  input  logic [12:0]     state_i,
  input  logic [2:0]      state_layers_i,
  input  logic [15:0]     tile_x0_i,
  input  logic [15:0]     tile_y0_i,
  input  logic            ld_valid_i,
  output logic            ld_ready_o,
  input  logic [31:0]     ld_color_i,
  input  logic [31:0]     ld_depth_i,
  input  logic [7:0]      ld_cov_i,
  input  logic [31:0]     ld_peel_i,
  input  logic [AccW-1:0] ld_acc_i,
  input  logic            frag_valid_i,
  output logic            frag_ready_o,
  input  logic [15:0]     frag_x_i,
  input  logic [15:0]     frag_y_i,
  input  logic [31:0]     frag_z_i,
  input  logic [31:0]     frag_rgba_i,
  input  logic [7:0]      frag_cov_i,
  output logic            idle_o,
  input  logic            st_start_i,
  input  logic            st_resolve_i,
  output logic            st_valid_o,
  output logic [31:0]     st_color_o,
  output logic [31:0]     st_depth_o,
  output logic [7:0]      st_cov_o,
  output logic [31:0]     st_peel_o,
  output logic [AccW-1:0] st_acc_o,
  output logic [4:0]      planes_o,
  output logic [3:0]      layers_o,
  output logic            ret_d_valid_o,
  output logic [31:0]     ret_d_pixel_o,
  output logic            ret_dwe_o,
  output logic [31:0]     ret_wdepth_o,
  output logic            ret_vwe_o,
  output logic [7:0]      ret_wcov_o,
  output logic            ret_c_valid_o,
  output logic [31:0]     ret_c_pixel_o,
  output logic            ret_cwe_o,
  output logic [31:0]     ret_wcolor_o,
  output logic            ret_awe_o,
  output logic [AccW-1:0] ret_wacc_o
);
  localparam int Words = TILE_W * TILE_H;
  int unsigned left;  // store pixels still to offer
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) left <= 0;
    else if (st_start_i) left <= Words;
    else if (left != 0) left <= left - 1;
  end
`ifdef BROKEN_ST_VALID
  assign st_valid_o = 1'b1;
`else
  assign st_valid_o = left != 0;
`endif
`ifdef BROKEN_X
  assign frag_ready_o = 1'bx;
`elsif BROKEN_HANG
  assign frag_ready_o = 1'b0;
`else
  assign frag_ready_o = 1'b1;
`endif
  assign ld_ready_o = 1'b1;
  assign idle_o     = left == 0;
  assign planes_o   = 5'b01111;
  assign layers_o   = 4'd0;
  assign {st_color_o, st_depth_o, st_cov_o, st_peel_o, st_acc_o} = '0;
  assign {ret_d_valid_o, ret_d_pixel_o, ret_dwe_o, ret_wdepth_o, ret_vwe_o, ret_wcov_o} = '0;
  assign {ret_c_valid_o, ret_c_pixel_o, ret_cwe_o, ret_wcolor_o, ret_awe_o, ret_wacc_o} = '0;
  wire unused = &{1'b0, state_we_i, state_i, state_layers_i, st_resolve_i, tile_x0_i, tile_y0_i, ld_valid_i, ld_color_i,
                  ld_depth_i, ld_cov_i, ld_peel_i, ld_acc_i, frag_valid_i, frag_x_i, frag_y_i,
                  frag_z_i, frag_rgba_i, frag_cov_i};
endmodule
