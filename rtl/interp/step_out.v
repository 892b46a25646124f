// step_out: the step/dir output stage of both axes, and the overrun rule.
//
// A command pulse reaches the core only when the output can take the pulse
// it will produce: both channels free and no pulse on its way from the
// core (the core's pulse output is registered), as of the clock before. A command pulse that comes
// while a move runs and the output cannot take it does not advance the
// interpolation; it sets the sticky overrun flag and counts in OVR_COUNT.
// No pulse is ever dropped after the core has produced it.
`default_nettype none

module step_out #(
    parameter integer TW = 12,  // timing register width
    parameter integer OW = 16   // overrun count width (OVR_COUNT, saturating)
) (
    input  wire          i_clk,
    input  wire          i_rst,
    input  wire          i_clear,      // clear the overrun flag and count
    input  wire [TW-1:0] i_len,
    input  wire [TW-1:0] i_space,
    input  wire [TW-1:0] i_setup,
    input  wire [TW-1:0] i_hold,
    input  wire          i_cmd,        // command pulse (cmd_gen's register)
    input  wire          i_cmd_next,   // i_cmd of the next clock (cmd_gen's o_cmd_next)
    input  wire          i_busy,       // the core has a move running
    output reg           o_cmd,        // command pulse passed to the core, a register
    input  wire          i_pulse,      // the core's output pulse
    input  wire          i_pulse_y,
    input  wire          i_pulse_neg,
    output wire          o_step_x,
    output wire          o_dir_x,
    output wire          o_step_y,
    output wire          o_dir_y,
    output reg           o_overrun,
    output reg  [OW-1:0] o_ovr_count
);

  // Ready, a register: the channels were free, no pulse was on its way
  // and no command went to the core in the clock before (a channel freed
  // in that clock is seen one clock later: conservative, never
  // optimistic). The gated command o_cmd = i_cmd & ready_q is itself a
  // register, formed a clock ahead from both terms' next values
  // (i_cmd_next, ready_d), so the core's command, its latest input, comes
  // straight from a flip-flop (issue 15: the gate's LUT and its routing
  // were on the critical path of interp_top).
  wire rdy_x, rdy_y;
  (* keep *) wire ready_d = rdy_x & rdy_y & ~i_pulse & ~o_cmd;  // kept: one LUT input
  reg ready_q;
  always @(posedge i_clk) begin
    if (i_rst) begin
      ready_q <= 1'b0;
      o_cmd <= 1'b0;
    end else begin
      ready_q <= ready_d;
      o_cmd <= i_cmd_next & ready_d;
    end
  end
  wire overrun = i_cmd & ~ready_q & i_busy;

  // Each timing value <= 1 (0 acts as 1), for both channels.
  wire len_le1 = (i_len[TW-1:1] == 0);
  wire space_le1 = (i_space[TW-1:1] == 0);
  wire setup_le1 = (i_setup[TW-1:1] == 0);
  wire hold_le1 = (i_hold[TW-1:1] == 0);

  step_chan #(.TW(TW)) u_x (
      .i_clk(i_clk), .i_rst(i_rst), .i_len(i_len), .i_space(i_space), .i_setup(i_setup),
      .i_hold(i_hold), .i_len_le1(len_le1), .i_space_le1(space_le1), .i_setup_le1(setup_le1),
      .i_hold_le1(hold_le1), .i_take(i_pulse & ~i_pulse_y), .i_neg(i_pulse_neg), .o_ready(rdy_x),
      .o_step(o_step_x), .o_dir(o_dir_x)
  );

  step_chan #(.TW(TW)) u_y (
      .i_clk(i_clk), .i_rst(i_rst), .i_len(i_len), .i_space(i_space), .i_setup(i_setup),
      .i_hold(i_hold), .i_len_le1(len_le1), .i_space_le1(space_le1), .i_setup_le1(setup_le1),
      .i_hold_le1(hold_le1), .i_take(i_pulse & i_pulse_y), .i_neg(i_pulse_neg), .o_ready(rdy_y),
      .o_step(o_step_y), .o_dir(o_dir_y)
  );

  // Sticky overrun flag.
  always @(posedge i_clk) begin
    if (i_rst | i_clear) o_overrun <= 1'b0;
    else if (overrun) o_overrun <= 1'b1;
  end

  // Overrun count, saturating: ovr_sat_q is "the count is all ones", a
  // register, so the OW-bit compare is not in the count's enable. OW = 16
  // (issue 15: was 32; a diagnostic count, 16 bits save ~20 LCs).
  reg ovr_sat_q;
  always @(posedge i_clk) begin
    if (i_rst | i_clear) begin
      o_ovr_count <= {OW{1'b0}};
      ovr_sat_q <= 1'b0;
    end else if (overrun & ~ovr_sat_q) begin
      o_ovr_count <= o_ovr_count + 1'b1;
      ovr_sat_q <= (o_ovr_count == {{(OW-1){1'b1}}, 1'b0});
    end
  end

endmodule
