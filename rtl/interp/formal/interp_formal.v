// interp_formal: formal harness of interp_core (block prep, queue,
// datapath) at a small W. One move, chosen by the solver among every move
// the host's validation accepts (the rules of Circular<W>::validate and
// Linear<W>::validate, written out below), is pushed after reset; then the
// command is held high.
//
// Asserted here, besides the datapath's own invariants (interp_dp.v,
// `ifdef FORMAL`):
//   - the position implied by the pulses equals the reported position, so
//     every pulse is exactly one unit of motion on one axis;
//   - when the move is done it is at its end point, and a line has taken
//     exactly |XE| + |YE| pulses, an arc at most 8 R + 8;
//   - the move is done within that many pulses (no runaway).
`default_nettype none

module interp_formal #(
    parameter integer W = 4  // coordinate width under proof
) (
    input wire i_clk,
    // The move: free inputs, captured in the reset clock and held.
    input wire i_arc,
    input wire i_cw,
    input wire signed [W+1:0] i_xs,
    input wire signed [W+1:0] i_ys,
    input wire signed [W+1:0] i_xe,
    input wire signed [W+1:0] i_ye
);

`include "interp_block.vh"

  localparam integer MAXC = (1 << W) - 1;

  reg f_arc, f_cw;
  reg signed [W+1:0] f_xs, f_ys, f_xe, f_ye;

  // ------------------------------------------------- the host's validation
  function [W+1:0] mag;
    input signed [W+1:0] v;
    mag = v[W+1] ? -v : v;
  endfunction

  // quadrant_of() of the model: points on an axis belong to the quadrant
  // the motion enters.
  function [1:0] quadrant_of;
    input signed [W+1:0] x, y;
    input cw;
    begin
      if (!cw) begin
        if (x > 0 && y >= 0) quadrant_of = 2'd0;
        else if (x <= 0 && y > 0) quadrant_of = 2'd1;
        else if (x < 0 && y <= 0) quadrant_of = 2'd2;
        else quadrant_of = 2'd3;
      end else begin
        if (x >= 0 && y > 0) quadrant_of = 2'd0;
        else if (x < 0 && y >= 0) quadrant_of = 2'd1;
        else if (x <= 0 && y < 0) quadrant_of = 2'd2;
        else quadrant_of = 2'd3;
      end
    end
  endfunction

  wire [W+1:0] axs = mag(f_xs), ays = mag(f_ys), axe = mag(f_xe), aye = mag(f_ye);
  wire signed [2*W+5:0] r2 = f_xs * f_xs + f_ys * f_ys;
  wire signed [2*W+5:0] de = f_xe * f_xe + f_ye * f_ye - r2;
  wire signed [2*W+5:0] band = $signed({1'b0, axe}) + $signed({1'b0, aye});
  wire [1:0] qs = quadrant_of(f_xs, f_ys, f_cw);
  wire [1:0] qe = quadrant_of(f_xe, f_ye, f_cw);
  wire [1:0] fwd = f_cw ? qs - qe : qe - qs;
  wire in_x_e = ~qe[0] ^ f_cw;
  wire [W+1:0] in_e = in_x_e ? axe : aye;
  wire [W+1:0] out_e = in_x_e ? aye : axe;
  wire [W+1:0] in_s = in_x_e ? axs : ays;
  wire [W+1:0] out_s = in_x_e ? ays : axs;
  wire same = (f_xs == f_xe) && (f_ys == f_ye);
  wire [2:0] k_start = (fwd != 0) ? {1'b0, fwd} : ((!same && in_s >= in_e && out_s <= out_e) ? 3'd0 : 3'd4);
  // Entry rule: in_e <= ceil(sqrt(R^2 - 1)), i.e. (in_e - 1)^2 < R^2 - 1.
  wire signed [2*W+5:0] in_e_m1 = $signed({1'b0, in_e}) - 1;
  wire entry_ok = (k_start == 0) || (in_e == 0) || (in_e_m1 * in_e_m1 < r2 - 1);

  // ------------------------------------------------------------- stimulus
  reg [1:0] f_t;  // 0: reset, 1: push, 2: run
  initial f_t = 2'd0;
  always @(posedge i_clk) if (f_t != 2'd2) f_t <= f_t + 1'b1;
  always @(posedge i_clk) begin
    if (f_t == 2'd0) begin
      f_arc <= i_arc;
      f_cw <= i_cw;
      f_xs <= i_xs;
      f_ys <= i_ys;
      f_xe <= i_xe;
      f_ye <= i_ye;
    end
  end
  // (From the clock after the capture: before it the registers hold no
  // move yet.)
  always @(*) begin
    if (f_t != 2'd0) begin
`ifdef LINE_ONLY
      assume(!f_arc);
`endif
`ifdef ARC_ONLY
      assume(f_arc);
`endif
      assume(axs <= MAXC && ays <= MAXC && axe <= MAXC && aye <= MAXC);
      if (f_arc) begin
        assume(r2 >= 2 && r2 <= MAXC * MAXC);
        assume(de <= band && -de <= band);
        assume(entry_ok);
      end
    end
  end

  wire rst = (f_t == 2'd0);
  wire push = (f_t == 2'd1);  // the move is captured by now
  wire cmd = 1'b1;

  wire pulse, pulse_y, pulse_neg, pulse_last, busy, xneg, yneg, arc_o;
  wire [W-1:0] xmag, ymag;
  wire [W+1:0] d;
  wire [1:0] q;
  wire [2:0] k;
  wire full;
  wire [2:0] level;

  // The block as the host writes it: kind, sense, signs, start quadrant,
  // crossings, magnitudes.
  wire [BLK_BITS-1:0] blk;
  assign blk[BLK_ARC] = f_arc;
  assign blk[BLK_CW] = f_cw;
  assign blk[BLK_SXN] = (f_xe < 0);
  assign blk[BLK_SYN] = (f_ye < 0);
  assign blk[BLK_Q +: 2] = qs;
  assign blk[BLK_K +: 3] = k_start;
  assign blk[BLK_XS +: W] = axs[W-1:0];
  assign blk[BLK_YS +: W] = ays[W-1:0];
  assign blk[BLK_XE +: W] = axe[W-1:0];
  assign blk[BLK_YE +: W] = aye[W-1:0];

  interp_core #(.W(W), .QAW(1)) dut (
      .i_clk(i_clk), .i_rst(rst), .i_abort(1'b0), .i_cmd(cmd),
      .i_push(push), .i_blk(blk),
      .o_full(full), .o_level(level),
      .o_pulse(pulse), .o_pulse_y(pulse_y), .o_pulse_neg(pulse_neg), .o_pulse_last(pulse_last),
      .o_busy(busy), .o_xmag(xmag), .o_xneg(xneg), .o_ymag(ymag), .o_yneg(yneg),
      .o_d(d), .o_q(q), .o_k(k), .o_arc(arc_o)
  );

  // ------------------------------------------------------------ properties
  // Position from the pulses (start: 0 for a line, the start point for an
  // arc) and the pulse count.
  reg signed [W+2:0] px, py;
  reg [W+4:0] n;
  reg loaded, was_busy;
  initial loaded = 1'b0;
  always @(posedge i_clk) begin
    if (rst) begin
      loaded <= 1'b0;
      was_busy <= 1'b0;
    end else begin
      if (level == 0 && f_t == 2'd2 && !loaded) begin
        loaded <= 1'b1;
        px <= f_arc ? f_xs : 0;
        py <= f_arc ? f_ys : 0;
        n <= 0;
      end
      if (loaded && pulse) begin
        if (pulse_y) py <= pulse_neg ? py - 1 : py + 1;
        else px <= pulse_neg ? px - 1 : px + 1;
        n <= n + 1'b1;
      end
      was_busy <= busy;
    end
  end

  wire signed [W+2:0] sx = xneg ? -$signed({3'b000, xmag}) : $signed({3'b000, xmag});
  wire signed [W+2:0] sy = yneg ? -$signed({3'b000, ymag}) : $signed({3'b000, ymag});
  wire [W+4:0] bound = f_arc ? 8 * (axs + ays) + 8 : axe + aye;
  // The position after the pulse of this clock (the state shown now is
  // the state after it).
  wire signed [W+2:0] pxn = (pulse && !pulse_y) ? (pulse_neg ? px - 1 : px + 1) : px;
  wire signed [W+2:0] pyn = (pulse && pulse_y) ? (pulse_neg ? py - 1 : py + 1) : py;
  wire [W+4:0] nn = pulse ? n + 1'b1 : n;

  always @(*) begin
    if (loaded && !rst) begin
      // Every pulse is one unit of motion of the reported position.
      assert(pxn == sx && pyn == sy);
      assert(nn <= bound);
      if (!busy) begin
        assert(pxn == f_xe && pyn == f_ye);
        if (!f_arc) assert(nn == axe + aye);
      end
    end
  end

endmodule
