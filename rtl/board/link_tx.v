// link_tx: the sending half of the host link. Takes the reply's bytes from
// the reply queue ({last, byte}, first-word-fall-through), sends each with
// SLIP escapes through uart_tx, computes the CRC as they go, and after the
// last byte sends the CRC (high byte first, escaped) and an END.
`default_nettype none

module link_tx (
    input  wire       i_clk,
    input  wire       i_rst,
    // The reply queue
    input  wire [8:0] i_data,    // {last, byte}
    input  wire       i_valid,
    output wire       o_pop,
    // To uart_tx
    output reg  [7:0] o_char,
    output reg        o_char_valid,
    input  wire       i_char_ready
);

`include "board_proto.vh"

  // What is being sent: 0 a reply byte, 1 CRC high, 2 CRC low, 3 END.
  reg [1:0] part_q;
  reg busy_q;        // a byte is in cur_q
  reg esc2_q;        // the second character of an escape is due
  reg [7:0] cur_q;
  reg last_q;
  reg [15:0] crc_q;
  wire [15:0] crc_next;

  crc16_byte u_crc (.i_crc(crc_q), .i_byte(i_data[7:0]), .o_crc(crc_next));

  wire special = cur_q == SLIP_END[7:0] || cur_q == SLIP_ESC[7:0];
  wire [7:0] esc_code = (cur_q == SLIP_END[7:0]) ? SLIP_ESC_END[7:0] : SLIP_ESC_ESC[7:0];
  // A character handed over to uart_tx this clock.
  wire sent = o_char_valid & i_char_ready;
  assign o_pop = ~busy_q & i_valid & (part_q == 2'd0);

  // The character on offer to uart_tx, from registers.
  always @(*) begin
    o_char_valid = busy_q;
    if (part_q == 2'd3) o_char = SLIP_END[7:0];
    else if (esc2_q) o_char = esc_code;
    else if (special) o_char = SLIP_ESC[7:0];
    else o_char = cur_q;
  end

  // Byte sequencing: reply bytes, then the CRC, then END.
  always @(posedge i_clk) begin
    if (i_rst) begin
      part_q <= 2'd0;
      busy_q <= 1'b0;
      esc2_q <= 1'b0;
      cur_q <= 8'd0;
      last_q <= 1'b0;
      crc_q <= CRC_INIT[15:0];
    end else if (o_pop) begin
      cur_q <= i_data[7:0];
      last_q <= i_data[8];
      crc_q <= crc_next;
      busy_q <= 1'b1;
    end else if (sent) begin
      if (part_q != 2'd3 && special && !esc2_q) begin
        esc2_q <= 1'b1;
      end else begin
        esc2_q <= 1'b0;
        case (part_q)
          2'd0: if (last_q) begin
            part_q <= 2'd1;
            cur_q <= crc_q[15:8];
          end else busy_q <= 1'b0;
          2'd1: begin
            part_q <= 2'd2;
            cur_q <= crc_q[7:0];
          end
          2'd2: part_q <= 2'd3;
          default: begin
            part_q <= 2'd0;
            busy_q <= 1'b0;
            crc_q <= CRC_INIT[15:0];
          end
        endcase
      end
    end
  end

endmodule
