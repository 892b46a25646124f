// cmd_gen: the interpolation command pulses.
//
//   SRC 0: none
//   SRC 1: the input pin (paper A's interrupt line): synchronised by two
//          flip-flops, one pulse per rising edge
//   SRC 2: feed generator, a phase accumulator: one pulse per carry out of
//          acc + INC (N bits), rate = INC * f_clk / 2^N; INC may change
//          while running (the phase carries over)
//   SRC 3: every clock (the core's limit; the output stage decides)
//
// i_ce, a clock enable of the feed generator and the every-clock source
// (the board's time scale, docs/board.md: a feed hold slows the command
// rate along a ramp to rest): the phase advances and a command comes only
// in clocks with i_ce, so the rate is scaled by the fraction of clocks
// with i_ce. Tie it to 1 where there is no time scale. The pin source is
// not scaled (an outside source: a hold cannot slow it).
`default_nettype none

module cmd_gen #(
    parameter integer N = 32  // phase accumulator width
) (
    input  wire         i_clk,
    input  wire         i_rst,
    input  wire         i_ce,
    input  wire [1:0]   i_src,
    input  wire         i_pin,
    input  wire [N-1:0] i_inc,
    output reg          o_cmd
);

  // Pin synchroniser and edge detector.
  reg [2:0] pin_q;
  always @(posedge i_clk) begin
    if (i_rst) pin_q <= 3'b000;
    else pin_q <= {pin_q[1:0], i_pin};
  end
  wire pin_rise = pin_q[1] & ~pin_q[2];

  // Phase accumulator (runs only while selected, on i_ce).
  reg [N-1:0] acc_q;
  wire [N:0] acc_sum = {1'b0, acc_q} + {1'b0, i_inc};
  always @(posedge i_clk) begin
    if (i_rst || i_src != 2'd2) acc_q <= {N{1'b0}};
    else if (i_ce) acc_q <= acc_sum[N-1:0];
  end

  // The command pulse, registered.
  always @(posedge i_clk) begin
    if (i_rst) o_cmd <= 1'b0;
    else case (i_src)
      2'd1: o_cmd <= pin_rise;
      2'd2: o_cmd <= i_ce & acc_sum[N];
      2'd3: o_cmd <= i_ce;
      default: o_cmd <= 1'b0;
    endcase
  end

endmodule
