// interp_top: the dedicated interpolator as a Wishbone peripheral.
//
//   wb_regs -> interp_core (prep, queue, datapath) -> step_out -> pins
//              cmd_gen (pin / feed / every clock) --^   pos_counter x2
//              (feed and every clock on i_cmd_ce: the board's time scale)
//
// Synchronous, active-high reset for every flop. The debug outputs carry
// the core's pulses (one per interpolation step) for test benches.
`default_nettype none

module interp_top #(
    parameter integer W = 24,   // coordinate width (3..30)
    parameter integer QAW = 4,  // log2 of the queue memory depth
    parameter integer TW = 12   // step timing width: STEP_LEN .. DIR_HOLD (regmap.def)
) (
    input  wire        i_clk,
    input  wire        i_rst,
    // Wishbone B4 classic slave
    input  wire        i_wb_cyc,
    input  wire        i_wb_stb,
    input  wire        i_wb_we,
    input  wire [7:0]  i_wb_adr,
    input  wire [31:0] i_wb_dat,
    output wire [31:0] o_wb_dat,
    output wire        o_wb_ack,
    // Command pin (paper A's interrupt line), asynchronous
    input  wire        i_cmd_pin,
    // Clock enable of the feed generator and the every-clock source (a
    // time scale: the board's feed hold); 1 where there is none
    input  wire        i_cmd_ce,
    // Step/dir outputs
    output wire        o_step_x,
    output wire        o_dir_x,
    output wire        o_step_y,
    output wire        o_dir_y,
    // Debug: the core's pulses
    output wire        o_pulse,
    output wire        o_pulse_y,
    output wire        o_pulse_neg,
    output wire        o_busy
);

  wire [1:0] src;
  wire abort, clear, push;
  wire [31:0] feed;
  wire [TW-1:0] len, space, setup, hold;
  wire [4*W+8:0] blk;  // the staged block (interp_block.vh)
  wire full, overrun;
  wire [QAW+1:0] level;
  wire [15:0] ovr_count;
  wire [31:0] pos_x, pos_y;
  reg [31:0] moves_q;

  wire cmd_raw, cmd_next, cmd_core;
  wire pulse, pulse_y, pulse_neg, pulse_last, busy;

  wb_regs #(.W(W), .QAW(QAW), .TW(TW)) u_regs (
      .i_clk(i_clk), .i_rst(i_rst),
      .i_wb_cyc(i_wb_cyc), .i_wb_stb(i_wb_stb), .i_wb_we(i_wb_we), .i_wb_adr(i_wb_adr),
      .i_wb_dat(i_wb_dat), .o_wb_dat(o_wb_dat), .o_wb_ack(o_wb_ack),
      .o_src(src), .o_abort(abort), .o_clear(clear), .o_feed(feed),
      .o_len(len), .o_space(space), .o_setup(setup), .o_hold(hold),
      .o_push(push), .o_blk(blk),
      .i_busy(busy), .i_full(full), .i_level(level), .i_overrun(overrun), .i_ovr_count(ovr_count),
      .i_pos_x(pos_x), .i_pos_y(pos_y), .i_moves(moves_q)
  );

  cmd_gen #(.N(32)) u_cmd (
      .i_clk(i_clk), .i_rst(i_rst), .i_ce(i_cmd_ce), .i_src(src), .i_pin(i_cmd_pin), .i_inc(feed), .o_cmd(cmd_raw),
      .o_cmd_next(cmd_next)
  );

  // The core's state outputs are for test benches; the peripheral reports
  // positions from its own counters. They go to unused_* wires (the
  // linter expects those names to be unused).
  wire [W-1:0] unused_xmag, unused_ymag;
  wire [W+1:0] unused_d;
  wire [1:0] unused_q;
  wire [2:0] unused_k;
  wire unused_xneg, unused_yneg, unused_arc;
  interp_core #(.W(W), .QAW(QAW)) u_core (
      .i_clk(i_clk), .i_rst(i_rst), .i_abort(abort), .i_cmd(cmd_core),
      .i_push(push), .i_blk(blk), .o_full(full), .o_level(level),
      .o_pulse(pulse), .o_pulse_y(pulse_y), .o_pulse_neg(pulse_neg), .o_pulse_last(pulse_last),
      .o_busy(busy), .o_xmag(unused_xmag), .o_xneg(unused_xneg), .o_ymag(unused_ymag),
      .o_yneg(unused_yneg), .o_d(unused_d), .o_q(unused_q), .o_k(unused_k), .o_arc(unused_arc)
  );

  step_out #(.TW(TW), .OW(16)) u_out (
      .i_clk(i_clk), .i_rst(i_rst), .i_clear(clear),
      .i_len(len), .i_space(space), .i_setup(setup), .i_hold(hold),
      .i_cmd(cmd_raw), .i_cmd_next(cmd_next), .i_busy(busy), .o_cmd(cmd_core),
      .i_pulse(pulse), .i_pulse_y(pulse_y), .i_pulse_neg(pulse_neg),
      .o_step_x(o_step_x), .o_dir_x(o_dir_x), .o_step_y(o_step_y), .o_dir_y(o_dir_y),
      .o_overrun(overrun), .o_ovr_count(ovr_count)
  );

  pos_counter #(.PW(32)) u_pos_x (
      .i_clk(i_clk), .i_rst(i_rst), .i_pulse(pulse & ~pulse_y), .i_neg(pulse_neg), .o_pos(pos_x)
  );

  pos_counter #(.PW(32)) u_pos_y (
      .i_clk(i_clk), .i_rst(i_rst), .i_pulse(pulse & pulse_y), .i_neg(pulse_neg), .o_pos(pos_y)
  );

  // Moves completed.
  always @(posedge i_clk) begin
    if (i_rst) moves_q <= 32'd0;
    else if (pulse_last) moves_q <= moves_q + 1'b1;
  end

  assign o_pulse = pulse;
  assign o_pulse_y = pulse_y;
  assign o_pulse_neg = pulse_neg;
  assign o_busy = busy;

endmodule
