`default_nettype none
// board8085_mailbox: the 256-byte window shared by the CPU (0x3000-0x30FF)
// and the host, both reading and writing while the CPU runs.
//
// Two copies (one iCE40 block RAM each) receive every write, so that each
// side has a read port of its own: a read answers one clock later, always.
// The copies' single write port is shared: a CPU write has priority, a host
// write that collides with it waits in a one-deep buffer and is applied on
// the next clock without a CPU write (the CPU never writes on two
// consecutive clocks: a write cycle is 3 T-states). A host write that finds
// the buffer full while the CPU writes again is lost and sets the sticky
// o_overrun: a host that does not write on every clock never sees it.
module board8085_mailbox (
    input  wire       i_clk,
    input  wire       i_rst,
    // CPU side
    input  wire       i_cpu_we,
    input  wire       i_cpu_re,    // the CPU reads (o_cpu_rdata at the next clock)
    input  wire [7:0] i_cpu_addr, i_cpu_wdata,
    output wire [7:0] o_cpu_rdata,
    // host side
    input  wire       i_host_we,
    input  wire [7:0] i_host_addr, i_host_wdata,
    output wire [7:0] o_host_rdata,
    output reg        o_overrun    // a host write was lost (sticky until reset)
);
  // The host write waiting behind a CPU write.
  reg       pend_q;
  reg [7:0] pend_addr_q, pend_data_q;

  wire       we = i_cpu_we | pend_q | i_host_we;
  wire [7:0] waddr = i_cpu_we ? i_cpu_addr : pend_q ? pend_addr_q : i_host_addr;
  wire [7:0] wdata = i_cpu_we ? i_cpu_wdata : pend_q ? pend_data_q : i_host_wdata;

  always @(posedge i_clk) begin
    if (i_rst) begin
      pend_q <= 1'b0;
      pend_addr_q <= 8'h00;
      pend_data_q <= 8'h00;
      o_overrun <= 1'b0;
    end else if (i_cpu_we) begin
      if (i_host_we) begin
        if (pend_q) begin
          o_overrun <= 1'b1;
        end else begin
          pend_q <= 1'b1;
          pend_addr_q <= i_host_addr;
          pend_data_q <= i_host_wdata;
        end
      end
    end else if (pend_q) begin
      // The pending write goes in now; a new host write takes its place.
      pend_q <= i_host_we;
      pend_addr_q <= i_host_addr;
      pend_data_q <= i_host_wdata;
    end
  end

  board8085_ram #(
      .AW(8)
  ) u_cpu_copy (
      .i_clk  (i_clk),
      .i_we   (we),
      .i_waddr(waddr),
      .i_wdata(wdata),
      .i_re   (i_cpu_re),
      .i_raddr(i_cpu_addr),
      .o_rdata(o_cpu_rdata)
  );

  board8085_ram #(
      .AW(8)
  ) u_host_copy (
      .i_clk  (i_clk),
      .i_we   (we),
      .i_waddr(waddr),
      .i_wdata(wdata),
      .i_re   (1'b1),
      .i_raddr(i_host_addr),
      .o_rdata(o_host_rdata)
  );
endmodule

`default_nettype wire
