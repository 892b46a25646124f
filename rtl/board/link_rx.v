// link_rx: the receiving half of the host link. Undoes the SLIP framing of
// the characters from uart_rx, writes each frame's bytes into one of two
// frame buffers (banks of MAX bytes; the next frame fills the other bank
// while link_ctrl reads this one), and computes the CRC and the length as
// the bytes come. At an END after at least one byte it reports the frame:
// o_done for one clock with its bank, length, CRC residue check and
// whether a byte of it was corrupt (bad escape, bad stop bit). An END with
// no byte before it is ignored (the host sends one to flush line noise).
// A frame that ends while link_ctrl is still busy with the last one is
// dropped (the host, getting no reply, sends it again).
`default_nettype none

module link_rx #(
    parameter integer MAX = 64  // bank size in bytes: the largest frame (a power of 2, 8..128)
) (
    input  wire       i_clk,
    input  wire       i_rst,
    input  wire [7:0] i_byte,     // from uart_rx
    input  wire       i_valid,
    input  wire       i_ferr,
    input  wire       i_busy,     // link_ctrl has not finished the last frame
    output reg        o_done,     // one clock: a frame has ended
    output reg        o_bank,     // its bank
    output reg  [7:0] o_len,      // its length (MAX + 1: longer than MAX)
    output reg        o_crc_ok,   // its CRC residue is 0
    output reg        o_bad,      // a byte of it was corrupt
    // Read port of the frame buffers: registered, one clock.
    input  wire [7:0] i_rd_addr,  // {bank, byte index}
    output reg  [7:0] o_rd_data
);

`include "board_proto.vh"

  localparam integer AW = $clog2(MAX);
  generate
    if (MAX < 8 || MAX > 128 || (1 << AW) != MAX) begin : g_bad_max
      link_rx_parameter_MAX_must_be_a_power_of_2_from_8_to_128 u_bad ();
    end
  endgenerate

  reg [7:0] mem [0:2*MAX-1];
  reg bank_q;       // the bank being filled
  reg [7:0] len_q;  // bytes so far, saturating at MAX + 1
  reg esc_q;        // the last character was ESC
  reg bad_q;
  reg [15:0] crc_q;
  wire [15:0] crc_next;

  // The unescaped byte of this character, if any.
  wire is_end = i_valid && i_byte == SLIP_END[7:0];
  wire is_esc = i_valid && !esc_q && i_byte == SLIP_ESC[7:0];
  wire esc_ok = i_byte == SLIP_ESC_END[7:0] || i_byte == SLIP_ESC_ESC[7:0];
  wire [7:0] data = !esc_q ? i_byte : (i_byte == SLIP_ESC_END[7:0] ? SLIP_END[7:0] : SLIP_ESC[7:0]);
  wire take = i_valid && !is_end && !is_esc;
  wire [7:0] max1 = MAX[7:0] + 8'd1;

  crc16_byte u_crc (.i_crc(crc_q), .i_byte(data), .o_crc(crc_next));

  // Frame buffer write port.
  always @(posedge i_clk) begin
    if (take && len_q < MAX[7:0]) mem[{bank_q, len_q[AW-1:0]}] <= data;
  end

  // Frame buffer read port.
  always @(posedge i_clk) begin
    o_rd_data <= mem[i_rd_addr[AW:0]];
  end
  wire [7:0] unused_rd_addr = i_rd_addr;

  // Frame state: length, CRC, escape, corruption; the bank flips at a frame's end.
  always @(posedge i_clk) begin
    o_done <= 1'b0;
    if (i_rst) begin
      bank_q <= 1'b0;
      len_q <= 8'd0;
      esc_q <= 1'b0;
      bad_q <= 1'b0;
      crc_q <= CRC_INIT[15:0];
      o_bank <= 1'b0;
      o_len <= 8'd0;
      o_crc_ok <= 1'b0;
      o_bad <= 1'b0;
    end else if (is_end) begin
      if (len_q != 8'd0 || bad_q) begin
        o_done <= ~i_busy;
        o_bank <= bank_q;
        o_len <= len_q;
        o_crc_ok <= crc_q == 16'd0;
        o_bad <= bad_q | esc_q;
        if (!i_busy) bank_q <= ~bank_q;
      end
      len_q <= 8'd0;
      esc_q <= 1'b0;
      bad_q <= 1'b0;
      crc_q <= CRC_INIT[15:0];
    end else if (i_ferr) begin
      bad_q <= 1'b1;
      esc_q <= 1'b0;
    end else if (is_esc) begin
      esc_q <= 1'b1;
    end else if (take) begin
      if (esc_q && !esc_ok) bad_q <= 1'b1;
      esc_q <= 1'b0;
      crc_q <= crc_next;
      if (len_q != max1) len_q <= len_q + 8'd1;
    end
  end

endmodule
