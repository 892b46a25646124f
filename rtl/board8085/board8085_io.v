`default_nettype none
// board8085_io: the board's I/O ports (docs/board8085.md).
//   OUT 10h  step/dir: bit0 X step, bit1 X dir, bit2 Y step, bit3 Y dir,
//            bit4 Z step, bit5 Z dir (dir 1 = negative). Every write latches
//            the three dir bits; each step bit written as 1 is one step pulse:
//            o_step_* high for the one clock after the write strobe, with the
//            new o_dir_* already valid.
//   IN  11h  number of rising edges of i_cmd seen (8 bits, wraps at 256)
//   OUT 12h  "done / irq to host" register (o_done, bit0: move done)
//   OUT 13h  debug byte (o_debug) with a one-clock o_debug_we strobe
//   other ports read 0xFF; writes to them are ignored.
// i_cmd must be synchronous to i_clk (it also drives RST 7.5 directly, so
// that the CPU and the counter see the same edge at the same clock).
module board8085_io (
    input  wire       i_clk,
    input  wire       i_rst,
    // CPU I/O write (the T2 strobe) and read address
    input  wire       i_we,
    input  wire [7:0] i_port, i_wdata,
    output reg  [7:0] o_rdata,   // combinational: value of port i_port
    // command pulses
    input  wire       i_cmd,
    // outputs
    output reg        o_step_x, o_step_y, o_step_z,  // one-clock strobes
    output reg        o_dir_x, o_dir_y, o_dir_z,     // 1: the negative direction
    output reg  [7:0] o_done,
    output reg  [7:0] o_debug,
    output reg        o_debug_we
);
  localparam [7:0] PORT_STEP = 8'h10, PORT_CMDCNT = 8'h11, PORT_DONE = 8'h12, PORT_DEBUG = 8'h13;

  reg       cmd_prev_q;
  reg [7:0] cmd_count_q;

  wire step_we = i_we && (i_port == PORT_STEP);

  // Step strobes and latched directions.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_step_x <= 1'b0;
      o_step_y <= 1'b0;
      o_step_z <= 1'b0;
      o_dir_x <= 1'b0;
      o_dir_y <= 1'b0;
      o_dir_z <= 1'b0;
    end else begin
      o_step_x <= step_we & i_wdata[0];
      o_step_y <= step_we & i_wdata[2];
      o_step_z <= step_we & i_wdata[4];
      if (step_we) begin
        o_dir_x <= i_wdata[1];
        o_dir_y <= i_wdata[3];
        o_dir_z <= i_wdata[5];
      end
    end
  end

  // Rising edges of i_cmd.
  always @(posedge i_clk) begin
    if (i_rst) begin
      cmd_prev_q <= 1'b0;
      cmd_count_q <= 8'h00;
    end else if (i_cmd != cmd_prev_q) begin  // the pin changes
      cmd_prev_q <= i_cmd;
      if (i_cmd) cmd_count_q <= cmd_count_q + 8'd1;
    end
  end

  // Done and debug registers.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_done <= 8'h00;
      o_debug <= 8'h00;
      o_debug_we <= 1'b0;
    end else begin
      if (i_we && i_port == PORT_DONE) o_done <= i_wdata;
      o_debug_we <= i_we && (i_port == PORT_DEBUG);
      if (i_we && i_port == PORT_DEBUG) o_debug <= i_wdata;
    end
  end

  always @* begin
    o_rdata = 8'hFF;
    if (i_port == PORT_CMDCNT) o_rdata = cmd_count_q;
  end
endmodule

`default_nettype wire
