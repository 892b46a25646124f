// uart_tx: 8N1 transmitter. A character is taken when o_ready and i_valid
// are both high, and sent LSB first between a start and a stop bit.
`default_nettype none

module uart_tx #(
    parameter integer CLKS_PER_BIT = 12  // clock / baud rate (12: 1 Mbaud at 12 MHz), >= 2
) (
    input  wire       i_clk,
    input  wire       i_rst,
    input  wire [7:0] i_data,
    input  wire       i_valid,
    output wire       o_ready,
    output wire       o_tx      // the line, idle high
);

  generate
    if (CLKS_PER_BIT < 2 || CLKS_PER_BIT > 65535) begin : g_bad_clks
      uart_tx_parameter_CLKS_PER_BIT_must_be_2_to_65535 u_bad ();
    end
  endgenerate

  localparam [15:0] FULL = CLKS_PER_BIT[15:0] - 16'd1;

  reg [9:0] shift_q;   // stop, data, start: bit 0 on the line
  reg [3:0] left_q;    // bits still to send, the one on the line included
  reg [15:0] cnt_q;

  assign o_ready = (left_q == 4'd0);
  assign o_tx = (left_q == 4'd0) ? 1'b1 : shift_q[0];

  // Shift register and bit timing.
  always @(posedge i_clk) begin
    if (i_rst) begin
      shift_q <= 10'h3FF;
      left_q <= 4'd0;
      cnt_q <= 16'd0;
    end else if (left_q == 4'd0) begin
      if (i_valid) begin
        shift_q <= {1'b1, i_data, 1'b0};
        left_q <= 4'd10;
        cnt_q <= FULL;
      end
    end else if (cnt_q != 16'd0) begin
      cnt_q <= cnt_q - 16'd1;
    end else begin
      shift_q <= {1'b1, shift_q[9:1]};
      left_q <= left_q - 4'd1;
      cnt_q <= FULL;
    end
  end

endmodule
