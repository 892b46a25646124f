// blk_prep: turns a block as the host writes it (kind, sense, start quadrant
// and crossings from Circular<W>::validate, magnitudes) into the register
// values interp_dp loads: the inward/outward magnitudes, SUB/ADD, the
// per-move comparison constants and the initial flags. Combinational; it
// sits in front of the move queue, so none of it is on the step loop.
//
// Line: XE, YE are |Xe|, |Ye|; SXN, SYN their signs; XS, YS, Q, K unused.
// Arc: |xs|, |ys|, |xe|, |ye| relative to the centre, Q = start quadrant,
// K = quadrant crossings (0..4). The host validates the arc (the hardware
// has no multiplier); an invalid block gives undefined pulses, never a hang
// of the bus.
`default_nettype none

module blk_prep #(
    parameter integer W = 24  // coordinate magnitude width
) (
    input  wire           i_arc,
    input  wire           i_cw,
    input  wire [1:0]     i_q,
    input  wire [2:0]     i_k,
    input  wire [W-1:0]   i_xs,
    input  wire [W-1:0]   i_ys,
    input  wire [W-1:0]   i_xe,
    input  wire [W-1:0]   i_ye,
    output wire [1:0]     o_q,
    output wire [2:0]     o_k,
    output wire [W-1:0]   o_ci,
    output wire [W-1:0]   o_co,
    output wire [W:0]     o_sub,
    output wire [W:0]     o_add,
    output wire [W+1:0]   o_ti1,
    output wire [W+1:0]   o_ti2,
    output wire [W+1:0]   o_tim1,
    output wire [W+1:0]   o_to2,
    output wire [7:0]     o_flags   // interp_dp F_* order
);

  // Inward axis in the start quadrant and in the end quadrant (the end
  // quadrant is K crossings away, so its parity differs by K[0]).
  wire in_x0 = ~i_q[0] ^ i_cw;
  wire in_xe = in_x0 ^ i_k[0];

  wire [W-1:0] cin0 = in_x0 ? i_xs : i_ys;
  wire [W-1:0] cout0 = in_x0 ? i_ys : i_xs;
  wire [W-1:0] e_in = in_xe ? i_xe : i_ye;
  wire [W-1:0] e_out = in_xe ? i_ye : i_xe;

  // Line: inward = X, target A = |Xe| reached counting up from 0.
  // Arc: target |c_in,end| reached counting down from |c_in,start|.
  wire [W+1:0] ti = {2'b00, i_arc ? e_in : i_xe};
  wire [W+1:0] to = {2'b00, i_arc ? e_out : i_ye};
  wire [W-1:0] ci0 = i_arc ? cin0 : {W{1'b0}};
  wire [W-1:0] co0 = i_arc ? cout0 : {W{1'b0}};
  wire [W-1:0] cin0_m1 = cin0 - 1'b1;
  wire [W+1:0] two = {{W{1'b0}}, 2'b10};

  assign o_q = i_arc ? i_q : 2'd0;
  assign o_k = i_arc ? i_k : 3'd0;
  assign o_ci = ci0;
  assign o_co = co0;
  assign o_sub = i_arc ? {cin0_m1, 1'b1} : {1'b0, i_ye};
  assign o_add = i_arc ? {cout0, 1'b1} : {1'b0, i_xe};
  // ti + 1 / ti + 2 (arc: ci counts down to ti), ti - 1 / ti - 2 (line).
  wire [W+1:0] d1 = i_arc ? {{(W+1){1'b0}}, 1'b1} : {(W+2){1'b1}};
  wire [W+1:0] d2 = i_arc ? two : {{(W+1){1'b1}}, 1'b0};
  assign o_ti1 = ti + d1;
  assign o_ti2 = ti + d2;
  assign o_tim1 = ti - 1'b1;
  assign o_to2 = to - two;

  wire [W+1:0] ci0_x = {2'b00, ci0};
  wire [W+1:0] co0_x = {2'b00, co0};
  assign o_flags[0] = (ci0_x == ti);               // F_IN_EX
  assign o_flags[1] = (co0_x == to);               // F_OUT_EX
  assign o_flags[2] = (ci0_x == o_ti1);            // F_IN_ONE
  assign o_flags[3] = (co0_x + 1'b1 == to);        // F_OUT_ONE
  assign o_flags[4] = i_arc & (ci0 == 1);          // F_CI_ONE
  assign o_flags[5] = (co0_x == ti);               // F_CO_TI
  assign o_flags[6] = (to == 0);                   // F_TO_Z
  assign o_flags[7] = (to == 1);                   // F_TO_ONE

endmodule
