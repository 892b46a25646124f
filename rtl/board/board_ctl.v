// board_ctl: the LINK window (link.def): the watchdog, the feed hold and
// its time scale, the pins' control, the frame counters. A Wishbone B4
// classic slave (ack one clock after the strobe; wb_regs takes two).
//
// Time scale: SCALE (0..0x10000) moves by one toward its target every RAMP
// clocks: toward 0 while a hold is asked for (CTRL.HOLD, or the watchdog
// tripped), toward 0x10000 otherwise. o_ce is high in a fraction SCALE /
// 0x10000 of the clocks (a phase accumulator), every clock at full scale:
// the chord engine's time advances only on o_ce, so a hold slows the
// commanded motion linearly to rest along its path and a resume brings it
// back, with every pulse given whole.
//
// Watchdog: armed by the first frame done; when WDOG (not 0) clocks pass
// without a frame done, it trips (sticky STATUS.WDOG, a hold) until the
// host writes CTRL.RESUME.
`default_nettype none

module board_ctl (
    input  wire        i_clk,
    input  wire        i_rst,
    // Wishbone
    input  wire        i_wb_cyc,
    input  wire        i_wb_stb,
    input  wire        i_wb_we,
    input  wire [7:0]  i_wb_adr,
    input  wire [31:0] i_wb_dat,
    output reg  [31:0] o_wb_dat,
    output reg         o_wb_ack,
    // From link_ctrl
    input  wire        i_frame_ok,
    input  wire        i_refused,
    // Out
    output wire        o_ce,       // the time-scaled clock enable
    output wire        o_hold,
    output wire        o_stopped,
    output reg         o_wdog,
    output wire        o_enable,
    output wire        o_pins
);

`include "board_proto.vh"

  wire acc = i_wb_cyc & i_wb_stb & ~o_wb_ack;
  wire wr = acc & i_wb_we;
  wire [7:0] adr = {i_wb_adr[7:2], 2'b00};
  wire [1:0] unused_adr = i_wb_adr[1:0];

  reg enable_q, pins_q, hold_q;
  reg [23:0] wdog_q;
  reg [15:0] ramp_q;
  reg [31:0] frames_q, refused_q;
  reg [23:0] quiet_q;  // clocks since the last frame done (saturating)
  reg armed_q;
  reg [16:0] scale_q;
  reg [15:0] tick_q;   // clocks since the last scale step
  reg [15:0] phase_q;

  assign o_hold = hold_q | o_wdog;
  assign o_stopped = (scale_q == 17'd0);
  assign o_enable = enable_q;
  assign o_pins = pins_q;

  // Acknowledge.
  always @(posedge i_clk) begin
    if (i_rst) o_wb_ack <= 1'b0;
    else o_wb_ack <= acc;
  end

  // Writable registers.
  always @(posedge i_clk) begin
    if (i_rst) begin
      enable_q <= R_LINK_CTRL[LINK_CTRL_ENABLE];
      pins_q <= R_LINK_CTRL[LINK_CTRL_PINS];
      hold_q <= R_LINK_CTRL[LINK_CTRL_HOLD];
      wdog_q <= R_LINK_WDOG[23:0];
      ramp_q <= R_LINK_RAMP[15:0];
    end else if (wr) begin
      case (adr)
        A_LINK_CTRL: begin
          enable_q <= i_wb_dat[LINK_CTRL_ENABLE];
          pins_q <= i_wb_dat[LINK_CTRL_PINS];
          hold_q <= i_wb_dat[LINK_CTRL_HOLD];
        end
        A_LINK_WDOG: wdog_q <= i_wb_dat[23:0];
        A_LINK_RAMP: ramp_q <= i_wb_dat[15:0];
        default: ;
      endcase
    end
  end

  wire resume = wr && adr == A_LINK_CTRL && i_wb_dat[LINK_CTRL_RESUME];

  // Watchdog.
  always @(posedge i_clk) begin
    if (i_rst) begin
      quiet_q <= 24'd0;
      armed_q <= 1'b0;
      o_wdog <= 1'b0;
    end else begin
      if (i_frame_ok || resume) quiet_q <= 24'd0;
      else if (quiet_q != 24'hFF_FFFF) quiet_q <= quiet_q + 24'd1;
      if (i_frame_ok) armed_q <= 1'b1;
      if (resume) o_wdog <= 1'b0;
      else if (armed_q && wdog_q != 24'd0 && quiet_q >= wdog_q) o_wdog <= 1'b1;
    end
  end

  // Time scale: one step toward the target every RAMP clocks.
  always @(posedge i_clk) begin
    if (i_rst) begin
      scale_q <= 17'h10000;
      tick_q <= 16'd0;
    end else if ({1'b0, tick_q} + 17'd1 < {1'b0, ramp_q}) begin
      tick_q <= tick_q + 16'd1;
    end else begin
      tick_q <= 16'd0;
      if (o_hold && scale_q != 17'd0) scale_q <= scale_q - 17'd1;
      else if (!o_hold && scale_q != 17'h10000) scale_q <= scale_q + 17'd1;
    end
  end

  // The clock enable: a phase accumulator with increment SCALE.
  wire [16:0] phase_sum = {1'b0, phase_q} + scale_q;
  always @(posedge i_clk) begin
    if (i_rst) phase_q <= 16'd0;
    else phase_q <= phase_sum[15:0];
  end
  assign o_ce = phase_sum[16];

  // Frame counters.
  always @(posedge i_clk) begin
    if (i_rst) begin
      frames_q <= 32'd0;
      refused_q <= 32'd0;
    end else begin
      if (i_frame_ok) frames_q <= frames_q + 32'd1;
      if (i_refused) refused_q <= refused_q + 32'd1;
    end
  end

  // Read data.
  always @(posedge i_clk) begin
    if (acc & ~i_wb_we) begin
      o_wb_dat <= 32'd0;
      case (adr)
        A_LINK_ID: o_wb_dat <= R_LINK_ID;
        A_LINK_CTRL: begin
          o_wb_dat[LINK_CTRL_ENABLE] <= enable_q;
          o_wb_dat[LINK_CTRL_PINS] <= pins_q;
          o_wb_dat[LINK_CTRL_HOLD] <= hold_q;
        end
        A_LINK_STATUS: begin
          o_wb_dat[LINK_STATUS_HOLD] <= o_hold;
          o_wb_dat[LINK_STATUS_STOPPED] <= o_stopped;
          o_wb_dat[LINK_STATUS_WDOG] <= o_wdog;
        end
        A_LINK_WDOG: o_wb_dat[23:0] <= wdog_q;
        A_LINK_RAMP: o_wb_dat[15:0] <= ramp_q;
        A_LINK_SCALE: o_wb_dat <= {15'd0, scale_q};
        A_LINK_FRAMES: o_wb_dat <= frames_q;
        A_LINK_REFUSED: o_wb_dat <= refused_q;
        default: ;
      endcase
    end
  end

endmodule
