`default_nettype none
// cpu8085_wrap: registered I/O around the CPU or the board for `make synth`,
// so that nextpnr's Fmax is register to register and the design fits any
// package (the same scheme as rtl/synth/timing_wrap.v): every input comes
// from a serial-in shift register, every output goes into a parallel-load
// shift register read out on one pin.
//
// Default: the CPU alone, with its bus, interrupt pins and retire strobe
// (the other debug outputs are for simulation and are left open, so their
// registers are trimmed). With DESIGN_BOARD: the whole board8085, ROM
// initialised from ROM_FILE.
module cpu8085_wrap (
    input  wire i_clk,
    input  wire i_ser,   // serial input
    input  wire i_load,  // load the output shift register
    output wire o_ser    // serial output
);
`ifdef DESIGN_BOARD
  // ROM image, relative to where yosys runs (rtl/synth)
  localparam ROM_FILE = "../board8085/synth/board_test.memh";
  localparam integer NI = 31;  // reset on top
  localparam integer NO = 32;
`else
  localparam integer NI = 15;
  localparam integer NO = 38;
`endif

  reg  [NI-1:0] in_q;
  reg  [NO-1:0] out_q;
  wire [NO-1:0] outs;

  always @(posedge i_clk) in_q <= {in_q[NI-2:0], i_ser};

  always @(posedge i_clk) begin
    if (i_load) out_q <= outs;
    else out_q <= {1'b0, out_q[NO-1:1]};
  end
  assign o_ser = out_q[0];

  wire rst = in_q[NI-1];

  // The debug outputs are left open on purpose: synthesis trims what only
  // they use.
  /* verilator lint_off PINCONNECTEMPTY */
`ifdef DESIGN_BOARD
  board8085 #(
      .ROM_FILE(ROM_FILE)
  ) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_cmd(in_q[0]), .i_trap(in_q[1]), .i_rst65(in_q[2]), .i_rst55(in_q[3]), .i_intr(in_q[4]),
      .i_intr_vec(in_q[12:5]),
      .o_step_x(outs[0]), .o_step_y(outs[1]), .o_step_z(outs[2]),
      .o_dir_x(outs[3]), .o_dir_y(outs[4]), .o_dir_z(outs[5]),
      .o_done(outs[13:6]), .o_debug(outs[21:14]), .o_debug_we(outs[22]),
      .i_host_addr(in_q[20:13]), .i_host_wdata(in_q[28:21]), .i_host_we(in_q[29]),
      .o_host_rdata(outs[30:23]), .o_host_overrun(outs[31]),
      .o_cpu_addr(), .o_cpu_dout(), .o_cpu_wr(), .o_cpu_io(), .o_retire(),
      .o_dbg_kind(), .o_dbg_irq(), .o_dbg_ipc(), .o_dbg_op(), .o_dbg_pc(), .o_dbg_sp(),
      .o_dbg_regs(), .o_halted(), .o_ie(), .o_sod()
  );
`else
  cpu8085 u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .o_addr(outs[15:0]), .o_dout(outs[23:16]), .i_din(in_q[7:0]),
      .o_rd(outs[24]), .o_wr(outs[25]), .o_io(outs[26]), .o_inta(outs[27]),
      .o_cycle(outs[30:28]), .o_tstate(outs[33:31]),
      .i_trap(in_q[8]), .i_rst75(in_q[9]), .i_rst65(in_q[10]), .i_rst55(in_q[11]),
      .i_intr(in_q[12]), .i_sid(in_q[13]),
      .o_sod(outs[34]), .o_halted(outs[35]), .o_ie(outs[36]), .o_retire(outs[37]),
      .o_dbg_kind(), .o_dbg_irq(), .o_dbg_ipc(), .o_dbg_op(), .o_dbg_pc(), .o_dbg_sp(),
      .o_dbg_regs(),
      .i_dbg_load(1'b0), .i_dbg_pc(16'h0000), .i_dbg_sp(16'h0000), .i_dbg_regs(64'h0)
  );
`endif
  /* verilator lint_on PINCONNECTEMPTY */
endmodule

`default_nettype wire
