// timing_wrap: registered I/O around a design, so that nextpnr's Fmax is
// register to register (in the spirit of PicoRV32's timing wrapper) and
// the design fits any package: every input of the design comes from a
// serial-in shift register, every output goes into a parallel-load
// shift register read out on one pin. Nothing of the design is trimmed but
// the debug outputs a design has for simulation only.
//
// The one timing wrapper of `make synth`; the design is selected by a define:
//   DESIGN_TOP        interp_top: core, output stage, feed generator,
//                     position counters, Wishbone registers (the peripheral)
//   DESIGN_CORE       interp_core (block prep, queue, datapath) + step_out
//                     (with CMD_HIGH: the core's command tied high, the
//                     analysis design core_free of designs.mk)
//   DESIGN_DP         the datapath interp_dp alone
//   DESIGN_INTERP3    the 3-axis core interp3_core, state outputs included
//   DESIGN_DLOOP      the step loop prototype rtl/proto/dloop (docs/rtl-proto.md)
//   DESIGN_DLOOP_NOD  the same without its D output (trimmed, as a core's
//                     state outputs are): the loop's own cost
//   DESIGN_DLOOP1, DESIGN_DLOOP1_NOD  the same for dloop1 (one step ahead)
//   DESIGN_DLOOP1L, DESIGN_DLOOP1L_NOD  the same for dloop1l (one-clock load)
//   DESIGN_DLOOP1X, DESIGN_DLOOP1X_NOD  the same for dloop1x (and crossings)
//   DESIGN_CPU8085    the 8085 CPU: bus, interrupt pins, retire strobe
//   DESIGN_BOARD8085  the whole board8085, ROM from ROM_FILE
// Each design sets NI (inputs, reset on top) and NO (outputs).
`default_nettype none

`ifdef DESIGN_DLOOP_NOD
`define DESIGN_DLOOP
`define DLOOP_NO_D
`endif
`ifdef DESIGN_DLOOP1_NOD
`define DESIGN_DLOOP1
`define DLOOP_NO_D
`endif
`ifdef DESIGN_DLOOP1L_NOD
`define DESIGN_DLOOP1L
`define DLOOP_NO_D
`endif
`ifdef DESIGN_DLOOP1X_NOD
`define DESIGN_DLOOP1X
`define DLOOP_NO_D
`endif
`ifdef DESIGN_DLOOP1
`define DESIGN_DLOOP
`define DLOOP_MODULE dloop1
`elsif DESIGN_DLOOP
`define DLOOP_MODULE dloop
`endif

module timing_wrap (
    input  wire i_clk_pin,
    input  wire i_ser,    // serial input
    input  wire i_load,   // load the output shift register
    output wire o_ser     // serial output
);

  // W: the coordinate width of the interpolator designs.
`ifdef DESIGN_DP
  localparam integer W = 24;
`include "interp_block.vh"
  // cmd, valid, the prepared block from bit 2, reset on top.
  localparam integer NI = 3 + PRE_BITS;
  localparam integer NO = 16 + 3 * W;
`elsif DESIGN_CORE
  localparam integer W = 24;
`include "interp_block.vh"
  // abort, push, the block from bit 2 (up to 10 + 4W), clear, the command's
  // next value, the command (the bit after it in the shift register: the
  // same bit a clock later, as cmd_gen's o_cmd_next and o_cmd), 2 bits
  // unused, the four TW-bit step timings from 16 + 4W, reset on top.
  localparam integer TW = 12;  // step timing width, as interp_top's
  localparam integer NI = 16 + 4 * W + 4 * TW + 1;
  localparam integer NO = 33;
`elsif DESIGN_TOP
  localparam integer W = 24;
  localparam integer NI = 45;  // Wishbone in, the pin, reset on top
  localparam integer NO = 41;
`elsif DESIGN_INTERP3
  localparam integer W = 24;
  localparam integer NI = 3 * W + 6;  // ends, signs, load, cmd, reset
  localparam integer NO = 8 + 3 * W + 3 * (W + 2);  // the state, then o_ready
`elsif DESIGN_DLOOP
  localparam integer W = 24;
  localparam integer NI = 2 * (W + 1) + 4;  // load, cmd, arc, SUB, ADD, reset
`ifdef DLOOP_NO_D
  localparam integer NO = 3;                // ready, pulse, g
`else
  localparam integer NO = 3 + W + 2;        // ready, pulse, g, D
`endif
`elsif DESIGN_DLOOP1L
  localparam integer W = 24;
  localparam integer NI = 5 * (W + 2) + 4;  // load, cmd, arc, the block, reset
