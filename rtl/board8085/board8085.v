`default_nettype none
// board8085: the 8085 interpolation board (docs/board8085.md): the cpu8085,
// 8 KiB ROM, 2 KiB RAM, the 256-byte host mailbox and the I/O ports.
//
//   0x0000-0x1FFF  ROM (writes ignored)     0x2000-0x27FF  RAM
//   0x3000-0x30FF  mailbox (host ports)     elsewhere: reads 0xFF, writes ignored
//   I/O: OUT 10h step/dir, IN 11h command edge count, OUT 12h done, OUT 13h debug
//   RST 7.5 = i_cmd (the command pulse). TRAP, RST 6.5/5.5 and INTR are pins;
//   an INTR acknowledge reads i_intr_vec.
//
// One clock = one T-state (3 MHz for the paper's timing). Reset: i_rst,
// synchronous, active high, resets the CPU and the I/O registers; memories
// keep their contents. The o_cpu_* and o_dbg_* outputs expose the CPU's bus
// and retire port for the lockstep testbench.
module board8085 #(
    parameter ROM_FILE = ""  // ROM image ($readmemh); +rom=PATH overrides in simulation
) (
    input  wire        i_clk,
    input  wire        i_rst,
    // command pulse (RST 7.5) and the other interrupt pins
    input  wire        i_cmd,
    input  wire        i_trap, i_rst65, i_rst55, i_intr,
    input  wire [ 7:0] i_intr_vec,   // instruction byte(s) an INTA reads
    // step outputs, one axis each (OUT 10h, docs/board8085.md)
    output wire        o_step_x, o_step_y, o_step_z,  // one-clock strobes
    output wire        o_dir_x, o_dir_y, o_dir_z,     // 1: the negative direction
    output wire [ 7:0] o_done,
    output wire [ 7:0] o_debug,
    output wire        o_debug_we,
    // host mailbox port
    input  wire [ 7:0] i_host_addr,
    input  wire [ 7:0] i_host_wdata,
    input  wire        i_host_we,
    output wire [ 7:0] o_host_rdata,
    output wire        o_host_overrun,
    // CPU bus and retire port, for testbenches
    output wire [15:0] o_cpu_addr,
    output wire [ 7:0] o_cpu_dout,
    output wire        o_cpu_wr, o_cpu_io,  // write strobe (T2); 1: I/O, 0: memory
    output wire        o_retire,
    output wire [ 1:0] o_dbg_kind,
    output wire [ 2:0] o_dbg_irq,
    output wire [15:0] o_dbg_ipc,
    output wire [ 7:0] o_dbg_op,
    output wire [15:0] o_dbg_pc,
    output wire [15:0] o_dbg_sp,
    output wire [63:0] o_dbg_regs,
    output wire        o_halted,
    output wire        o_ie,
    output wire        o_sod
);
  wire [15:0] addr;
  wire [ 7:0] dout;
  reg  [ 7:0] din;
  wire rd, wr, io, inta;
  wire [2:0] cycle, tstate;

  cpu8085 u_cpu (
      .i_clk     (i_clk),
      .i_rst     (i_rst),
      .o_addr    (addr),
      .o_dout    (dout),
      .i_din     (din),
      .o_rd      (rd),
      .o_wr      (wr),
      .o_io      (io),
      .o_inta    (inta),
      .o_cycle   (cycle),
      .o_tstate  (tstate),
      .i_trap    (i_trap),
      .i_rst75   (i_cmd),
      .i_rst65   (i_rst65),
      .i_rst55   (i_rst55),
      .i_intr    (i_intr),
      .i_sid     (1'b0),
      .o_sod     (o_sod),
      .o_halted  (o_halted),
      .o_ie      (o_ie),
      .o_retire  (o_retire),
      .o_dbg_kind(o_dbg_kind),
      .o_dbg_irq (o_dbg_irq),
      .o_dbg_ipc (o_dbg_ipc),
      .o_dbg_op  (o_dbg_op),
      .o_dbg_pc  (o_dbg_pc),
      .o_dbg_sp  (o_dbg_sp),
      .o_dbg_regs(o_dbg_regs),
      .i_dbg_load(1'b0),
      .i_dbg_pc  (16'h0000),
      .i_dbg_sp  (16'h0000),
      .i_dbg_regs(64'h0)
  );

  // Address decode.
  wire sel_rom = (addr[15:13] == 3'b000);
  wire sel_ram = (addr[15:11] == 5'b00100);
  wire sel_mbx = (addr[15:8] == 8'h30);
  wire mem_wr = wr && !io;

  wire [7:0] rom_q, ram_q, mbx_q, io_q;

  board8085_rom #(
      .ROM_FILE(ROM_FILE)
  ) u_rom (
      .i_clk (i_clk),
      .i_re  (rd),
      .i_addr(addr[12:0]),
      .o_data(rom_q)
  );

  board8085_ram #(
      .AW(11)
  ) u_ram (
      .i_clk  (i_clk),
      .i_we   (mem_wr && sel_ram),
      .i_waddr(addr[10:0]),
      .i_wdata(dout),
      .i_re   (rd),
      .i_raddr(addr[10:0]),
      .o_rdata(ram_q)
  );

  board8085_mailbox u_mbx (
      .i_clk       (i_clk),
      .i_rst       (i_rst),
      .i_cpu_we    (mem_wr && sel_mbx),
      .i_cpu_re    (rd),
      .i_cpu_addr  (addr[7:0]),
      .i_cpu_wdata (dout),
      .o_cpu_rdata (mbx_q),
      .i_host_we   (i_host_we),
      .i_host_addr (i_host_addr),
      .i_host_wdata(i_host_wdata),
      .o_host_rdata(o_host_rdata),
      .o_overrun   (o_host_overrun)
  );

  board8085_io u_io (
      .i_clk     (i_clk),
      .i_rst     (i_rst),
      .i_we      (wr && io),
      .i_port    (addr[7:0]),
      .i_wdata   (dout),
      .o_rdata   (io_q),
      .i_cmd     (i_cmd),
      .o_step_x  (o_step_x),
      .o_step_y  (o_step_y),
      .o_step_z  (o_step_z),
      .o_dir_x   (o_dir_x),
      .o_dir_y   (o_dir_y),
      .o_dir_z   (o_dir_z),
      .o_done    (o_done),
      .o_debug   (o_debug),
      .o_debug_we(o_debug_we)
  );

  // Read data: the memories register at the end of T2 (rd strobe); which
  // one answers is registered at the same edge, as are the I/O and INTA
  // bytes. The CPU samples din at the end of T3.
  localparam [2:0] S_ROM = 3'd0, S_RAM = 3'd1, S_MBX = 3'd2, S_REG = 3'd3, S_NONE = 3'd4;
  reg [2:0] src_q;
  reg [7:0] reg_q;  // I/O or INTA byte
  always @(posedge i_clk) begin
    if (i_rst) begin
      src_q <= S_NONE;
      reg_q <= 8'hFF;
    end else if (rd || inta) begin
      if (inta) begin
        src_q <= S_REG;
        reg_q <= i_intr_vec;
      end else if (io) begin
        src_q <= S_REG;
        reg_q <= io_q;
      end else if (sel_rom) src_q <= S_ROM;
      else if (sel_ram) src_q <= S_RAM;
      else if (sel_mbx) src_q <= S_MBX;
      else src_q <= S_NONE;
    end
  end
  always @* begin
    case (src_q)
      S_ROM: din = rom_q;
      S_RAM: din = ram_q;
      S_MBX: din = mbx_q;
      S_REG: din = reg_q;
      default: din = 8'hFF;
    endcase
  end

  assign o_cpu_addr = addr;
  assign o_cpu_dout = dout;
  assign o_cpu_wr = wr;
  assign o_cpu_io = io;

  // The machine cycle type and T-state are for waveforms only.
  wire [5:0] unused_cpu = {cycle, tstate};
endmodule

`default_nettype wire
