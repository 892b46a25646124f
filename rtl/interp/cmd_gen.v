// cmd_gen: the interpolation command pulses.
//
//   SRC 0: none
//   SRC 1: the input pin (paper A's interrupt line): synchronised by two
//          flip-flops, one pulse per rising edge
//   SRC 2: feed generator, a phase accumulator: one pulse per carry out of
//          acc + INC (N bits), rate = INC * f_clk / 2^N; INC may change
//          while running (the phase carries over)
//   SRC 3: every clock (the core's limit; the output stage decides)
`default_nettype none

module cmd_gen #(
    parameter integer N = 32  // phase accumulator width
) (
    input  wire         i_clk,
    input  wire         i_rst,
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

  // Phase accumulator (runs only while selected).
  reg [N-1:0] acc_q;
  wire [N:0] acc_sum = {1'b0, acc_q} + {1'b0, i_inc};
  always @(posedge i_clk) begin
    if (i_rst || i_src != 2'd2) acc_q <= {N{1'b0}};
    else acc_q <= acc_sum[N-1:0];
  end

  // The command pulse, registered.
  always @(posedge i_clk) begin
    if (i_rst) o_cmd <= 1'b0;
    else case (i_src)
      2'd1: o_cmd <= pin_rise;
      2'd2: o_cmd <= acc_sum[N];
      2'd3: o_cmd <= 1'b1;
      default: o_cmd <= 1'b0;
    endcase
  end

endmodule