`ifdef DLOOP_NO_D
  localparam integer NO = 3;                // ready, pulse, g
`else
  localparam integer NO = 3 + W + 2;        // ready, pulse, g, D
`endif
`elsif DESIGN_DLOOP1X
  localparam integer W = 24;
  localparam integer NI = 6 * (W + 2) + 4;  // load, cmd, arc, the block, reset
`ifdef DLOOP_NO_D
  localparam integer NO = 4;                // ready, pulse, g, cross
`else
  localparam integer NO = 4 + W + 2;        // ready, pulse, g, cross, D
`endif
`elsif DESIGN_CPU8085
  localparam integer NI = 15;
  localparam integer NO = 38;
`elsif DESIGN_BOARD8085
  // ROM image, relative to where yosys runs (rtl/synth)
  localparam ROM_FILE = "../board8085/synth/board_test.memh";
  localparam integer NI = 31;
  localparam integer NO = 32;
`else
  // No design selected: elaboration stops here.
  localparam integer NI = 0;
  localparam integer NO = 0;
  initial begin
    $display("timing_wrap: define one of DESIGN_TOP, DESIGN_CORE, DESIGN_DP, DESIGN_INTERP3, DESIGN_DLOOP, DESIGN_CPU8085, DESIGN_BOARD8085");
    $finish;
  end
`endif

  // The clock on a global buffer, explicitly: nextpnr runs with
  // --no-promote-globals so that it does not move high-fanout enables onto
  // the few global nets (their long entry delay would set Fmax).
  wire i_clk;
`ifdef SYNTHESIS
  SB_GB u_clk_gb (.USER_SIGNAL_TO_GLOBAL_BUFFER(i_clk_pin), .GLOBAL_BUFFER_OUTPUT(i_clk));
`else
  assign i_clk = i_clk_pin;
`endif

  reg [NI-1:0] in_q;
  reg [NO-1:0] out_q;
  wire [NO-1:0] outs;

  always @(posedge i_clk) in_q <= {in_q[NI-2:0], i_ser};

  always @(posedge i_clk) begin
    if (i_load) out_q <= outs;
    else out_q <= {1'b0, out_q[NO-1:1]};
  end
  assign o_ser = out_q[0];

  // Reset from the input register too, so it is a register output.
  wire rst = in_q[NI-1];

`ifdef DESIGN_DP
  interp_dp #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(rst), .i_cmd(in_q[0]), .i_valid(in_q[1]), .o_ready(outs[0]),
      .i_pre(in_q[2 +: PRE_BITS]),
      .o_pulse(outs[1]), .o_pulse_y(outs[2]), .o_pulse_neg(outs[3]), .o_pulse_last(outs[4]),
      .o_busy(outs[5]), .o_xmag(outs[6 +: W]), .o_xneg(outs[6 + W]), .o_ymag(outs[7 + W +: W]),
      .o_yneg(outs[7 + 2 * W]), .o_d(outs[8 + 2 * W +: W + 2]), .o_q(outs[10 + 3 * W +: 2]),
      .o_k(outs[12 + 3 * W +: 3]), .o_arc(outs[15 + 3 * W])
  );
`elsif DESIGN_CORE
  wire cmd_core, busy, pulse, pulse_y, pulse_neg;
  // The state outputs are for test benches; timing is of the rest.
  interp_core #(.W(W), .QAW(4)) u_core (
      .i_clk(i_clk), .i_rst(rst), .i_abort(in_q[0]),
`ifdef CMD_HIGH
      .i_cmd(1'b1),  // analysis design core_free: the command held high
`else
      .i_cmd(cmd_core),
`endif
      .i_push(in_q[1]), .i_blk(in_q[2 +: BLK_BITS]),
      .o_full(outs[4]), .o_level(outs[10:5]),
      .o_pulse(pulse), .o_pulse_y(pulse_y), .o_pulse_neg(pulse_neg), .o_pulse_last(outs[11]),
      .o_busy(busy), .o_xmag(), .o_xneg(), .o_ymag(), .o_yneg(), .o_d(), .o_q(), .o_k(), .o_arc()
  );
  step_out #(.TW(TW), .OW(16)) u_out (
      .i_clk(i_clk), .i_rst(rst), .i_clear(in_q[2 + BLK_BITS]),
      .i_len(in_q[16 + 4 * W +: TW]), .i_space(in_q[16 + 4 * W + TW +: TW]),
      .i_setup(in_q[16 + 4 * W + 2 * TW +: TW]), .i_hold(in_q[16 + 4 * W + 3 * TW +: TW]),
      .i_cmd(in_q[4 + BLK_BITS]), .i_cmd_next(in_q[3 + BLK_BITS]), .i_busy(busy), .o_cmd(cmd_core),
      .i_pulse(pulse), .i_pulse_y(pulse_y), .i_pulse_neg(pulse_neg),
      .o_step_x(outs[0]), .o_dir_x(outs[1]), .o_step_y(outs[2]), .o_dir_y(outs[3]),
      .o_overrun(outs[12]), .o_ovr_count(outs[28:13])
  );
  assign outs[31:29] = {pulse, pulse_y, pulse_neg};
  assign outs[32] = busy;
`ifdef CMD_HIGH
  wire unused_cmd = cmd_core;  // core_free: the core's command is tied high
`endif
`elsif DESIGN_TOP
  interp_top #(.W(W), .QAW(4)) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_wb_cyc(in_q[0]), .i_wb_stb(in_q[1]), .i_wb_we(in_q[2]), .i_wb_adr(in_q[10:3]),
      .i_wb_dat(in_q[42:11]), .o_wb_dat(outs[31:0]), .o_wb_ack(outs[32]),
      .i_cmd_pin(in_q[43]), .i_cmd_ce(1'b1),
      .o_step_x(outs[33]), .o_dir_x(outs[34]), .o_step_y(outs[35]), .o_dir_y(outs[36]),
      .o_pulse(outs[37]), .o_pulse_y(outs[38]), .o_pulse_neg(outs[39]), .o_busy(outs[40])
  );
`elsif DESIGN_INTERP3
  interp3_core #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_load(in_q[0]), .i_cmd(in_q[1]),
      .i_xneg(in_q[2]), .i_yneg(in_q[3]), .i_zneg(in_q[4]),
      .i_xe(in_q[5 +: W]), .i_ye(in_q[5 + W +: W]), .i_ze(in_q[5 + 2 * W +: W]),
      .o_step_x(outs[0]), .o_step_y(outs[1]), .o_step_z(outs[2]),
      .o_dir_x(outs[3]), .o_dir_y(outs[4]), .o_dir_z(outs[5]), .o_done(outs[6]),
      .o_x(outs[7 +: W]), .o_y(outs[7 + W +: W]), .o_z(outs[7 + 2 * W +: W]),
      .o_exy(outs[7 + 3 * W +: W + 2]), .o_exz(outs[9 + 4 * W +: W + 2]),
      .o_eyz(outs[11 + 5 * W +: W + 2]), .o_ready(outs[13 + 6 * W])
  );
`elsif DESIGN_DLOOP
  `DLOOP_MODULE #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_load(in_q[0]), .i_cmd(in_q[1]), .i_arc(in_q[2]),
      .i_sub(in_q[3 +: W + 1]), .i_add(in_q[4 + W +: W + 1]),
`ifdef DLOOP_NO_D
      .o_ready(outs[0]), .o_pulse(outs[1]), .o_g(outs[2]), .o_d()
`else
      .o_ready(outs[0]), .o_pulse(outs[1]), .o_g(outs[2]), .o_d(outs[3 +: W + 2])
`endif
  );
