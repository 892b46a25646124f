// blk_prep: turns a block as the host writes it (kind, sense, start quadrant
// and crossings from Circular<W>::validate, magnitudes) into the register
// values interp_dp loads: the inward/outward magnitudes, SUB/ADD, the
// per-move comparison constants and the initial flags.
//
// Two pipeline stages, so that no path is longer than a multiplexer, an
// adder or a comparator: stage 1 (the clock after i_push) selects the
// inward/outward magnitudes and the targets; stage 2 forms SUB, ADD and
// the constants and carries stage 1 along; the output (o_wr high for one
// clock, two clocks after i_push) adds the flags, compared from stage 2.
// A block may be pushed in every clock.
//
// Line: XE, YE are |Xe|, |Ye|; SXN, SYN their signs; XS, YS, Q, K unused.
// Arc: |xs|, |ys|, |xe|, |ye| relative to the centre, Q = start quadrant,
// K = quadrant crossings (0..4). The host validates the arc (the hardware
// has no multiplier); an invalid block gives undefined pulses.
`default_nettype none

module blk_prep #(
    parameter integer W = 24  // coordinate magnitude width
) (
    input  wire           i_clk,
    input  wire           i_rst,
    input  wire           i_push,
    input  wire [4*W+8:0] i_blk,      // the host's block: [BLK_BITS-1:0], interp_block.vh
    output wire [1:0]     o_inflight, // pushes not yet written (0..2)
    output wire           o_wr,       // the prepared block is valid
    output wire [8*W+26:0] o_pre      // the prepared block: [PRE_BITS-1:0], interp_block.vh
);

`include "interp_block.vh"

  // The host's block, field by field.
  wire arc = i_blk[BLK_ARC];
  wire cw = i_blk[BLK_CW];
  wire sxn = i_blk[BLK_SXN];
  wire syn = i_blk[BLK_SYN];
  wire [1:0] q = i_blk[BLK_Q +: 2];
  wire [2:0] k = i_blk[BLK_K +: 3];
  wire [W-1:0] xs = i_blk[BLK_XS +: W];
  wire [W-1:0] ys = i_blk[BLK_YS +: W];
  wire [W-1:0] xe = i_blk[BLK_XE +: W];
  wire [W-1:0] ye = i_blk[BLK_YE +: W];

  // ------------------------------------------------------------- stage 1
  // Inward axis in the start quadrant and in the end quadrant (K crossings
  // away, so its parity differs by K[0]).
  wire in_x0 = ~q[0] ^ cw;
  wire in_xe = in_x0 ^ k[0];

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
      ci1_q <= arc ? (in_x0 ? xs : ys) : {W{1'b0}};
      co1_q <= arc ? (in_x0 ? ys : xs) : {W{1'b0}};
      ti1s_q <= arc ? (in_xe ? xe : ye) : xe;
      to1s_q <= arc ? (in_xe ? ye : xe) : ye;
    end
  end

  // ------------------------------------------------------------- stage 2
  wire [W+1:0] ti = {2'b00, ti1s_q};
  wire [W+1:0] to = {2'b00, to1s_q};
  wire [W+1:0] two = {{W{1'b0}}, 2'b10};
  // Line: ci counts up to ti; arc: down to it.
  wire [W+1:0] d1 = arc1_q ? {{(W+1){1'b0}}, 1'b1} : {(W+2){1'b1}};
  wire [W+1:0] d2 = arc1_q ? two : {{(W+1){1'b1}}, 1'b0};

  reg v2_q;
  reg [W:0] sub2_q, add2_q;
  reg [W+1:0] ti1_q, ti2_q, tim1_q, to1_q, to2_q;
  reg [W-1:0] cim1_q;         // ci - 1
  reg arc2_q, cw2_q, sxn2_q, syn2_q;
  reg [1:0] q2_q;
  reg [2:0] k2_q;
  reg [W-1:0] ci2_q, co2_q, ti2s_q, to2s_q;

  always @(posedge i_clk) begin
    if (i_rst) v2_q <= 1'b0;
    else v2_q <= v1_q;
  end

  always @(posedge i_clk) begin
    if (v1_q) begin
      cim1_q <= ci1_q - 1'b1;
      sub2_q <= arc1_q ? {ci1_q - 1'b1, 1'b1} : {1'b0, to1s_q};
      add2_q <= arc1_q ? {co1_q, 1'b1} : {1'b0, ti1s_q};
      ti1_q <= ti + d1;
      ti2_q <= ti + d2;
      tim1_q <= ti - 1'b1;
      to1_q <= to - 1'b1;
      to2_q <= to - two;
      arc2_q <= arc1_q;
      cw2_q <= cw1_q;
      sxn2_q <= sxn1_q;
      syn2_q <= syn1_q;
      q2_q <= q1_q;
      k2_q <= k1_q;
      ci2_q <= ci1_q;
      co2_q <= co1_q;
      ti2s_q <= ti1s_q;
      to2s_q <= to1s_q;
    end
  end

  // -------------------------------------------------------------- output
  assign o_inflight = {1'b0, v1_q} + {1'b0, v2_q};
  assign o_wr = v2_q;
  assign o_pre[PRE_ARC] = arc2_q;
  assign o_pre[PRE_CW] = cw2_q;
  assign o_pre[PRE_SXN] = sxn2_q;
  assign o_pre[PRE_SYN] = syn2_q;
  assign o_pre[PRE_Q +: 2] = q2_q;
  assign o_pre[PRE_K +: 3] = k2_q;
  assign o_pre[PRE_CI +: W] = ci2_q;
  assign o_pre[PRE_CO +: W] = co2_q;
  assign o_pre[PRE_SUB +: W + 1] = sub2_q;
  assign o_pre[PRE_ADD +: W + 1] = add2_q;
  assign o_pre[PRE_TI1 +: W + 2] = ti1_q;
  assign o_pre[PRE_TI2 +: W + 2] = ti2_q;
  assign o_pre[PRE_TIM1 +: W + 2] = tim1_q;
  assign o_pre[PRE_TO2 +: W + 2] = to2_q;

  // ci == ti1: arc, ci - 1 == ti; line, 0 == A - 1.
  wire in_one = arc2_q ? (cim1_q == ti2s_q) : (ti2s_q == 1);
  wire [7:0] flags;                                     // interp_dp F_* order
  assign o_pre[PRE_FLAGS +: 8] = flags;
  assign flags[0] = (ci2_q == ti2s_q);                // F_IN_EX
  assign flags[1] = (co2_q == to2s_q);                // F_OUT_EX
  assign flags[2] = in_one;                           // F_IN_ONE
  assign flags[3] = ({2'b00, co2_q} == to1_q);        // F_OUT_ONE
  assign flags[4] = arc2_q & (ci2_q == 1);            // F_CI_ONE
  assign flags[5] = (co2_q == ti2s_q);                // F_CO_TI
  assign flags[6] = (to2s_q == 0);                    // F_TO_Z
  assign flags[7] = (to2s_q == 1);                    // F_TO_ONE

endmodule
