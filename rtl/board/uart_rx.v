// uart_rx: 8N1 receiver. The line is synchronised by two flip-flops; a
// falling edge starts a character, the start bit is checked at its middle
// and each data bit and the stop bit are sampled one bit time apart, at
// their middles. A character whose stop bit is 0 is reported on o_ferr
// (and not on o_valid): the link counts it as a corrupt frame.
`default_nettype none

module uart_rx #(
    parameter integer CLKS_PER_BIT = 12  // clock / baud rate (12: 1 Mbaud at 12 MHz), >= 4
) (
    input  wire       i_clk,
    input  wire       i_rst,
    input  wire       i_rx,      // the line, idle high, asynchronous
    output reg  [7:0] o_data,
    output reg        o_valid,   // one clock: o_data is a character
    output reg        o_ferr     // one clock: a character with a bad stop bit
);

  generate
    if (CLKS_PER_BIT < 4 || CLKS_PER_BIT > 65535) begin : g_bad_clks
      uart_rx_parameter_CLKS_PER_BIT_must_be_4_to_65535 u_bad ();
    end
  endgenerate

  localparam [15:0] FULL = CLKS_PER_BIT[15:0] - 16'd1;
  localparam [15:0] HALF = CLKS_PER_BIT[15:0] / 16'd2 - 16'd1;

  reg [1:0] sync_q;
  wire rx = sync_q[1];
  reg busy_q;
  reg [15:0] cnt_q;
  reg [3:0] bit_q;   // 0: start bit, 1..8 data, 9 stop
  reg [7:0] shift_q;

  // Synchroniser (reset to the idle level).
  always @(posedge i_clk) begin
    if (i_rst) sync_q <= 2'b11;
    else sync_q <= {sync_q[0], i_rx};
  end

  // Bit timing and shifting.
  always @(posedge i_clk) begin
    o_valid <= 1'b0;
    o_ferr <= 1'b0;
    if (i_rst) begin
      busy_q <= 1'b0;
      cnt_q <= 16'd0;
      bit_q <= 4'd0;
      shift_q <= 8'd0;
      o_data <= 8'd0;
    end else if (!busy_q) begin
      if (!rx) begin
        busy_q <= 1'b1;
        cnt_q <= HALF;
        bit_q <= 4'd0;
      end
    end else if (cnt_q != 16'd0) begin
      cnt_q <= cnt_q - 16'd1;
    end else begin
      cnt_q <= FULL;
      bit_q <= bit_q + 4'd1;
      if (bit_q == 4'd0) begin
        if (rx) busy_q <= 1'b0;  // a glitch, not a start bit
      end else if (bit_q == 4'd9) begin
        busy_q <= 1'b0;
        o_data <= shift_q;
        o_valid <= rx;
        o_ferr <= ~rx;
      end else begin
        shift_q <= {rx, shift_q[7:1]};  // LSB first
      end
    end
  end

endmodule
