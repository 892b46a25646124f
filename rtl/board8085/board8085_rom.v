`default_nettype none
// board8085_rom: the board's 8 KiB program ROM, one synchronous read port
// (an iCE40 block RAM), initialised by $readmemh.
//
// Contents: the file named by the plusarg +rom=PATH in simulation (Verilator,
// Icarus), otherwise ROM_FILE; with neither, every byte reads 0xFF (an erased
// EPROM). The file is one byte per line in hex, 8192 lines, as written by
// rtl/board8085/hex2memh from the asm80 Intel HEX.
module board8085_rom #(
    parameter ROM_FILE = ""  // $readmemh file for synthesis ("" = erased)
) (
    input  wire        i_clk,
    input  wire        i_re,    // read enable
    input  wire [12:0] i_addr,
    output reg  [ 7:0] o_data  // mem[i_addr] at the last clock edge with i_re
);
  reg [7:0] mem[0:8191];

  integer i;
`ifndef SYNTHESIS
  reg [8*512-1:0] path;
`endif
  initial begin
    for (i = 0; i < 8192; i = i + 1) mem[i] = 8'hFF;
`ifndef SYNTHESIS
    if ($value$plusargs("rom=%s", path)) $readmemh(path, mem);
    else
`endif
    if (ROM_FILE != "") $readmemh(ROM_FILE, mem);
  end

  always @(posedge i_clk) if (i_re) o_data <= mem[i_addr];
endmodule

`default_nettype wire
