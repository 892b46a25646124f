// blk_prep: turns a block as the host writes it (kind, sense, start quadrant
// and crossings from Circular<W>::validate, magnitudes) into the register
// values interp_dp loads: the inward/outward magnitudes, SUB/ADD, the
// per-move comparison constants and the initial flags.
//
// One pipeline stage, so that no path is longer than a multiplexer, or an
// adder, or a comparator: the early fields of the prepared block (kind,
// sense, signs, q, k, ci, co, ti, to: the host's fields as they are, and
// ADD, a multiplexer) are the host's block
// itself, valid with i_push (o_wr = i_push: the queue writes them in the
// push clock); the late fields (SUB, the comparison constants, the
// flags: an adder or a comparator each) are registered from i_blk in
// the push clock and valid in the clock after it (o_wr_late). The queue
// stores the two parts a clock apart (interp_core). No flip-flop holds a
// copy of the host's block (before: a stage 1 of ~105 flip-flops, one LC
// each), and i_blk need not be held after i_push.
// A block may be pushed in every clock.
//
// Line: TI, TO are |Xe|, |Ye|; SXN, SYN their signs; CI, CO, Q, K must be
// 0 (a line's ci counts up from 0; interp_top's wb_regs zeroes them, and
// the harnesses' hosts write them so). Arc: SXN, SYN must be 0.
// Arc: the magnitudes relative to the centre in inward/outward order (the
// host's choice, contour::inout_order in model/interp/hw_order.hpp):
// CI, CO the start's on the start quadrant's inward and outward axes, TI,
// TO the end's on the end quadrant's; Q = start quadrant, K = quadrant
// crossings (0..4). The host validates the arc (the hardware has no
// multiplier); an invalid block gives undefined pulses.
`default_nettype none

module blk_prep #(
    parameter integer W = 24  // coordinate magnitude width
) (
    input  wire           i_clk,
    input  wire           i_rst,
    input  wire           i_push,
    input  wire [4*W+8:0] i_blk,      // the host's block: [BLK_BITS-1:0], interp_block.vh
    output wire           o_wr,       // the early fields of o_pre are valid (i_push itself)
    output wire           o_wr_late,  // the late fields are valid (the clock after i_push)
    output wire [7*W+20:0] o_pre      // the prepared block: [PRE_BITS-1:0], interp_block.vh
);

`include "interp_block.vh"

  // The host's block, field by field.
  wire arc = i_blk[BLK_ARC];
  wire cw = i_blk[BLK_CW];
  wire sxn = i_blk[BLK_SXN];
  wire syn = i_blk[BLK_SYN];
  wire [1:0] q = i_blk[BLK_Q +: 2];
  wire [2:0] k = i_blk[BLK_K +: 3];
  wire [W-1:0] h_ci = i_blk[BLK_CI +: W];
  wire [W-1:0] h_co = i_blk[BLK_CO +: W];
  wire [W-1:0] h_ti = i_blk[BLK_TI +: W];
  wire [W-1:0] h_to = i_blk[BLK_TO +: W];

  // ------------------------------------------------------ register stage
  // The fields with an adder or a comparator: SUB, the per-move constants
  // and the flags, registered from i_blk in the push clock (valid in the
  // clock after it, o_wr_late). The two flags that compare
  // with a value one off (ci - 1 == ti, co == to - 1) use inc_terms below,
  // so no adder sits before their comparators. A line's start is 0, so
  // the comparisons with ci, co hold for it as they are.
  wire [W+1:0] ti = {2'b00, h_ti};
  wire [W+1:0] two = {{W{1'b0}}, 2'b10};
  // Line: ci counts up to ti; arc: down to it.
  wire [W+1:0] d2 = arc ? two : {{(W+1){1'b1}}, 1'b0};

`include "inc_terms.vh"
  // The terms are kept (LUT boundaries): one LUT level, then the AND.
  // ci - 1 == ti in W bits (ci - 1 wraps at ci = 0 as the W-bit value
  // does): ti + 1 == ci modulo 2^W, the test of the two shifted up one bit
  // ({ti, 1} + 1 = {ti + 1, 0}). co == to - 1: co + 1 == to.
  (* keep *) wire [W:0] t_in_one = inc_terms({h_ti, 1'b1}, {h_ci, 1'b0});
  (* keep *) wire [W:0] t_out_one = inc_terms({1'b0, h_co}, {1'b0, h_to});

  reg v2_q;
  reg [W:0] sub2_q;
  reg [W+1:0] ti2_q;
  reg [7:0] flags2_q;                                    // interp_dp F_* order

  always @(posedge i_clk) begin
    if (i_rst) v2_q <= 1'b0;
    else v2_q <= i_push;
  end

  // Loaded in the push clock (an enable, not a free-running register: 13
  // LCs fewer and a better placement, core_hx8k seeds 1-5, docs/rtl.md).
  always @(posedge i_clk) begin
    if (i_push) begin
      sub2_q <= arc ? {h_ci - 1'b1, 1'b1} : {1'b0, h_to};
      ti2_q <= ti + d2;
      flags2_q[0] <= (h_ci == h_ti);                     // F_IN_EX
      flags2_q[1] <= (h_co == h_to);                     // F_OUT_EX
      flags2_q[2] <= arc ? &t_in_one : (h_ti == 1);      // F_IN_ONE: ci == ti1 (line: 0 == A - 1)
      flags2_q[3] <= &t_out_one;                         // F_OUT_ONE: co == to - 1
      flags2_q[4] <= (h_ci == 1);                        // F_CI_ONE (line: ci = 0)
      flags2_q[5] <= (h_co == h_ti);                     // F_CO_TI
      flags2_q[6] <= (h_to == 0);                        // F_TO_Z
      flags2_q[7] <= (h_to == 1);                        // F_TO_ONE
    end
  end

  // -------------------------------------------------------------- output
  // Early fields (o_wr, the push clock): the host's block (the targets
  // ti, to as they are) and ADD, a multiplexer.
  assign o_wr = i_push;
  assign o_pre[PRE_ARC] = arc;
  assign o_pre[PRE_CW] = cw;
  assign o_pre[PRE_SXN] = sxn;
  assign o_pre[PRE_SYN] = syn;
  assign o_pre[PRE_Q +: 2] = q;
  assign o_pre[PRE_K +: 3] = k;
  assign o_pre[PRE_CI +: W] = h_ci;
  assign o_pre[PRE_CO +: W] = h_co;
  assign o_pre[PRE_ADD +: W + 1] = arc ? {h_co, 1'b1} : {1'b0, h_ti};
  assign o_pre[PRE_TI +: W] = h_ti;
  assign o_pre[PRE_TO +: W] = h_to;
  // Late fields (o_wr_late): the register stage.
  assign o_wr_late = v2_q;
  assign o_pre[PRE_SUB +: W + 1] = sub2_q;
  assign o_pre[PRE_TI2 +: W + 2] = ti2_q;
  assign o_pre[PRE_FLAGS +: 8] = flags2_q;

endmodule