`elsif DESIGN_DLOOP1L
  dloop1l #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_load(in_q[0]), .i_cmd(in_q[1]), .i_arc(in_q[2]),
      .i_s2(in_q[3 +: W + 2]), .i_a0(in_q[5 + W +: W + 2]),
      .i_f1(in_q[7 + 2 * W +: W + 2]), .i_f2(in_q[9 + 3 * W +: W + 2]), .i_f3(in_q[11 + 4 * W +: W + 2]),
`ifdef DLOOP_NO_D
      .o_ready(outs[0]), .o_pulse(outs[1]), .o_g(outs[2]), .o_d()
`else
      .o_ready(outs[0]), .o_pulse(outs[1]), .o_g(outs[2]), .o_d(outs[3 +: W + 2])
`endif
  );
`elsif DESIGN_DLOOP1X
  dloop1x #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(rst),
      .i_load(in_q[0]), .i_cmd(in_q[1]), .i_arc(in_q[2]),
      .i_s2(in_q[3 +: W + 2]), .i_a0(in_q[5 + W +: W + 2]), .i_r(in_q[7 + 2 * W +: W + 2]),
      .i_f1(in_q[9 + 3 * W +: W + 2]), .i_f2(in_q[11 + 4 * W +: W + 2]), .i_f3(in_q[13 + 5 * W +: W + 2]),
      .o_ready(outs[0]), .o_pulse(outs[1]), .o_g(outs[2]), .o_cross(outs[3]),
`ifdef DLOOP_NO_D
      .o_d()
`else
      .o_d(outs[4 +: W + 2])
`endif
  );
`elsif DESIGN_CPU8085
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
`elsif DESIGN_BOARD8085
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
`endif

endmodule
