// cmd_gen: the interpolation command pulses.
//
//   SRC 0: none
//   SRC 1: the input pin (paper A's interrupt line): synchronised by two
//          flip-flops, one pulse per rising edge
//   SRC 2: feed generator, a phase accumulator: one pulse per carry out of
//          acc + INC (N bits), rate = INC * f_clk / 2^N; INC may change
//          while running (the phase carries over). The accumulator is two
//          halves, the low half's carry registered into the high half's
//          next step (so no carry chain is longer than N - N/2 bits: the
//          command comes one LUT after the high half's chain): a carry of
//          the low half reaches the output one step late, the count of
//          pulses over any run differs from a one-piece accumulator's by
//          at most one, the rate is the same.
//   SRC 3: every clock (the core's limit; the output stage decides)
//
// i_ce, a clock enable of the feed generator and the every-clock source
// (the board's time scale, docs/board.md: a feed hold slows the command
// rate along a ramp to rest): the phase advances and a command comes only
// in clocks with i_ce, so the rate is scaled by the fraction of clocks
// with i_ce. Tie it to 1 where there is no time scale. The pin source is
// not scaled (an outside source: a hold cannot slow it).
//
// o_cmd_next is o_cmd's next value (its register's input): the output
// stage gates it with its own ready term a clock ahead, so the command the
// core sees is one register (step_out).
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
    output reg          o_cmd,
    output reg          o_cmd_next   // o_cmd of the next clock (combinational)
);

  // Pin synchroniser and edge detector.
  reg [2:0] pin_q;
  always @(posedge i_clk) begin
    if (i_rst) pin_q <= 3'b000;
    else pin_q <= {pin_q[1:0], i_pin};
  end
  wire pin_rise = pin_q[1] & ~pin_q[2];

  // Phase accumulator (runs only while selected, on i_ce): the low NL
  // bits, their carry (cl_q, added into the high half at the next step)
  // and the high NH bits, whose carry out is the command.
  localparam integer NL = N / 2;
  localparam integer NH = N - NL;
  reg [NL-1:0] lo_q;
  reg [NH-1:0] hi_q;
  reg cl_q;
  wire [NL:0] lo_sum = {1'b0, lo_q} + {1'b0, i_inc[NL-1:0]};
  wire [NH:0] hi_sum = {1'b0, hi_q} + {1'b0, i_inc[N-1:NL]} + {{NH{1'b0}}, cl_q};
  always @(posedge i_clk) begin
    if (i_rst || i_src != 2'd2) begin
      lo_q <= {NL{1'b0}};
      hi_q <= {NH{1'b0}};
      cl_q <= 1'b0;
    end else if (i_ce) begin
      lo_q <= lo_sum[NL-1:0];
      hi_q <= hi_sum[NH-1:0];
      cl_q <= lo_sum[NL];
    end
  end

  // The command pulse, registered: o_cmd_next is its register's input,
  // written as the carry and two terms from flip-flops and inputs (kept:
  // LUT boundaries, so the carry is one LUT input, not decoded again).
  (* keep *) wire feed_en = ~i_rst & (i_src == 2'd2) & i_ce;
  (* keep *) wire other_cmd = ~i_rst & ((i_src == 2'd1) ? pin_rise : (i_src == 2'd3) & i_ce);
  always @(*) o_cmd_next = other_cmd | (feed_en & hi_sum[NH]);
  always @(posedge i_clk) o_cmd <= o_cmd_next;

endmodule
