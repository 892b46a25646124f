`default_nettype none
// board8085_ram: a synchronous RAM of 2**AW bytes with one read and one
// write port (an iCE40 block RAM; the read under an enable: a Verilated
// model reads only then): the board's program RAM and each copy of
// the mailbox. The read shows the contents before a write at the same edge.
module board8085_ram #(
    parameter AW = 11  // address width: 11 = 2 KiB
) (
    input  wire          i_clk,
    input  wire          i_we,
    input  wire [AW-1:0] i_waddr,
    input  wire [   7:0] i_wdata,
    input  wire          i_re,     // read enable: o_rdata <= mem[i_raddr]
    input  wire [AW-1:0] i_raddr,
    output reg  [   7:0] o_rdata
);
  reg [7:0] mem[0:(1<<AW)-1];

  // Simulation starts from zeros (the ISS's reset memory); the hardware's
  // block RAM powers up to zeros too.
  integer i;
  initial for (i = 0; i < (1 << AW); i = i + 1) mem[i] = 8'h00;

  always @(posedge i_clk) begin
    if (i_we) mem[i_waddr] <= i_wdata;
    if (i_re) o_rdata <= mem[i_raddr];
  end
endmodule

`default_nettype wire
