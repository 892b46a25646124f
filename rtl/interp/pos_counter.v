// pos_counter: the position of one axis in steps, two's complement,
// readable at any time; counts the pulses the core issues.
`default_nettype none

module pos_counter #(
    parameter integer PW = 32  // counter width
) (
    input  wire          i_clk,
    input  wire          i_rst,
    input  wire          i_pulse,
    input  wire          i_neg,
    output reg  [PW-1:0] o_pos
);

  always @(posedge i_clk) begin
    if (i_rst) o_pos <= {PW{1'b0}};
    else if (i_pulse) o_pos <= o_pos + {{(PW-1){i_neg}}, 1'b1};  // +1 or -1
  end

endmodule
