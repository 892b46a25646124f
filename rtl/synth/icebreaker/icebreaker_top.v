// icebreaker_top: the interpolator on an iCEBreaker (iCE40UP5K, 12 MHz).
//
// A small Wishbone master plays a fixed program into interp_top after
// reset: step timing (2 us step, 2 us space, 1 us dir setup and hold),
// feed generator at 1000 command pulses per second, then a full circle of
// R = 1000 and two lines, queued, and again whenever the core is idle.
// STEP/DIR of X and Y are on PMOD 1A (pins 1-4), the green LED shows
// "moving", the red LED the X direction. BTN_N resets.
`default_nettype none

module icebreaker_top (
    input  wire CLK,     // 12 MHz
    input  wire BTN_N,   // reset, active low
    output wire LEDR_N,
    output wire LEDG_N,
    output wire P1A1,    // STEP X
    output wire P1A2,    // DIR X
    output wire P1A3,    // STEP Y
    output wire P1A4     // DIR Y
);

`include "interp_regs.vh"

  // Power-on and button reset, synchronous.
  reg [3:0] por_q = 4'd0;
  reg [1:0] btn_q = 2'b00;
  always @(posedge CLK) begin
    btn_q <= {btn_q[0], BTN_N};
    if (!btn_q[1]) por_q <= 4'd0;
    else if (por_q != 4'hF) por_q <= por_q + 1'b1;
  end
  wire rst = (por_q != 4'hF);

  // The program: (address, data) pairs 0..LAST. Entries from LOOP on are replayed
  // whenever the core is idle.
  localparam [4:0] LAST = 5'd19;  // the last entry
  localparam integer LOOP = 6;
  reg [7:0] adr;
  reg [31:0] dat;
  reg [4:0] pc_q;
  always @(*) begin
    case (pc_q)
      5'd0: begin adr = A_STEP_LEN; dat = 32'd24; end
      5'd1: begin adr = A_STEP_SPACE; dat = 32'd24; end
      5'd2: begin adr = A_DIR_SETUP; dat = 32'd12; end
      5'd3: begin adr = A_DIR_HOLD; dat = 32'd12; end
      5'd4: begin adr = A_FEED; dat = 32'd357914; end  // 1000 Hz at 12 MHz
      5'd5: begin adr = A_CTRL; dat = 32'd2 << CTRL_SRC; end
      // Full circle, R = 1000, CCW from (1000, 0): Q1, 4 crossings.
      5'd6: begin adr = A_BLK_MODE; dat = (32'd1 << BLK_MODE_ARC) | (32'd4 << BLK_MODE_K); end
      5'd7: begin adr = A_BLK_CI; dat = 32'd1000; end
      5'd8: begin adr = A_BLK_CO; dat = 32'd0; end
      5'd9: begin adr = A_BLK_TI; dat = 32'd1000; end
      5'd10: begin adr = A_BLK_TO; dat = 32'd0; end
      5'd11: begin adr = A_PUSH; dat = 32'd1; end
      // Line (-1000, +1000), then (+1000, -1000): back to the start.
      5'd12: begin adr = A_BLK_MODE; dat = 32'd1 << BLK_MODE_SXN; end
      5'd13: begin adr = A_BLK_TI; dat = 32'd1000; end
      5'd14: begin adr = A_BLK_TO; dat = 32'd1000; end
      5'd15: begin adr = A_PUSH; dat = 32'd1; end
      5'd16: begin adr = A_BLK_MODE; dat = 32'd1 << BLK_MODE_SYN; end
      5'd17: begin adr = A_BLK_TI; dat = 32'd1000; end
      5'd18: begin adr = A_BLK_TO; dat = 32'd1000; end
      default: begin adr = A_PUSH; dat = 32'd1; end
    endcase
  end

  // Wishbone master: one write per entry; after the last, wait for the
  // core to start and to go idle again, then replay from LOOP.
  reg stb_q, wait_q, seen_busy_q;
  wire ack, busy;
  wire [31:0] unused_rdat;
  always @(posedge CLK) begin
    if (rst) begin
      pc_q <= 5'd0;
      stb_q <= 1'b0;
      wait_q <= 1'b0;
      seen_busy_q <= 1'b0;
    end else if (wait_q) begin
      if (busy) seen_busy_q <= 1'b1;
      else if (seen_busy_q) begin
        wait_q <= 1'b0;
        seen_busy_q <= 1'b0;
        pc_q <= LOOP[4:0];
      end
    end else if (stb_q) begin
      if (ack) begin
        stb_q <= 1'b0;
        if (pc_q == LAST) wait_q <= 1'b1;
        else pc_q <= pc_q + 1'b1;
      end
    end else begin
      stb_q <= 1'b1;
    end
  end

  wire step_x, dir_x, step_y, dir_y;
  wire unused_pulse, unused_pulse_y, unused_pulse_neg;

  interp_top #(.W(24), .QAW(4)) u_interp (
      .i_clk(CLK), .i_rst(rst),
      .i_wb_cyc(stb_q), .i_wb_stb(stb_q), .i_wb_we(1'b1), .i_wb_adr(adr), .i_wb_dat(dat),
      .o_wb_dat(unused_rdat), .o_wb_ack(ack),
      .i_cmd_pin(1'b0), .i_cmd_ce(1'b1),
      .o_step_x(step_x), .o_dir_x(dir_x), .o_step_y(step_y), .o_dir_y(dir_y),
      .o_pulse(unused_pulse), .o_pulse_y(unused_pulse_y), .o_pulse_neg(unused_pulse_neg), .o_busy(busy)
  );

  assign P1A1 = step_x;
  assign P1A2 = dir_x;
  assign P1A3 = step_y;
  assign P1A4 = dir_y;
  assign LEDG_N = ~busy;
  assign LEDR_N = ~dir_x;

endmodule
