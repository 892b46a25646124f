// step_chan: the step/dir timing of one axis.
//
// Takes one pulse (i_take, i_neg) when o_ready, and emits it as a STEP
// pulse with DIR set to i_neg, keeping (in clocks; 0 acts as 1):
//   step high   >= LEN      STEP high time (exactly LEN)
//   step low    >= SPACE    from a STEP falling edge to the next rising edge
//   dir setup   >= SETUP    from a DIR change to the next STEP rising edge
//   dir hold    >= HOLD     from a STEP falling edge to a DIR change
// o_ready is low from the clock after i_take until the step has fallen.
//
// Each interval is a down-counter loaded when it starts (the high time at
// the rising edge, space and hold at the falling edge, setup at the DIR
// change; high time, hold and setup share one counter: they follow each
// other) and counting to 0; an interval of n clocks has passed when the
// counter, loaded with n in the first clock of the interval, is <= 1.
// That test is a registered flag beside each counter (formed from the value
// loaded, or from "<= 2" before a count), so no counter's compare sits in
// the STEP/DIR decisions; once its flag is set a counter runs on
// unread (the flag stays set until the next load).
`default_nettype none

module step_chan #(
    parameter integer TW = 12  // timing register width
) (
    input  wire          i_clk,
    input  wire          i_rst,
    input  wire [TW-1:0] i_len,
    input  wire [TW-1:0] i_space,
    input  wire [TW-1:0] i_setup,
    input  wire [TW-1:0] i_hold,
    // Each timing value <= 1 (step_out forms them once for both channels).
    input  wire          i_len_le1,
    input  wire          i_space_le1,
    input  wire          i_setup_le1,
    input  wire          i_hold_le1,
    input  wire          i_take,
    input  wire          i_neg,
    output wire          o_ready,
    output reg           o_step,
    output reg           o_dir
);

  reg pend_q;          // a pulse is waiting or being emitted
  reg want_q;          // its direction
  // One counter for the intervals that follow each other: the STEP high
  // time (from a rise), the DIR hold (from a fall) and the DIR setup (from
  // a DIR change, which needs the hold passed). A rise may come while the
  // hold still counts (no DIR change wanted): the hold is then abandoned,
  // DIR cannot change while STEP is high, and the next fall starts it
  // again. Clocks left, this one included.
  reg [TW-1:0] cnt_q;
  reg setup_q;         // cnt_q counts a DIR setup (from a DIR change to the rise)
  reg [TW-1:0] spc_q;  // STEP low clocks still required, this one included

  // The flags: the counter beside each is <= 1. cnt_ok is the high time's
  // "last clock" while STEP is high, "hold passed" after a fall, "setup
  // passed" after a DIR change.
  reg cnt_ok, space_ok;
  // v <= 2.
  function automatic le2(input [TW-1:0] v);
    le2 = (v[TW-1:2] == 0) & ~(v[1] & v[0]);
  endfunction
  wire dir_eq = (o_dir == want_q);
  wire change_dir = pend_q & ~o_step & ~dir_eq & cnt_ok;
  wire rise = pend_q & ~o_step & dir_eq & space_ok & (~setup_q | cnt_ok);
  wire fall = o_step & cnt_ok;

  assign o_ready = ~pend_q;

  // Pending pulse.
  always @(posedge i_clk) begin
    if (i_rst) begin
      pend_q <= 1'b0;
      want_q <= 1'b0;
    end else if (i_take & ~pend_q) begin
      pend_q <= 1'b1;
      want_q <= i_neg;
    end else if (fall) begin
      pend_q <= 1'b0;
    end
  end

  // STEP.
  always @(posedge i_clk) begin
    if (i_rst) o_step <= 1'b0;
    else if (rise) o_step <= 1'b1;
    else if (fall) o_step <= 1'b0;
  end

  // High time left / hold / setup still required. The three loads are
  // exclusive (fall needs STEP high; rise and a DIR change need it low
  // and DIR equal to / different from the wanted one), so the value
  // loaded is chosen by flip-flops alone (STEP, DIR == wanted), beside the
  // load decision rather than after it; and the counter runs on once its
  // flag is set (only the flag is read, and it stays set until a load),
  // so the count needs no enable: the counter's input is one LUT after
  // the load decision (issue 15: the priority chain rise / fall / change
  // / count was five LUTs deep).
  wire cnt_ld = rise | fall | change_dir;
  wire [TW-1:0] cnt_val = o_step ? i_hold : dir_eq ? i_len : i_setup;
  wire cnt_val_le1 = o_step ? i_hold_le1 : dir_eq ? i_len_le1 : i_setup_le1;
  always @(posedge i_clk) begin
    if (i_rst) begin
      cnt_q <= {TW{1'b0}};
      cnt_ok <= 1'b1;
    end else if (cnt_ld) begin
      cnt_q <= cnt_val;
      cnt_ok <= cnt_val_le1;
    end else begin
      cnt_q <= cnt_q - 1'b1;
      cnt_ok <= cnt_ok | le2(cnt_q);
    end
  end
  always @(posedge i_clk) begin
    if (i_rst | rise) setup_q <= 1'b0;
    else if (change_dir) setup_q <= 1'b1;
  end

  // Low time still required (runs on once its flag is set, like cnt_q).
  always @(posedge i_clk) begin
    if (i_rst) begin
      spc_q <= {TW{1'b0}};
      space_ok <= 1'b1;
    end else if (fall) begin
      spc_q <= i_space;
      space_ok <= i_space_le1;
    end else begin
      spc_q <= spc_q - 1'b1;
      space_ok <= space_ok | le2(spc_q);
    end
  end

  // DIR.
  always @(posedge i_clk) begin
    if (i_rst) o_dir <= 1'b0;
    else if (change_dir) o_dir <= want_q;
  end

endmodule
