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
//   - the move is done within that many pulses (no runaway);
//   - the step rule: a reference of docs/algorithm.md's "One command
//     pulse" (Linear, Circular), registers |x|, |y|, q, k, D, steps once
//     per output pulse; each pulse (axis, sign) and the state shown with
//     it equal the reference's, and there is a pulse exactly while the
//     reference is not done (so the pulse count is the reference's).
// With COVER defined the assertions give way to the covers (o_cov), one
// per contract path (run_formal.sh covers). Flow and figures:
// run_formal.sh, docs/rtl.md "Formal".
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
`ifdef COVER
    ,
    output wire [23:0] o_cov  // the covers (below), one bit each
`endif
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
  // crossings, magnitudes (arc: in inward/outward order, the start's by
  // the start quadrant, the end's by the end quadrant; line: 0, 0, |xe|,
  // |ye|).
  wire in_x_s = ~qs[0] ^ f_cw;
  wire [BLK_BITS-1:0] blk;
  assign blk[BLK_ARC] = f_arc;
  assign blk[BLK_CW] = f_cw;
  // The fields a kind does not use are 0, as interp_core requires (a
  // line's CI, CO, Q, K, an arc's SXN, SYN; wb_regs zeroes them).
  assign blk[BLK_SXN] = !f_arc && (f_xe < 0);
  assign blk[BLK_SYN] = !f_arc && (f_ye < 0);
  assign blk[BLK_Q +: 2] = f_arc ? qs : 2'd0;
  assign blk[BLK_K +: 3] = f_arc ? k_start : 3'd0;
  assign blk[BLK_CI +: W] = !f_arc ? {W{1'b0}} : in_x_s ? axs[W-1:0] : ays[W-1:0];
  assign blk[BLK_CO +: W] = !f_arc ? {W{1'b0}} : in_x_s ? ays[W-1:0] : axs[W-1:0];
  assign blk[BLK_TI +: W] = (f_arc && !in_x_e) ? aye[W-1:0] : axe[W-1:0];
  assign blk[BLK_TO +: W] = (f_arc && !in_x_e) ? axe[W-1:0] : aye[W-1:0];

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
  wire load_now = (level == 0 && f_t == 2'd2 && !loaded);  // the move is in the datapath
  always @(posedge i_clk) begin
    if (rst) begin
      loaded <= 1'b0;
      was_busy <= 1'b0;
    end else begin
      if (load_now) begin
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

  // ------------------------------------------- the reference of the step
  // docs/algorithm.md, "One command pulse" of Linear and of Circular,
  // written out register by register (not derived from the datapath nor
  // the C++ model). It takes one step for every output pulse of the core;
  // its state after the step must be the state the core shows with the
  // pulse. Registers one bit wider than the contract's, so that an
  // overflow of the core is a difference, not a shared wrap-around.
  //   line: r_a = x travelled, r_b = y travelled, D = A y - B x
  //   arc:  r_a = |x|, r_b = |y|, q, k, D = x^2 + y^2 - R^2
  reg [W:0] r_a, r_b;
  reg [1:0] r_q;
  reg [2:0] r_k;
  reg signed [W+3:0] r_d;
  reg r_done;
  reg [W+4:0] r_n;  // steps taken
  wire f_sxn = (f_xe < 0), f_syn = (f_ye < 0);
  wire [W:0] e_a = axe[W:0], e_b = aye[W:0];
  wire signed [W+3:0] e_as = $signed({3'b000, e_a}), e_bs = $signed({3'b000, e_b});

  // Arc: the inward axis is X when (q even) XOR CW; quadrant signs.
  wire r_inx = ~r_q[0] ^ f_cw;
  wire r_qxn = (r_q == 2'd1) || (r_q == 2'd2);
  wire r_qyn = (r_q == 2'd2) || (r_q == 2'd3);
  wire [W:0] r_in = r_inx ? r_a : r_b;
  wire [W:0] r_out = r_inx ? r_b : r_a;
  wire [W:0] r_in_e = r_inx ? e_a : e_b;
  wire [W:0] r_out_e = r_inx ? e_b : e_a;

  reg r_inw, r_rule, r_py, r_pneg;  // step inward / X; end-point rule fired; pulse
  reg [W:0] r_a1, r_b1, r_in1;
  reg [1:0] r_q1;
  reg [2:0] r_k1;
  reg signed [W+3:0] r_d1;
  reg r_done1, r_cross;
  always @(*) begin
    r_inw = (r_d >= 0);  // tie: D = 0 goes in (line: moves X)
    r_rule = 1'b0;
    r_a1 = r_a;
    r_b1 = r_b;
    r_q1 = r_q;
    r_k1 = r_k;
    r_d1 = r_d;
    r_in1 = r_in;
    r_cross = 1'b0;
    r_py = 1'b0;
    r_pneg = 1'b0;
    if (!f_arc) begin
      if (r_inw && r_a == e_a) begin
        r_inw = 1'b0;
        r_rule = 1'b1;
      end else if (!r_inw && r_b == e_b) begin
        r_inw = 1'b1;
        r_rule = 1'b1;
      end
      if (r_inw) begin
        r_a1 = r_a + 1'b1;
        r_d1 = r_d - e_bs;
        r_py = 1'b0;
        r_pneg = f_sxn;
      end else begin
        r_b1 = r_b + 1'b1;
        r_d1 = r_d + e_as;
        r_py = 1'b1;
        r_pneg = f_syn;
      end
      r_done1 = (r_a1 == e_a) && (r_b1 == e_b);
    end else begin
      if (r_k == 3'd0) begin
        if (r_inw && r_in == r_in_e) begin
          r_inw = 1'b0;
          r_rule = 1'b1;
        end else if (!r_inw && r_out == r_out_e) begin
          r_inw = 1'b1;
          r_rule = 1'b1;
        end
      end
      if (r_inw) begin
        r_d1 = r_d - (2 * $signed({3'b000, r_in}) - 1);
        r_in1 = r_in - 1'b1;
        if (r_inx) r_a1 = r_in1;
        else r_b1 = r_in1;
        r_py = ~r_inx;
        r_pneg = ~(r_inx ? r_qxn : r_qyn);
        if (r_in1 == 0) begin
          r_cross = 1'b1;
          r_q1 = f_cw ? r_q - 1'b1 : r_q + 1'b1;
          r_k1 = r_k - 1'b1;
        end
      end else begin
        r_d1 = r_d + (2 * $signed({3'b000, r_out}) + 1);
        if (r_inx) r_b1 = r_out + 1'b1;
        else r_a1 = r_out + 1'b1;
        r_py = r_inx;
        r_pneg = r_inx ? r_qyn : r_qxn;
      end
      r_done1 = (r_k1 == 3'd0) && (r_a1 == e_a) && (r_b1 == e_b);
    end
  end

  always @(posedge i_clk) begin
    if (load_now) begin
      r_a <= f_arc ? axs[W:0] : {(W+1){1'b0}};
      r_b <= f_arc ? ays[W:0] : {(W+1){1'b0}};
      r_q <= f_arc ? qs : 2'd0;
      r_k <= f_arc ? k_start : 3'd0;
      r_d <= 0;
      r_n <= 0;
      r_done <= f_arc ? (k_start == 0 && axs == axe && ays == aye) : (axe == 0 && aye == 0);
    end else if (loaded && pulse) begin
      r_a <= r_a1;
      r_b <= r_b1;
      r_q <= r_q1;
      r_k <= r_k1;
      r_d <= r_d1;
      r_n <= r_n + 1'b1;
      r_done <= r_done1;
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
  // The reference's state as the core should show it now: after its step
  // when there is a pulse, else unchanged.
  wire [W:0] r_a_now = pulse ? r_a1 : r_a;
  wire [W:0] r_b_now = pulse ? r_b1 : r_b;
  wire [1:0] r_q_now = pulse ? r_q1 : r_q;
  wire [2:0] r_k_now = pulse ? r_k1 : r_k;
  wire signed [W+3:0] r_d_now = pulse ? r_d1 : r_d;
  wire r_done_now = pulse ? r_done1 : r_done;
  wire [W+4:0] r_n_now = pulse ? r_n + 1'b1 : r_n;

`ifndef COVER
  always @(*) begin
    if (loaded && !rst) begin
      // Every pulse is one unit of motion of the reported position.
      assert(pxn == sx && pyn == sy);
      assert(nn <= bound);
      if (!busy) begin
        assert(pxn == f_xe && pyn == f_ye);
        if (!f_arc) assert(nn == axe + aye);
      end
      // The step rule: one pulse per clock exactly while the reference is
      // not done, each the reference's (axis, sign), with its state after.
      assert(pulse == !r_done);
      if (pulse) assert(pulse_y == r_py && pulse_neg == r_pneg);
      assert({1'b0, xmag} == r_a_now && {1'b0, ymag} == r_b_now);
      assert($signed(d) == r_d_now);
      assert(busy == !r_done_now);
      assert(nn == r_n_now);
      // (begin/end: `assert (...); else` would make the else the first
      // assert's fail action in SystemVerilog, as Verilator reads it.)
      if (f_arc) begin
        assert(q == r_q_now && k == r_k_now);
      end else begin
        assert(xneg == f_sxn && yneg == f_syn);
      end
    end
  end
`else
  // ---------------------------------------------------------------- covers
  // Each contract path, as one output of the cover model (run_formal.sh
  // covers: a bounded model check must find a trace to each). Taken at a
  // step of the reference (s) or at the load (ld).
  wire s = loaded && !rst && pulse && !r_done;
  wire sa = s && f_arc, sl = s && !f_arc;
  wire ldc = load_now && f_arc;
  assign o_cov = {
      sa && f_cw && r_q == 2'd3,   // 23 arc CW step in Q4
      sa && f_cw && r_q == 2'd2,   // 22 arc CW step in Q3
      sa && f_cw && r_q == 2'd1,   // 21 arc CW step in Q2
      sa && f_cw && r_q == 2'd0,   // 20 arc CW step in Q1
      sa && !f_cw && r_q == 2'd3,  // 19 arc CCW step in Q4
      sa && !f_cw && r_q == 2'd2,  // 18 arc CCW step in Q3
      sa && !f_cw && r_q == 2'd1,  // 17 arc CCW step in Q2
      sa && !f_cw && r_q == 2'd0,  // 16 arc CCW step in Q1
      sa && r_inw,                 // 15 arc inward step
      sa && !r_inw,                // 14 arc outward step
      sa && r_d == 0 && !r_rule,   // 13 arc tie D = 0 goes in
      sa && r_rule && !r_inw,      // 12 arc end-point rule: inward axis arrived, out
      sa && r_rule && r_inw,       // 11 arc end-point rule: outward axis arrived, in
      sa && r_cross && r_k == 3'd1,  // 10 arc crossing onto the end quadrant
      ldc && k_start == 3'd0,      //  9 arc k = 0 at the load
      ldc && k_start == 3'd1,      //  8 arc k = 1 at the load
      ldc && k_start == 3'd2,      //  7 arc k = 2 at the load
      ldc && k_start == 3'd3,      //  6 arc k = 3 at the load
      ldc && k_start == 3'd4,      //  5 arc k = 4 at the load (full circle or round)
      loaded && f_arc && !busy && k_start == 3'd4 && r_n != 0,  //  4 arc of k = 4 done
      sl && r_inw && r_d == 0 && !r_rule,  //  3 line tie D = 0 moves X
      sl && !r_inw,                //  2 line Y step
      sl && r_rule,                //  1 line end-point rule (A = 0)
      sl && f_sxn && f_syn         //  0 line step into the third quadrant
  };
`endif

endmodule
