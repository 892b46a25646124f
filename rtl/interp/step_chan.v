// step_chan: the step/dir timing of one axis.
//
// Takes one pulse (i_take, i_neg) when o_ready, and emits it as a STEP
// pulse with DIR set to i_neg, keeping (in clocks; 0 acts as 1):
//   step high   >= LEN      STEP high time
//   step low    >= SPACE    from a STEP falling edge to the next rising edge
//   dir setup   >= SETUP    from a DIR change to the next STEP rising edge
//   dir hold    >= HOLD     from a STEP falling edge to a DIR change
// o_ready is low from the clock after i_take until the step has fallen.
`default_nettype none

module step_chan #(
    parameter integer TW = 16  // timing register width
) (
    input  wire          i_clk,
    input  wire          i_rst,
    input  wire [TW-1:0] i_len,
    input  wire [TW-1:0] i_space,
    input  wire [TW-1:0] i_setup,
    input  wire [TW-1:0] i_hold,
    input  wire          i_take,
    input  wire          i_neg,
    output wire          o_ready,
    output reg           o_step,
    output reg           o_dir
);

  reg pend_q;          // a pulse is waiting or being emitted
  reg want_q;          // its direction
  reg [TW-1:0] high_q; // clocks of STEP high left
  reg [TW-1:0] fall_q; // clocks since the STEP falling edge (saturating)
  reg [TW-1:0] dirc_q; // clocks since the DIR change (saturating)

  wire [TW-1:0] one = {{(TW-1){1'b0}}, 1'b1};
  wire [TW-1:0] len = (i_len == 0) ? one : i_len;
  // The counters count the clock in which the event becomes visible as 1,
  // so "fall_q >= SPACE" in a clock lets STEP rise in the next one after
  // exactly SPACE low clocks.
  wire space_ok = (fall_q >= i_space);
  wire hold_ok = (fall_q >= i_hold);
  wire setup_ok = (dirc_q >= i_setup);
  wire change_dir = pend_q & ~o_step & (o_dir != want_q) & hold_ok;
  wire rise = pend_q & ~o_step & (o_dir == want_q) & space_ok & setup_ok;
  wire fall = o_step & (high_q <= one);

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

  // STEP and its high-time counter.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_step <= 1'b0;
      high_q <= {TW{1'b0}};
    end else if (rise) begin
      o_step <= 1'b1;
      high_q <= len;
    end else if (fall) begin
      o_step <= 1'b0;
    end else if (o_step) begin
      high_q <= high_q - 1'b1;
    end
  end

  // DIR.
  always @(posedge i_clk) begin
    if (i_rst) o_dir <= 1'b0;
    else if (change_dir) o_dir <= want_q;
  end

  // Clocks since the STEP falling edge, saturating.
  always @(posedge i_clk) begin
    if (i_rst) fall_q <= {TW{1'b1}};
    else if (fall) fall_q <= one;
    else if (~o_step && fall_q != {TW{1'b1}}) fall_q <= fall_q + 1'b1;
  end

  // Clocks since the DIR change, saturating.
  always @(posedge i_clk) begin
    if (i_rst) dirc_q <= {TW{1'b1}};
    else if (change_dir) dirc_q <= one;
    else if (dirc_q != {TW{1'b1}}) dirc_q <= dirc_q + 1'b1;
  end

endmodule
