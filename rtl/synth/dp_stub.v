// dp_stub: a stand-in for interp_dp in the analysis design core_nodp
// (rtl/synth/designs.mk: yosys drops interp_dp and gives this module its
// name), for timing only: it measures what the rest of
// `core` (block preparation, queue, output stage, the wrapper) makes when
// the datapath costs nothing. NOT an interpolator: it loads the prepared
// block into a register that rotates by one bit per clock (every bit of
// the block stays live, so yosys keeps the queue whole), takes a block in
// every other clock of the command, and shows bits of that register as
// its pulse and busy outputs. Same ports and parameter as interp_dp.
`default_nettype none

module dp_stub #(
    parameter integer W = 24  // coordinate magnitude width, as interp_dp's
) (
    input  wire           i_clk,
    input  wire           i_rst,
    input  wire           i_cmd,
    input  wire           i_valid,
    output wire           o_ready,
    input  wire [7*W+20:0] i_pre,
    output reg            o_pulse,
    output reg            o_pulse_y,
    output reg            o_pulse_neg,
    output reg            o_pulse_last,
    output wire           o_busy,
    output wire [W-1:0]   o_xmag,
    output wire           o_xneg,
    output wire [W-1:0]   o_ymag,
    output wire           o_yneg,
    output wire [W+1:0]   o_d,
    output wire [1:0]     o_q,
    output wire [2:0]     o_k,
    output wire           o_arc
);

  localparam integer PB = 7 * W + 21;  // the prepared block's width

  reg [PB-1:0] blk_q;  // the last block taken, rotating
  reg tog_q;           // takes a block in every other clock
  wire ld = i_valid & i_cmd & tog_q;
  assign o_ready = ld;

  always @(posedge i_clk) begin
    tog_q <= i_rst ? 1'b0 : ~tog_q;
    blk_q <= ld ? i_pre : {blk_q[0], blk_q[PB-1:1]};
    o_pulse <= blk_q[0] & i_cmd;
    o_pulse_y <= blk_q[1];
    o_pulse_neg <= blk_q[2];
    o_pulse_last <= blk_q[3];
  end

  assign o_busy = blk_q[4];
  assign o_xmag = {W{1'b0}};
  assign o_xneg = 1'b0;
  assign o_ymag = {W{1'b0}};
  assign o_yneg = 1'b0;
  assign o_d = {(W + 2){1'b0}};
  assign o_q = 2'd0;
  assign o_k = 3'd0;
  assign o_arc = 1'b0;

endmodule
