// interp_dp: the interpolation datapath of paper A, one step per clock.
//
// Executes the contract of docs/algorithm.md ("Linear", "Circular") on a
// block prepared by blk_prep. Both kinds share one recurrence
//
//     inward step:  D <- D - SUB        outward step:  D <- D + ADD
//
//   line:   inward = X, SUB = B = |Ye|, ADD = A = |Xe| (constants);
//           ci = x travelled (counts up), co = y travelled (counts up).
//   circle: SUB = 2|c_in| - 1, ADD = 2|c_out| + 1 (kept in registers so the
//           loop holds a single add); ci = |c_in| (counts down),
//           co = |c_out| (counts up); ci and co swap roles when ci reaches 0
//           (a quadrant crossing).
//
// The end-point rule needs "no distance left" on either axis. Those tests
// (ci == ti, co == to) and the ones that tell whether the next step ends the
// move are kept as registered flags, each updated from a comparison of the
// current registers with a per-move constant (ti, ti2, to), so
// no wide comparator sits in the D loop. `ifdef FORMAL` asserts that every
// flag equals the comparison it stands for.
//
// D is kept in two halves with the low half's carry pending (registered,
// added into the high half at the next step), so no D carry chain is wider
// than half of D; D's sign is a register of its own and the resolved D is
// formed on the observe path only (o_d).
//
// A block is loaded when the datapath is idle, or in the very clock that
// issues the last pulse of the running move: consecutive blocks run back to
// back with no idle clock.
//
// Reset: synchronous, active high; it abandons the running move.
`default_nettype none

module interp_dp #(
    parameter integer W = 24  // coordinate magnitude width (2..30)
) (
    input  wire           i_clk,
    input  wire           i_rst,
    // Command: one interpolation step in every clock where it is high.
    input  wire           i_cmd,
    // Prepared block (blk_prep), valid/ready handshake.
    input  wire           i_valid,
    output wire           o_ready,       // block is taken in this clock
    input  wire [7*W+20:0] i_pre,        // [PRE_BITS-1:0], interp_block.vh
    // Output pulse, registered: valid in the clock after the step, together
    // with the state after it.
    output reg            o_pulse,
    output reg            o_pulse_y,     // 0: X, 1: Y
    output reg            o_pulse_neg,   // 1: minus direction
    output reg            o_pulse_last,  // the pulse that ended its move
    // Observable state (docs/algorithm.md, "Observable state").
    output wire           o_busy,        // a move is loaded and not done
    output wire [W-1:0]   o_xmag,
    output wire           o_xneg,
    output wire [W-1:0]   o_ymag,
    output wire           o_yneg,
    output wire [W+1:0]   o_d,
    output wire [1:0]     o_q,
    output wire [2:0]     o_k,
    output wire           o_arc
);

`include "interp_block.vh"

  // The prepared block, field by field (the values a load takes).
  wire l_arc = i_pre[PRE_ARC];
  wire l_cw = i_pre[PRE_CW];
  wire l_sxn = i_pre[PRE_SXN];
  wire l_syn = i_pre[PRE_SYN];
  wire [1:0] l_q = i_pre[PRE_Q +: 2];
  wire [2:0] l_k = i_pre[PRE_K +: 3];
  wire [W-1:0] l_ci = i_pre[PRE_CI +: W];
  wire [W-1:0] l_co = i_pre[PRE_CO +: W];
  wire [W:0] l_sub = i_pre[PRE_SUB +: W + 1];
  wire [W:0] l_add = i_pre[PRE_ADD +: W + 1];
  wire [W-1:0] l_ti = i_pre[PRE_TI +: W];
  wire [W+1:0] l_ti2 = i_pre[PRE_TI2 +: W + 2];
  wire [W-1:0] l_to = i_pre[PRE_TO +: W];
  wire [7:0] l_flags = i_pre[PRE_FLAGS +: 8];

  // Flag bit order of l_flags (blk_prep builds it the same way).
  localparam integer F_IN_EX   = 0;  // ci == ti: inward axis has no distance left
  localparam integer F_OUT_EX  = 1;  // co == to: outward axis has no distance left
  localparam integer F_IN_ONE  = 2;  // ci == ti + 1 (arc) / ti - 1: one inward step left
  localparam integer F_OUT_ONE = 3;  // co == to - 1: one outward step left
  localparam integer F_CI_ONE  = 4;  // ci == 1 (arc): an inward step crosses
  localparam integer F_CO_TI   = 5;  // co == ti (arc): a crossing lands on ti
  localparam integer F_TO_Z    = 6;  // to == 0 (constant per move)
  localparam integer F_TO_ONE  = 7;  // to == 1 (constant per move)

  // ---------------------------------------------------------------- state
  reg           arc_q, cw_q, sxn_q, syn_q;
  reg [1:0]     q_q;
  reg [2:0]     k_q;
  // D in two halves (see "next values"): D = (dh + cp) * 2^DL + dl.
  localparam integer DW = W + 2;   // D's width
  localparam integer DL = DW / 2;  // its low half
  localparam integer DH = DW - DL; // its high half
  reg [DL-1:0]  dl_q;
  reg [DH-1:0]  dh_q, dh1_q;       // dh1 = dh + 1
  reg           cp_q;              // pending carry of the low half
  reg           dneg_q;            // D < 0 (the sign of the resolved D)
  reg [W:0]     nsub_q, add_q;     // nsub = ~SUB
  // The resolved D (the observe path and the formal checks only).
  wire [W+1:0]  d_q = {cp_q ? dh1_q : dh_q, dl_q};
  reg [W-1:0]   ci_q, co_q;
  reg [W-1:0]   ti_q, to_q;        // the inward / outward targets
  reg [W+1:0]   ti2_q;
  reg           in_ex_q, out_ex_q, in_one_q, out_one_q, ci_one_q, co_ti_q;
  reg           to_z_q, to_one_q;

  // ------------------------------------------------------------ decisions
  reg kz_q, k1z_q;                        // k == 0; k == 1 with to == 0 (arc)
  wire kz = kz_q;
  wire d_pos = ~dneg_q;                   // D >= 0
  // Derived flags, registers too (their next values are formed below
  // from the next values of the flags they combine):
  //   done_q  = k == 0 & both axes arrived
  //   lastk_q = k == 0 & one axis arrived, the other one step away
  //   xf_q    = k == 1 & ci == 1 & co == ti & to == 0 (an inward step
  //             crosses onto the end point)
  reg done_q, lastk_q, xf_q;
  wire done = done_q;
  wire busy = ~done;
  wire st = i_cmd & busy;                  // a step happens in this clock

  // D >= 0 chooses the inward axis; in the end quadrant an axis with no
  // distance left hands the pulse to the other one.
  wire inw = kz ? (d_pos ? ~in_ex_q : out_ex_q) : d_pos;
  // An inward step from ci == 1 crosses onto the next quadrant (arcs only;
  // in the end quadrant ci never falls below ti >= 1).
  // (ci_one_q is 0 on a line.)
  // xing_q = ~kz & ci_one, a register of its own (formed with ci_one's
  // next value): it selects wide multiplexers (SUB, ci), so it is one net
  // from a flip-flop, not a LUT after two.
  reg xing_q, xing_sub_q, xing_ci_q;
  wire xing = xing_q;

  // Would this step end the move? In the end quadrant only when one axis
  // has arrived and the other has one step left, and then the end-point
  // rule fixes the axis, so D plays no part; with one crossing left, when
  // an inward step (D >= 0) crosses onto the end point itself.
  wire last = lastk_q | (d_pos & xf_q);

  // The load, ld = valid & (done | st & last), is the decision with the
  // largest fan-out (every register's enable or load multiplexer, the
  // queue's read side), and the command is the late input of the clock. So
  // ld is one LUT after the command: its two other terms are formed from
  // flip-flops alone, and each is kept (a LUT boundary for abc, which
  // would otherwise put the command through the decision's whole depth).
  (* keep *) wire ld_idle = i_valid & done;   // a block waits, none runs
  (* keep *) wire ld_last = i_valid & last;   // a block waits, this step ends the run
  (* keep *) wire ld = ld_idle | (i_cmd & ld_last);
  assign o_ready = ld;

  // The step enables the same way: a register-only term each, the
  // command ANDed in one LUT before the flip-flops' enables.
  wire e_in = busy & inw;                  // ci and the inward flags
  wire e_out = busy & (~inw | xing);       // co and the outward flags
  wire e_x = busy & inw & xing;            // a crossing: q, k

  // Axis of the inward step: X for a line; for an arc X when the quadrant
  // is even XOR clockwise.
  wire in_is_x = arc_q ? (~q_q[0] ^ cw_q) : 1'b1;
  wire pulse_x = (inw == in_is_x);
  // Quadrant signs (Q1..Q4 = 0..3): x < 0 in Q2, Q3; y < 0 in Q3, Q4.
  wire qxn = q_q[0] ^ q_q[1];
  wire qyn = q_q[1];
  // Line: the axis sign. Arc: inward runs against the quadrant sign,
  // outward with it.
  wire pulse_neg = arc_q ? ((pulse_x ? qxn : qyn) ^ inw) : (pulse_x ? sxn_q : syn_q);

  // ------------------------------------------------------- next values
  // D's two halves are added apart: the low half's carry out is kept
  // (cp) and added into the high half at the next step, as its carry in,
  // so no carry chain is wider than DH bits. The high half is kept twice,
  // dh and dh + 1, both stepped with the same operand and carry in: the
  // resolved high half dh + cp is one of the two (a multiplexer on the
  // observe path, o_d), and D's sign, which the step decision reads, is
  // formed beside the chains from the candidates and registered (dneg).
  // SUB is kept inverted (D - SUB = D + ~SUB + 1), so no inverter sits
  // before a chain.
  wire [DW-1:0] nsubx = {1'b1, nsub_q};          // ~{0, SUB}
  wire [DW-1:0] addx = {1'b0, add_q};
  // Low half, DL + 1 bits (the carry out on top); {a, 1} + {b, 1} is
  // a + b + 1 in bits DL+1..1.
  wire [DL+1:0] li_w = {1'b0, dl_q, 1'b1} + {1'b0, nsubx[DL-1:0], 1'b1};
  wire [DL:0] li = li_w[DL+1:1];
  wire [DL:0] lo = {1'b0, dl_q} + {1'b0, addx[DL-1:0]};
  // High half, the pending carry in: {a, c} + {b, c} is a + b + c in
  // bits DH..1.
  wire [DH-1:0] cpx = {{(DH-1){1'b0}}, cp_q};
  wire [DH-1:0] hi0 = dh_q + nsubx[DW-1:DL] + cpx;
  wire [DH-1:0] hi1 = dh1_q + nsubx[DW-1:DL] + cpx;
  wire [DH-1:0] ho0 = dh_q + addx[DW-1:DL] + cpx;
  wire [DH-1:0] ho1 = dh1_q + addx[DW-1:DL] + cpx;
  // Bit 0 of the sum above is 0 (1 + 1): unused.
  wire unused_b0 = li_w[0];
  // The sign of D after the step: of the high half with the new carry.
  wire dneg_in = li[DL] ? hi1[DH-1] : hi0[DH-1];
  wire dneg_out = lo[DL] ? ho1[DH-1] : ho0[DH-1];
  // ci: -1 (arc) or +1 (line) in one carry chain whose operand is a
  // register bit (no up/down multiplexer after two chains). An inward step
  // that crosses has ci = 1, so ci - 1 = 0 and co is ORed in: no crossing
  // multiplexer after the chain either.
  wire [W-1:0] ci_step = ci_q + {{(W-1){arc_q}}, 1'b1};
  wire [W-1:0] ci_xing = co_q & {W{xing_ci_q}};

  // Comparisons of the current registers with per-move constants; they
  // feed only flag registers. The ones with a target one or two off
  // (co == ti + 1, co == ti - 1: arcs only; co == to - 2) are carry-free
  // a + 1 == b tests of the target itself (one 4-input term per bit, then
  // their AND; a + 2 == b: the low bits equal and a + 1 == b above them),
  // so the block carries ti and to (2W bits) rather than ti + 1, ti - 1
  // and to - 2 (3W + 6 bits, three adders in blk_prep; issue 15).
`include "inc_terms.vh"
  wire [W+1:0] ci_x = {2'b00, ci_q};
  wire c_ci_ti2 = (ci_x == ti2_q);
  wire c_co_ti1 = &inc_terms({1'b0, ti_q}, {1'b0, co_q});   // ti + 1 == co
  wire c_co_to2 = (co_q[0] == to_q[0])                      // co + 2 == to
                & (&inc_terms({2'b00, co_q[W-1:1]}, {2'b00, to_q[W-1:1]}));
  wire c_co_tim1 = &inc_terms({1'b0, co_q}, {1'b0, ti_q});  // co + 1 == ti
  wire c_ci_two = (ci_q == 2);
  wire c_co_one = (co_q == 1);
  // ti == 0 is co == ti right after a crossing (co = 0).
  wire ti_z = (ti_q == {W{1'b0}});

  // Clock enables, ld | st & e for a step term e, written
  // ld_idle | i_cmd & (ld_last | e): one LUT after the command, beside ld
  // rather than after it (ld then reaches only the load multiplexers). A
  // register with a reset takes it inside its enable (i_rst is in ldr_idle),
  // the iCE40 flip-flop's own sync reset.
  wire ldr_idle = i_rst | ld_idle;
  wire le_st = ld_last | busy;
  wire le_in = ld_last | e_in;
  wire le_out = ld_last | e_out;
  wire le_x = ld_last | e_x;
  wire ce_st = ld_idle | (i_cmd & le_st);
  wire cer_st = ldr_idle | (i_cmd & le_st);
  wire ce_in = ld_idle | (i_cmd & le_in);
  wire ce_out = ld_idle | (i_cmd & le_out);
  wire cer_x = ldr_idle | (i_cmd & le_x);

  // D: cleared by a load, else one add per step. Not reset: like the
  // magnitudes, it means nothing until a block is loaded (a reset in its
  // clear would put i_rst into the load's fan-out).
  always @(posedge i_clk) begin
    if (ce_st) begin
      if (ld) begin
        dl_q <= {DL{1'b0}};
        dh_q <= {DH{1'b0}};
        dh1_q <= {{(DH-1){1'b0}}, 1'b1};
        cp_q <= 1'b0;
        dneg_q <= 1'b0;
      end else if (inw) begin
        dl_q <= li[DL-1:0];
        cp_q <= li[DL];
        dh_q <= hi0;
        dh1_q <= hi1;
        dneg_q <= dneg_in;
      end else begin
        dl_q <= lo[DL-1:0];
        cp_q <= lo[DL];
        dh_q <= ho0;
        dh1_q <= ho1;
        dneg_q <= dneg_out;
      end
    end
  end

  // SUB = 2|c_in| - 1 (arc) / B (line), kept inverted: ~(x - arc) is
  // ~x + arc.
  always @(posedge i_clk) begin
    if (ce_in) nsub_q[W:1] <= ld ? ~l_sub[W:1] : (xing_sub_q ? ~add_q[W:1] : nsub_q[W:1]) + {{(W-1){1'b0}}, arc_q};
  end

  // Bit 0 of SUB and ADD: a line's constants, 1 throughout an arc (odd
  // values stepped by 2): set by the load alone (no step enable).
  always @(posedge i_clk) begin
    if (ld) begin
      nsub_q[0] <= ~l_sub[0];
      add_q[0] <= l_add[0];
    end
  end

  // ADD = 2|c_out| + 1 (arc) / A (line); 1 after a crossing.
  always @(posedge i_clk) begin
    if (ce_out) add_q[W:1] <= ld ? l_add[W:1] : inw ? {W{1'b0}} : add_q[W:1] + {{(W-1){1'b0}}, arc_q};
  end

  // ci: inward-axis magnitude; takes co's value at a crossing.
  always @(posedge i_clk) begin
    if (ce_in) ci_q <= ld ? l_ci : ci_step | ci_xing;
  end

  // co: outward-axis magnitude; 0 after a crossing.
  always @(posedge i_clk) begin
    if (ce_out) co_q <= ld ? l_co : inw ? {W{1'b0}} : co_q + 1'b1;
  end

  // Quadrant and crossings left; k = 0 with both axes exhausted is "done",
  // which is also the reset state.
  always @(posedge i_clk) begin
    if (cer_x) begin
      if (i_rst) begin
        q_q <= 2'd0;
        k_q <= 3'd0;
        kz_q <= 1'b1;
        k1z_q <= 1'b0;
      end else if (ld) begin
        q_q <= l_q;
        k_q <= l_k;
        kz_q <= (l_k == 3'd0);
        k1z_q <= (l_k == 3'd1) & l_arc & l_flags[F_TO_Z];
      end else begin
        q_q <= cw_q ? q_q - 1'b1 : q_q + 1'b1;
        k_q <= k_q - 1'b1;
        kz_q <= (k_q == 3'd1);
        k1z_q <= (k_q == 3'd2) & to_z_q;
      end
    end
  end

  // Move constants.
  always @(posedge i_clk) begin
    if (ld) begin
      arc_q <= l_arc;
      cw_q <= l_cw;
      sxn_q <= l_sxn;
      syn_q <= l_syn;
      ti_q <= l_ti;
      ti2_q <= l_ti2;
      to_q <= l_to;
      to_z_q <= l_flags[F_TO_Z];
      to_one_q <= l_flags[F_TO_ONE];
    end
  end

  // Inward-axis flags: change on inward steps only. Not reset, like D:
  // they mean nothing until a block is loaded (with done set, nothing
  // reads them), and a reset would put i_rst into their enables.
  always @(posedge i_clk) begin
    if (ce_in) begin
      if (ld) begin
        in_ex_q <= l_flags[F_IN_EX];
        in_one_q <= l_flags[F_IN_ONE];
        ci_one_q <= l_flags[F_CI_ONE];
      end else begin
        in_ex_q <= xing ? co_ti_q : in_one_q;
        in_one_q <= xing ? c_co_ti1 : c_ci_ti2;
        ci_one_q <= arc_q & (xing ? c_co_one : c_ci_two);
      end
    end
  end
  // xing_q and its two copies (kept: yosys would merge them), one per
  // wide multiplexer (SUB's, ci's), so each is a net of ~25 loads
  // rather than one of ~75 (issue 15: xing_q's routing to SUB's
  // multiplexer was on a critical path).
  wire xing_n = ld ? (l_k != 3'd0) & l_flags[F_CI_ONE]
                   : arc_q & (xing ? (k_q != 3'd1) & c_co_one : ~kz & c_ci_two);
  always @(posedge i_clk) begin
    if (ce_in) xing_q <= xing_n;
  end
  (* keep *) always @(posedge i_clk) begin
    if (ce_in) xing_sub_q <= xing_n;
  end
  (* keep *) always @(posedge i_clk) begin
    if (ce_in) xing_ci_q <= xing_n;
  end

  // Outward-axis flags: change on outward steps and at crossings; not
  // reset either.
  always @(posedge i_clk) begin
    if (ce_out) begin
      if (ld) begin
        out_ex_q <= l_flags[F_OUT_EX];
        out_one_q <= l_flags[F_OUT_ONE];
        co_ti_q <= l_flags[F_CO_TI];
      end else begin
        out_ex_q <= ~inw ? out_one_q : to_z_q;      // outward step : crossing
        out_one_q <= ~inw ? c_co_to2 : to_one_q;
        co_ti_q <= ~inw ? c_co_tim1 : ti_z;
      end
    end
  end

  // Derived flags. Load: from the block's flags. Inward step within the
  // quadrant, crossing, outward step: from the flags' next values as the
  // flag registers above form them.
  wire l_kz = (l_k == 3'd0);
  wire l_k1z = (l_k == 3'd1) & l_arc & l_flags[F_TO_Z];
  wire kz_x = (k_q == 3'd1);                     // k after a crossing is 0
  wire k1z_x = (k_q == 3'd2) & to_z_q;
  // Their values after a step: inward within the quadrant, crossing,
  // outward (from flip-flops only; the command enables the registers).
  wire in_stay = inw & ~xing;
  wire done_s = in_stay ? kz & in_one_q & out_ex_q
              : inw ? kz_x & co_ti_q & to_z_q
              : kz & in_ex_q & out_one_q;
  wire lastk_s = in_stay ? kz & ((c_ci_ti2 & out_ex_q) | (in_one_q & out_one_q))
               : inw ? kz_x & ((c_co_ti1 & to_z_q) | (co_ti_q & to_one_q))
               : kz & ((in_one_q & out_one_q) | (in_ex_q & c_co_to2));
  wire xf_s = in_stay ? k1z_q & arc_q & c_ci_two & co_ti_q
            : inw ? k1z_x & c_co_one & ti_z
            : k1z_q & ci_one_q & c_co_tim1;
  // done_q is reset (the idle state); the other two are not (read only
  // while a move runs).
  always @(posedge i_clk) begin
    if (cer_st) begin
      if (i_rst) done_q <= 1'b1;
      else if (ld) done_q <= l_kz & l_flags[F_IN_EX] & l_flags[F_OUT_EX];
      else done_q <= done_s;
    end
  end
  always @(posedge i_clk) begin
    if (ce_st) begin
      if (ld) begin
        lastk_q <= l_kz & ((l_flags[F_IN_ONE] & l_flags[F_OUT_EX]) | (l_flags[F_IN_EX] & l_flags[F_OUT_ONE]));
        xf_q <= l_k1z & l_flags[F_CI_ONE] & l_flags[F_CO_TI];
      end else begin
        lastk_q <= lastk_s;
        xf_q <= xf_s;
      end
    end
  end

  // Output pulse, aligned with the state after the step.
  always @(posedge i_clk) begin
    if (i_rst) begin
      o_pulse <= 1'b0;
      o_pulse_y <= 1'b0;
      o_pulse_neg <= 1'b0;
      o_pulse_last <= 1'b0;
    end else begin
      o_pulse <= st;
      o_pulse_y <= ~pulse_x;
      o_pulse_neg <= pulse_neg;
      o_pulse_last <= st & last;
    end
  end

  // ------------------------------------------------------ observable state
  wire in_x_now = arc_q ? (~q_q[0] ^ cw_q) : 1'b1;
  assign o_busy = busy;
  assign o_xmag = in_x_now ? ci_q : co_q;
  assign o_ymag = in_x_now ? co_q : ci_q;
  assign o_xneg = arc_q ? qxn : sxn_q;
  assign o_yneg = arc_q ? qyn : syn_q;
  assign o_d = d_q;
  assign o_q = q_q;
  assign o_k = k_q;
  assign o_arc = arc_q;

`ifdef FORMAL
  // ------------------------------------------------------------- formal
  // Reference values the flags stand for, and the exact discriminant.
  reg [W+1:0] ti_f, to_f;      // targets
  reg [2*W+3:0] r2_f;          // arc: R^2
  reg [W+3:0] n_f;             // pulses since the load
  reg past_valid_f;
  initial past_valid_f = 1'b0;
  always @(posedge i_clk) past_valid_f <= 1'b1;

  always @(posedge i_clk) begin
    if (ld) begin
      ti_f <= {2'b00, l_ti};
      to_f <= {2'b00, l_to};
      r2_f <= {{(W+4){1'b0}}, l_ci} * {{(W+4){1'b0}}, l_ci} + {{(W+4){1'b0}}, l_co} * {{(W+4){1'b0}}, l_co};
      n_f <= {(W+4){1'b0}};
    end else if (st) begin
      n_f <= n_f + 1'b1;
    end
  end

  wire signed [2*W+5:0] ci_s = $signed({{(W+6){1'b0}}, ci_q});
  wire signed [2*W+5:0] co_s = $signed({{(W+6){1'b0}}, co_q});
  wire signed [2*W+5:0] d_s = {{(W+4){d_q[W+1]}}, d_q};
  wire [W:0] sub_q = ~nsub_q;
  wire signed [2*W+5:0] sub_s = $signed({{(W+5){1'b0}}, sub_q});
  wire signed [2*W+5:0] add_s = $signed({{(W+5){1'b0}}, add_q});
  wire signed [2*W+5:0] r2_s = $signed({2'b00, r2_f});
  wire signed [2*W+5:0] MAXM_S = $signed({{(W+6){1'b0}}, {W{1'b1}}});  // 2^W - 1

  // `loaded_f`: a block has been loaded since reset (before, the
  // registers other than the flags hold no move).
  reg loaded_f;
  initial loaded_f = 1'b0;
  always @(posedge i_clk) begin
    if (i_rst) loaded_f <= 1'b0;
    else if (ld) loaded_f <= 1'b1;
  end

  always @(*) begin
    if (past_valid_f && loaded_f && !i_rst) begin
      // D's halves: dh1 = dh + 1, dneg is the resolved D's sign.
      assert(dh1_q == dh_q + 1'b1);
      assert(dneg_q == d_q[W+1]);
      // Flags equal the comparisons they stand for.
      assert(in_ex_q == ({2'b00, ci_q} == ti_f));
      assert(out_ex_q == ({2'b00, co_q} == to_f));
      assert(in_one_q == ({2'b00, ci_q} == (arc_q ? ti_f + 1'b1 : ti_f - 1'b1)));
      assert(out_one_q == ({2'b00, co_q} == to_f - 1'b1));
      assert(ti2_q == (arc_q ? ti_f + 2'd2 : ti_f - 2'd2));
      assert({2'b00, ti_q} == ti_f && {2'b00, to_q} == to_f);
      assert(to_z_q == (to_f == 0) && to_one_q == (to_f == 1));
      assert(xing_q == (~kz_q & ci_one_q));
      assert(xing_sub_q == xing_q && xing_ci_q == xing_q);
      assert(k_q <= 3'd4);
      assert(kz_q == (k_q == 3'd0));
      assert(done_q == (kz_q & in_ex_q & out_ex_q));
      assert(lastk_q == (kz_q & ((in_one_q & out_ex_q) | (in_ex_q & out_one_q))));
      assert(xf_q == (k1z_q & ci_one_q & co_ti_q));
      assert(k1z_q == (k_q == 3'd1 && arc_q && to_f == 0));
      if (!arc_q) begin
        // Line: D = A*y - B*x, within [-B, A - 1] (or 0 when A = 0), and
        // the distance travelled never passes the end point.
        assert(k_q == 3'd0);
        assert(!ci_one_q);  // xing leaves arc_q out
`ifndef FORMAL_REF_ONLY
        assert(d_s == add_s * co_s - sub_s * ci_s);
`endif
        assert(d_s >= -sub_s && (d_s < add_s || d_q == 0));
        assert({2'b00, ci_q} <= ti_f && {2'b00, co_q} <= to_f);
        assert(ti_f == {1'b0, add_q} && to_f == {1'b0, sub_q});
        // Done within the pulse count: every pulse is one unit of A + B.
        assert({{4{1'b0}}, ci_q} + {{4{1'b0}}, co_q} == n_f);
      end else begin
        // Arc: SUB, ADD track the magnitudes; D = x^2 + y^2 - R^2.
        assert(ci_one_q == (ci_q == 1));
        assert(co_ti_q == ({2'b00, co_q} == ti_f));
        assert(sub_q == {ci_q, 1'b0} - 1'b1);
        assert(add_q == {co_q, 1'b1});
        // |D| <= 2 (2^W - 1) (docs/algorithm.md, "Bounds"): W + 2 bits.
        assert(d_s <= 2 * MAXM_S && d_s >= -2 * MAXM_S);
`ifndef FORMAL_REF_ONLY
        assert(d_s == ci_s * ci_s + co_s * co_s - r2_s);
`endif
        if (k_q == 3'd0) begin
          assert({2'b00, ci_q} >= ti_f);
          assert({2'b00, co_q} <= to_f);
        end
      end
    end
  end

  // At most one unit of motion per clock: the pulse moves exactly one axis
  // by one, and no register changes without a step or a load.
  always @(posedge i_clk) begin
    if (past_valid_f && loaded_f && !$past(i_rst) && !i_rst && !$past(ld) && !$past(st)) begin
      assert(d_q == $past(d_q) && ci_q == $past(ci_q) && co_q == $past(co_q));
      assert(o_pulse == 1'b0);
    end
  end
`endif

endmodule
