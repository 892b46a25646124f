`default_nettype none
`timescale 1ns / 1ps
// board_tb: an Icarus Verilog run of the board (rtl/board8085) on the board
// test program (programs/board_test.a80, ROM image by +rom=PATH): the host
// writes a move of 3 pulses (X+ and Y-) in the mailbox, three command
// pulses come on i_cmd, and the step outputs, the done register and the
// mailbox status must show it. Prints PASS or FAIL lines; ends with $finish.
module board_tb;
  reg clk = 1'b0;
  reg rst = 1'b1;
  reg cmd = 1'b0;
  reg [7:0] host_addr = 8'h00, host_wdata = 8'h00;
  reg host_we = 1'b0;
  wire [7:0] host_rdata;
  wire step_x, step_y, step_z, dir_x, dir_y, dir_z;
  wire [7:0] done, debug;

  board8085 u_board (
      .i_clk(clk), .i_rst(rst),
      .i_cmd(cmd), .i_trap(1'b0), .i_rst65(1'b0), .i_rst55(1'b0), .i_intr(1'b0), .i_intr_vec(8'hFF),
      .o_step_x(step_x), .o_step_y(step_y), .o_step_z(step_z),
      .o_dir_x(dir_x), .o_dir_y(dir_y), .o_dir_z(dir_z),
      .o_done(done), .o_debug(debug), .o_debug_we(),
      .i_host_addr(host_addr), .i_host_wdata(host_wdata), .i_host_we(host_we),
      .o_host_rdata(host_rdata), .o_host_overrun(),
      .o_cpu_addr(), .o_cpu_dout(), .o_cpu_wr(), .o_cpu_io(), .o_retire(),
      .o_dbg_kind(), .o_dbg_irq(), .o_dbg_ipc(), .o_dbg_op(), .o_dbg_pc(), .o_dbg_sp(),
      .o_dbg_regs(), .o_halted(), .o_ie(), .o_sod()
  );

  always #5 clk = ~clk;

  integer xs = 0, ys_neg = 0, others = 0, failures = 0, i;
  always @(posedge clk) begin
    if (step_x && !dir_x) xs = xs + 1;
    if (step_y && dir_y) ys_neg = ys_neg + 1;
    if ((step_x && dir_x) || (step_y && !dir_y) || step_z) others = others + 1;
  end

  task host_write(input [7:0] a, input [7:0] d);
    begin
      @(negedge clk);
      host_addr = a;
      host_wdata = d;
      host_we = 1'b1;
      @(negedge clk);
      host_we = 1'b0;
      @(negedge clk);
    end
  endtask

  task expect(input [8*24-1:0] what, input integer got, input integer want);
    begin
      if (got !== want) begin
        $display("FAIL %0s: %0d, expected %0d", what, got, want);
        failures = failures + 1;
      end
    end
  endtask

  initial begin
    repeat (2) @(negedge clk);
    rst = 1'b0;
    host_write(8'h00, 8'h0D);  // X step, Y step, Y negative
    host_write(8'h01, 8'd3);   // three pulses
    repeat (400) @(negedge clk);
    for (i = 0; i < 3; i = i + 1) begin
      cmd = 1'b1;
      @(negedge clk);
      cmd = 1'b0;
      repeat (400) @(negedge clk);
    end
    host_addr = 8'h80;  // STATUS
    @(negedge clk);
    @(negedge clk);
    expect("mailbox STATUS", host_rdata, 3);
    host_addr = 8'h81;  // EDGES
    @(negedge clk);
    @(negedge clk);
    expect("mailbox EDGES", host_rdata, 3);
    expect("X+ steps", xs, 3);
    expect("Y- steps", ys_neg, 3);
    expect("other steps", others, 0);
    expect("done register", done, 1);
    expect("debug byte", debug, 3);
    if (failures == 0) $display("PASS board_tb");
    $finish;
  end
endmodule

`default_nettype wire
