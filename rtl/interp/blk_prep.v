// blk_prep: turns a block as the host writes it (kind, sense, start quadrant
// and crossings from Circular<W>::validate, magnitudes) into the register
// values interp_dp loads: the inward/outward magnitudes, SUB/ADD, the
// per-move comparison constants and the initial flags.
//
// Two pipeline stages, so that no path is longer than a multiplexer, or an
// adder, or a comparator: stage 1 (the clock after i_push, o_wr) selects
// the inward/outward magnitudes and the targets, and gives the early
// fields of the prepared block (kind, sense, signs, q, k, ci, co, ADD, ti, to);
// stage 2 (the clock after, o_wr_late) forms the late fields from stage
// 1: SUB, the comparison constants and the flags. The queue stores the
// two parts a clock apart (interp_core), so no field is carried through
// a stage it does not need.
// A block may be pushed in every clock.
//
// Line: TI, TO are |Xe|, |Ye|; SXN, SYN their signs; CI, CO, Q, K unused.
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
    output wire           o_wr,       // the early fields of o_pre are valid (the clock after i_push)
    output wire           o_wr_late,  // the late fields are valid (the clock after o_wr)
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

  // ------------------------------------------------------------- stage 1

  reg v1_q;
  reg arc1_q, cw1_q, sxn1_q, syn1_q;
  reg [1:0] q1_q;
  reg [2:0] k1_q;
  reg [W-1:0] ci1_q, co1_q;   // start magnitudes (line: 0, 0)
  reg [W-1:0] ti1s_q, to1s_q; // targets (line: A, B; arc: end magnitudes)

  always @(posedge i_clk) begin
    if (i_rst) v1_q <= 1'b0;
    else v1_q <= i_push;
  end

  always @(posedge i_clk) begin
    if (i_push) begin
      arc1_q <= arc;
      cw1_q <= cw;
      sxn1_q <= sxn & ~arc;
      syn1_q <= syn & ~arc;
      q1_q <= arc ? q : 2'd0;
      k1_q <= arc ? k : 3'd0;
      ci1_q <= arc ? h_ci : {W{1'b0}};
      co1_q <= arc ? h_co : {W{1'b0}};
      ti1s_q <= h_ti;
      to1s_q <= h_to;
    end
  end

  // ------------------------------------------------------------- stage 2
  // The fields with an adder or a comparator: SUB, the per-move constants
  // and the flags, registered from stage 1 (o_wr_late, the clock after
  // o_wr). The two flags that compare with a value one off (ci - 1 == ti,
  // co == to - 1) use inc_terms below, so no adder sits before their
  // comparators.
  wire [W+1:0] ti = {2'b00, ti1s_q};
  wire [W+1:0] two = {{W{1'b0}}, 2'b10};
  // Line: ci counts up to ti; arc: down to it.
  wire [W+1:0] d2 = arc1_q ? two : {{(W+1){1'b1}}, 1'b0};

`include "inc_terms.vh"
  // The terms are kept (LUT boundaries): one LUT level, then the AND.
  // ci - 1 == ti in W bits (ci - 1 wraps at ci = 0 as the W-bit value
  // does): ti + 1 == ci modulo 2^W, the test of the two shifted up one bit
  // ({ti, 1} + 1 = {ti + 1, 0}). co == to - 1: co + 1 == to.
  (* keep *) wire [W:0] t_in_one = inc_terms({ti1s_q, 1'b1}, {ci1_q, 1'b0});
  (* keep *) wire [W:0] t_out_one = inc_terms({1'b0, co1_q}, {1'b0, to1s_q});

  reg v2_q;
  reg [W:0] sub2_q;
  reg [W+1:0] ti2_q;
  reg [7:0] flags2_q;                                    // interp_dp F_* order

  always @(posedge i_clk) begin
    if (i_rst) v2_q <= 1'b0;
    else v2_q <= v1_q;
  end

  always @(posedge i_clk) begin
    if (v1_q) begin
      sub2_q <= arc1_q ? {ci1_q - 1'b1, 1'b1} : {1'b0, to1s_q};
      ti2_q <= ti + d2;
      flags2_q[0] <= (ci1_q == ti1s_q);                    // F_IN_EX
      flags2_q[1] <= (co1_q == to1s_q);                    // F_OUT_EX
      flags2_q[2] <= arc1_q ? &t_in_one : (ti1s_q == 1);   // F_IN_ONE: ci == ti1 (line: 0 == A - 1)
      flags2_q[3] <= &t_out_one;                           // F_OUT_ONE: co == to - 1
      flags2_q[4] <= arc1_q & (ci1_q == 1);                // F_CI_ONE
      flags2_q[5] <= (co1_q == ti1s_q);                    // F_CO_TI
      flags2_q[6] <= (to1s_q == 0);                        // F_TO_Z
      flags2_q[7] <= (to1s_q == 1);                        // F_TO_ONE
    end
  end

  // -------------------------------------------------------------- output
  // Early fields (o_wr): stage 1 (the targets ti, to as they are) and ADD,
  // a multiplexer after it.
  assign o_wr = v1_q;
  assign o_pre[PRE_ARC] = arc1_q;
  assign o_pre[PRE_CW] = cw1_q;
  assign o_pre[PRE_SXN] = sxn1_q;
  assign o_pre[PRE_SYN] = syn1_q;
  assign o_pre[PRE_Q +: 2] = q1_q;
  assign o_pre[PRE_K +: 3] = k1_q;
  assign o_pre[PRE_CI +: W] = ci1_q;
  assign o_pre[PRE_CO +: W] = co1_q;
  assign o_pre[PRE_ADD +: W + 1] = arc1_q ? {co1_q, 1'b1} : {1'b0, ti1s_q};
  assign o_pre[PRE_TI +: W] = ti1s_q;
  assign o_pre[PRE_TO +: W] = to1s_q;
  // Late fields (o_wr_late): stage 2.
  assign o_wr_late = v2_q;
  assign o_pre[PRE_SUB +: W + 1] = sub2_q;
  assign o_pre[PRE_TI2 +: W + 2] = ti2_q;
  assign o_pre[PRE_FLAGS +: 8] = flags2_q;

endmodule
