// crc16_byte: one byte of CRC-16/CCITT-FALSE (polynomial 0x1021, MSB
// first, no reflection, no final xor; the register starts at 0xFFFF).
// Combinational. A frame followed by its CRC, high byte first, leaves the
// register at 0: the receiver checks that residue.
`default_nettype none

module crc16_byte (
    input  wire [15:0] i_crc,
    input  wire [7:0]  i_byte,
    output wire [15:0] o_crc
);

  // Eight shifts of the polynomial division, one per data bit.
  function automatic [15:0] step(input [15:0] c, input b);
    step = {c[14:0], 1'b0} ^ ((c[15] ^ b) ? 16'h1021 : 16'h0000);
  endfunction

  wire [15:0] c1 = step(i_crc, i_byte[7]);
  wire [15:0] c2 = step(c1, i_byte[6]);
  wire [15:0] c3 = step(c2, i_byte[5]);
  wire [15:0] c4 = step(c3, i_byte[4]);
  wire [15:0] c5 = step(c4, i_byte[3]);
  wire [15:0] c6 = step(c5, i_byte[2]);
  wire [15:0] c7 = step(c6, i_byte[1]);
  assign o_crc = step(c7, i_byte[0]);

endmodule
