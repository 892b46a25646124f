// interp3_core: paper A's reference-pulse linear interpolator extended to
// three axes (X, Y, Z), one interpolation step per clock.
//
// Executes the contract of docs/algorithm.md, "Linear on three axes"; the golden model is
// contour::Linear3<W> (model/interp/linear3.hpp). The discriminants
//
//   exy = a(2y+1) - b(2x+1), exz = a(2z+1) - c(2x+1), eyz = b(2z+1) - c(2y+1)
//
// change by even amounts only (-2b, +2a, ...), so each is kept as its low
// bit e0 (constant during a move) and its "half" h = (e - e0) / 2 (W + 1
// bits, two's complement; the sign of h is the sign of e).
//
// Built for the clock (docs/rtl-3axis.md, "Timing structure"): no decision
// is computed in the clock that uses it; in front of each adder sits one
// 2:1 multiplexer whose select is a register, behind it the choice of a
// carry-select adder:
//
//   s_q         the axis of the next step, one-hot {Z, Y, X}, a register:
//               computed in the clock before from registered bits only
//   c1, c2      per discriminant, its two candidates: the half after a
//               step on each of the two axes that change it
//               (exy: X -> h - b, Y -> h + a; exz: X -> h - c, Z -> h + a;
//               eyz: Y -> h - c, Z -> h + b)
//   step        m = the candidate s_q picks (the new h); h <= m,
//               c1 <= m + op1, c2 <= m + op2: one mux, one adder
//               (carry-select); the selects are copied per 8 bits; the
//               step enables are one LUT of i_cmd, act_q and s_q
//   selection   s_q's next value from the sign bits of the candidates and
//               halves (registers), chosen by s_q: two LUT levels
//               (the contract's rule reduced to the signs, proved below)
//   flags       r = (x < a); l = (x + 1 == a), the next X step is the last,
//               kept by comparing x with a - 2 (a register) when X steps
//
// Timing: i_load in a clock (edge L0) takes the move, with priority over
// i_cmd; it may abandon a running move. The core then prepares it for three
// clocks (edges L1: -b, -c, the initial halves; L2: the candidates take the
// initial half; L3: the half, the candidates, s_q) with o_ready low and
// takes its first command at edge L4 at the earliest: a command while
// o_ready is low is ignored. In
// every clock with o_ready high, i_cmd high and the move not done, one axis
// steps. Outputs are registered: o_step_* is high for the one clock after
// the step, together with the state after it (the model's "state read after
// the pulse is the state after the move"). o_done is valid from the clock
// after the load; the state outputs once o_ready is high.
//
// Reset: synchronous, active high. Every register but the six candidate
// registers is reset (to the state of the zero move, which is done and
// ready); the candidates are read only after a load has prepared them.
`default_nettype none

module interp3_core #(
    parameter integer W = 24  // coordinate magnitude width (2..30)
) (
    input  wire           i_clk,
    input  wire           i_rst,
    // Move: magnitudes and signs of the end point relative to the start.
    input  wire           i_load,   // load the move in this clock
    input  wire [W-1:0]   i_xe,     // |XE|
    input  wire [W-1:0]   i_ye,     // |YE|
    input  wire [W-1:0]   i_ze,     // |ZE|
    input  wire           i_xneg,   // XE < 0
    input  wire           i_yneg,   // YE < 0
    input  wire           i_zneg,   // ZE < 0
    // Command: one interpolation step in every clock where it is high
    // (and o_ready is high).
    input  wire           i_cmd,
    // Output pulse, registered: high in the clock after the step.
    output reg            o_step_x,
    output reg            o_step_y,
    output reg            o_step_z,
    output wire           o_dir_x,  // 1: minus direction (constant per move)
    output wire           o_dir_y,
    output wire           o_dir_z,
    output wire           o_done,   // the move has reached its end point
    output wire           o_ready,  // the loaded move is prepared: commands are taken
    // Observable state (docs/algorithm.md, "Linear on three axes", State3): magnitudes.
    output wire [W-1:0]   o_x,
    output wire [W-1:0]   o_y,
    output wire [W-1:0]   o_z,
    output wire [W+1:0]   o_exy,
    output wire [W+1:0]   o_exz,
    output wire [W+1:0]   o_eyz
);

  // Illegal widths stop elaboration: the instance names the rule.
  generate
    if (W < 2 || W > 30) begin : g_bad_width
      interp3_core_parameter_W_must_be_2_to_30 u_bad ();
    end
  endgenerate

  localparam integer HW = W + 1;  // width of a discriminant's half
  localparam integer K = HW / 2;  // low part of the split adders (12 of 25 bits)
  localparam integer DW = HW + 1;  // a sum in split form: {high, pending carry, low}

  // A sum in split form d = {H, k, L} (H: HW - K bits, k: 1, L: K) stands
  // for ((H + k) << K) + L (mod 2^HW): the carry out of the low part is
  // kept as k and added to the high part by the next addition, so that
  // neither chain waits for the other. d + o + ci in split form: two
  // short chains, each fed by registers only (ci and k are their carry-ins).
  function automatic [DW-1:0] sadd(input [DW-1:0] d, input [HW-1:0] o, input ci);
    reg [K:0] lo;
    reg [HW-K-1:0] hi;
    begin
      lo = {1'b0, d[K-1:0]} + {1'b0, o[K-1:0]} + {{K{1'b0}}, ci};
      hi = d[DW-1:K+1] + o[HW-1:K] + {{(HW - K - 1) {1'b0}}, d[K]};
      sadd = {hi, lo};
    end
  endfunction
  // The value of a sum in split form: H + k (a chain fed by registers).
  function automatic [HW-1:0] sval(input [DW-1:0] d);
    reg [HW-K-1:0] hi;
    begin
      hi = d[DW-1:K+1] + {{(HW - K - 1) {1'b0}}, d[K]};
      sval = {hi, d[K-1:0]};
    end
  endfunction

  // ------------------------------------------------------------ registers
  // Move constants, taken at the load (L0).
  reg [W-1:0] a_q, b_q;               // |XE|, |YE|
  reg [W-1:0] nbz_q, ncz_q;           // ~|YE|, ~|ZE|
  reg xneg_q, yneg_q, zneg_q;
  reg [W-1:0] am2_q, bm2_q, cm2_q;    // a - 2, b - 2, c - 2 (mod 2^W)
  reg e0xy_q, e0xz_q, e0yz_q;         // low bits of the discriminants
  // The adders' operands: from L2 on a, b, ~b, ~c (-b = ~b + 1: the
  // carry-ins ci*_q are 1); in the clocks after L0 and L1 the halves
  // a >> 1, b >> 1, ~(b >> 1), ~(c >> 1) and the carry-ins that make
  // a' + ~b' + ci the initial half (a - b - e0) / 2.
  reg [HW-1:0] oa_q, ob_q, onb_q, onc_q;
  reg [HW-1:0] oa2_q, onc2_q;          // copies for exz (against fan-out)
  reg cixy_q, cixz_q, ciyz_q;
  // Load phases: p1_q after L0, p2_q after L1, p3_q after L2, p4_q after
  // L3; ldph_q any, pre_q = p1 | p2 | p3; f22_q = p1 | p3 | p4 (the
  // third sums take op2).
  reg p1_q, p2_q, p3_q, p4_q, ldph_q, pre_q, f22_q;
  // Interpolation state.
  reg [W-1:0] x_q, y_q, z_q;          // distance travelled
  reg lded_q;                         // a move was loaded since the reset
  reg rx_q, ry_q, rz_q;               // distance left: x < a
  reg lx_q, ly_q, lz_q;               // last step: x + 1 == a
  reg [HW-1:0] hxy_q, hxz_q, hyz_q;   // halves of exy, exz, eyz
  // Per discriminant, with op1, op2 its two updates (exy: -b on X, +a
  // on Y; exz: -c on X, +a on Z; eyz: -c on Y, +b on Z):
  //   c1 = h + op1, c2 = h + op2                the candidates
  //   d11 = h + 2 op1, d12 = h + op1 + op2, d22 = h + 2 op2   (split form)
  reg [HW-1:0] cxy1_q, cxy2_q, cxz1_q, cxz2_q, cyz1_q, cyz2_q;
  reg [DW-1:0] dxy11_q, dxy12_q, dxy22_q;
  reg [DW-1:0] dxz11_q, dxz12_q, dxz22_q;
  reg [DW-1:0] dyz11_q, dyz12_q, dyz22_q;
  reg [2:0] s_q;                      // next step {Z, Y, X}; 000 while loading
  // The multiplexers' selects per discriminant: the next step is its op1
  // (X, X, Y: s_q's bit); 1 while loading. The set conditions differ
  // (by terms that never hold) so that synthesis keeps them apart.
  reg gxy_q, gxz_q, gyz_q;
  reg gz_q;                           // s_q's Z bit, 1 while loading (the selection's)
  reg ox_q, oy_q, oz_q;               // no distance left on the other two axes: ~ry & ~rz ...
  reg fx_q, fy_q, fz_q;               // a step on X ends the move: lx & ox ...
  reg act_q;                          // ready and not done
  // Registered step enables: the axis that steps on a command (act_q and
  // s_q), and whether a command changes each discriminant.
  reg mx_q, my_q, mz_q;
  reg kxy_q, kxz_q, kyz_q;
  reg kdxy_q, kdxz_q, kdyz_q;         // copies for the d's enables (below)

  wire sx = s_q[0];
  wire sy = s_q[1];
  wire sz = s_q[2];
  // A step in this clock (a load in the same clock wins: every register a
  // step changes is set by the load, or prepared again after it).
  wire go = i_cmd & act_q;
  wire mv_x = i_cmd & mx_q;
  wire mv_y = i_cmd & my_q;
  wire mv_z = i_cmd & mz_q;

  // ------------------------------------------------------------- datapath
  // A step on op1 (g = 1): h <= c1, c1 <= d11, c2 <= d12 and every d
  // plus op1; on op2: h <= c2, c1 <= d12, c2 <= d22 and every d plus
  // op2. d11 + op2 = d12 + op1 and d12 + op2 = d22 + op1, so four sums
  // per discriminant, each d and operand a register, the choice after
  // them by a registered select:
  //   d11 <= g ? d11 + op1 : d11 + op2
  //   d12 <= g ? d11 + op2 : d22 + op1
  //   d22 <= g ? d22 + op1 : d22 + op2
  // Preparing (docs/rtl-3axis.md, "Timing"), g = 1 and the d are 0 from
  // L0: d11 takes op1 at L1, op2 at L2 (p2_q), d22 op2 at L1, L3, L4
  // (f22_q) and op1 at L2; the operands are the halves until L2, so that
  // d11, d12, d22 are the initial half after L2, and the state is
  // prepared after L4.
  wire [HW-1:0] o1xy = onb_q, o2xy = oa_q;
  wire [HW-1:0] o1xz = onc2_q, o2xz = oa2_q;
  wire [HW-1:0] o1yz = onc_q, o2yz = ob_q;
  wire [DW-1:0] sxy1 = sadd(dxy11_q, o1xy, cixy_q), sxy2 = sadd(dxy11_q, o2xy, 1'b0);
  wire [DW-1:0] sxy3 = sadd(dxy22_q, o1xy, cixy_q), sxy4 = sadd(dxy22_q, o2xy, 1'b0);
  wire [DW-1:0] sxz1 = sadd(dxz11_q, o1xz, cixz_q), sxz2 = sadd(dxz11_q, o2xz, 1'b0);
  wire [DW-1:0] sxz3 = sadd(dxz22_q, o1xz, cixz_q), sxz4 = sadd(dxz22_q, o2xz, 1'b0);
  wire [DW-1:0] syz1 = sadd(dyz11_q, o1yz, ciyz_q), syz2 = sadd(dyz11_q, o2yz, 1'b0);
  wire [DW-1:0] syz3 = sadd(dyz22_q, o1yz, ciyz_q), syz4 = sadd(dyz22_q, o2yz, 1'b0);
  // The values of the d (the next candidates).
  wire [HW-1:0] vxy11 = sval(dxy11_q), vxy12 = sval(dxy12_q), vxy22 = sval(dxy22_q);
  wire [HW-1:0] vxz11 = sval(dxz11_q), vxz12 = sval(dxz12_q), vxz22 = sval(dxz22_q);
  wire [HW-1:0] vyz11 = sval(dyz11_q), vyz12 = sval(dyz12_q), vyz22 = sval(dyz22_q);
  // Which discriminants change in this clock (s_q is one-hot when act_q).
  // Each is one LUT of i_cmd: the halves and candidates are also enabled
  // by the reset (the halves' reset value is 0), the d by the load that
  // clears them, each group from its own copy of k, so that synthesis
  // does not form one enable from the other (two LUT levels).
  wire en_xy = i_rst | ldph_q | (i_cmd & kxy_q);
  wire en_xz = i_rst | ldph_q | (i_cmd & kxz_q);
  wire en_yz = i_rst | ldph_q | (i_cmd & kyz_q);
  wire end_xy = i_load | ldph_q | (i_cmd & kdxy_q);
  wire end_xz = i_load | ldph_q | (i_cmd & kdxz_q);
  wire end_yz = i_load | ldph_q | (i_cmd & kdyz_q);

  // ------------------------------------------------------------ selection
  // While the move is not done, the contract's selection is a function of
  // the discriminants' signs alone (docs/rtl-3axis.md, "The selection from
  // the signs"; proved below):
  //   X  if exy >= 0 and exz >= 0
  //   Y  if exy < 0 and eyz >= 0
  //   Z  if exz < 0 and eyz < 0
  // (an axis with no distance left makes the discriminants that name it
  // take the sign that excludes it). The next selection is that of the
  // state after this clock's step: with s_q one-hot, for each axis s_q may
  // name, the signs of the candidates that step makes the new halves, and
  // the halves it leaves alone; in the clock after L3 (p4_q, s_q = 000) the
  // initial halves, which are then both candidates of each discriminant.
  // Written as a sum of products, one term per step axis (two LUT levels).
  wire gxy1 = cxy1_q[HW-1], gxy2 = cxy2_q[HW-1], gxy0 = hxy_q[HW-1];  // 1: negative
  wire gxz1 = cxz1_q[HW-1], gxz2 = cxz2_q[HW-1], gxz0 = hxz_q[HW-1];
  wire gyz1 = cyz1_q[HW-1], gyz2 = cyz2_q[HW-1], gyz0 = hyz_q[HW-1];
  // (sx | p4_q) is gxy_q, (sy | p4_q) gyz_q, (sz | p4_q) gz_q whenever the
  // selection is taken (p4_q or act_q): three inputs per product.
  wire selx_n = (gxy_q & ~gxy1 & ~gxz1) | (sy & ~gxy2 & ~gxz0) | (sz & ~gxy0 & ~gxz2);
  wire sely_n = (sx & gxy1 & ~gyz0) | (gyz_q & gxy2 & ~gyz1) | (sz & gxy0 & ~gyz2);
  wire selz_n = (sx & gxz1 & gyz0) | (sy & gxz0 & gyz1) | (gz_q & gxz2 & gyz2);
  // Whether a step can come after this clock's: the move ends with the
  // step if fx_q (X), fy_q, fz_q (registers: l and no distance left on the
  // other axes; at L4 all three are "the move is the zero move").
  wire act_n = ~((gxy_q & fx_q) | (sy & fy_q) | (sz & fz_q));
  // The step enables of the next clock, gated by act_n, as sums of
  // products of four registered bits each (s_q one-hot, or p4_q with the
  // selects g 1): each product a net of its own, so that synthesis maps
  // each enable in two LUT levels.
  (* keep *) wire mx1 = gxy_q & ~gxy1 & ~gxz1 & ~fx_q;
  (* keep *) wire mx2 = sy & ~gxy2 & ~gxz0 & ~fy_q;
  (* keep *) wire mx3 = sz & ~gxy0 & ~gxz2 & ~fz_q;
  (* keep *) wire my1 = sx & gxy1 & ~gyz0 & ~fx_q;
  (* keep *) wire my2 = gyz_q & gxy2 & ~gyz1 & ~fy_q;
  (* keep *) wire my3 = sz & gxy0 & ~gyz2 & ~fz_q;
  (* keep *) wire mz1 = sx & gxz1 & gyz0 & ~fx_q;
  (* keep *) wire mz2 = sy & gxz0 & gyz1 & ~fy_q;
  (* keep *) wire mz3 = gz_q & gxz2 & gyz2 & ~fz_q;
  // kxy = act_n & ~selz_n etc.
  (* keep *) wire kxy1 = sx & ~(gxz1 & gyz0) & ~fx_q;
  (* keep *) wire kxy2 = sy & ~(gxz0 & gyz1) & ~fy_q;
  (* keep *) wire kxy3 = gz_q & ~(gxz2 & gyz2) & ~fz_q;
  (* keep *) wire kxz1 = sx & ~(gxy1 & ~gyz0) & ~fx_q;
  (* keep *) wire kxz2 = gyz_q & ~(gxy2 & ~gyz1) & ~fy_q;
  (* keep *) wire kxz3 = sz & ~(gxy0 & ~gyz2) & ~fz_q;
  (* keep *) wire kyz1 = gxy_q & ~(~gxy1 & ~gxz1) & ~fx_q;
  (* keep *) wire kyz2 = sy & ~(~gxy2 & ~gxz0) & ~fy_q;
  (* keep *) wire kyz3 = sz & ~(~gxy0 & ~gxz2) & ~fz_q;
  wire mx_n = mx1 | mx2 | mx3;
  wire my_n = my1 | my2 | my3;
  wire mz_n = mz1 | mz2 | mz3;
  wire kxy_n = kxy1 | kxy2 | kxy3;
  wire kxz_n = kxz1 | kxz2 | kxz3;
  wire kyz_n = kyz1 | kyz2 | kyz3;

  wire [W-1:0] one_w = {{(W-1){1'b0}}, 1'b1};
  wire [W-1:0] two_w = {{(W-2){1'b0}}, 2'b10};

  // Move constants: read only after a load (not reset; so that the
  // load alone enables them). The signs and low bits are outputs: reset.
  always @(posedge i_clk) begin
    if (i_load) begin
      a_q <= i_xe;
      b_q <= i_ye;
      nbz_q <= ~i_ye;
      ncz_q <= ~i_ze;
      am2_q <= i_xe - two_w;
      bm2_q <= i_ye - two_w;
      cm2_q <= i_ze - two_w;
    end
  end
  always @(posedge i_clk) begin
    if (i_rst) begin
      xneg_q <= 1'b0;
      yneg_q <= 1'b0;
      zneg_q <= 1'b0;
      e0xy_q <= 1'b0;
      e0xz_q <= 1'b0;
      e0yz_q <= 1'b0;
    end else if (i_load) begin
      xneg_q <= i_xneg;
      yneg_q <= i_yneg;
      zneg_q <= i_zneg;
      e0xy_q <= i_xe[0] ^ i_ye[0];
      e0xz_q <= i_xe[0] ^ i_ze[0];
      e0yz_q <= i_ye[0] ^ i_ze[0];
    end
  end
  // The operands: the halves from the load (a' + ~b' + (a0 | ~b0) is
  // (a - b - e0) / 2), the move's constants from L2.
  // (Not reset: read only in the load phases and while act_q is high.)
  always @(posedge i_clk) begin
    if (i_load | p2_q) begin
      oa_q <= i_load ? {2'b00, i_xe[W-1:1]} : {1'b0, a_q};
      ob_q <= i_load ? {2'b00, i_ye[W-1:1]} : {1'b0, b_q};
      onb_q <= i_load ? {2'b11, ~i_ye[W-1:1]} : {1'b1, nbz_q};
      onc_q <= i_load ? {2'b11, ~i_ze[W-1:1]} : {1'b1, ncz_q};
      cixy_q <= ~i_load | i_xe[0] | ~i_ye[0];
      cixz_q <= ~i_load | i_xe[0] | ~i_ze[0];
      ciyz_q <= ~i_load | i_ye[0] | ~i_ze[0];
    end
  end
  // Copies of a and ~c for exz (against fan-out; their enable differs by a
  // term that never holds, so that synthesis keeps them apart).
  always @(posedge i_clk) begin
    if (i_load | p2_q | (p4_q & act_q)) begin
      oa2_q <= i_load ? {2'b00, i_xe[W-1:1]} : {1'b0, a_q};
      onc2_q <= i_load ? {2'b11, ~i_ze[W-1:1]} : {1'b1, ncz_q};
    end
  end

  // Load phases (a load restarts them).
  always @(posedge i_clk) begin
    if (i_rst) begin
      p1_q <= 1'b0;
      p2_q <= 1'b0;
      p3_q <= 1'b0;
      p4_q <= 1'b0;
      ldph_q <= 1'b0;
      pre_q <= 1'b0;
      f22_q <= 1'b0;
    end else begin
      p1_q <= i_load;
      p2_q <= p1_q & ~i_load;
      p3_q <= p2_q & ~i_load;
      p4_q <= p3_q & ~i_load;
      ldph_q <= i_load | p1_q | p2_q | p3_q;
      pre_q <= i_load | p1_q | p2_q;
      f22_q <= i_load | p2_q | p3_q;
    end
  end

  // Distance travelled: cleared by a load, counted by the steps. Not
  // reset (so that their enables are i_load | i_cmd & m): lded_q, reset,
  // set by a load, shows 0 on the outputs until the first load.
  always @(posedge i_clk) begin
    if (i_load) x_q <= {W{1'b0}};
    else if (mv_x) x_q <= x_q + one_w;
  end
  always @(posedge i_clk) begin
    if (i_load) y_q <= {W{1'b0}};
    else if (mv_y) y_q <= y_q + one_w;
  end
  always @(posedge i_clk) begin
    if (i_load) z_q <= {W{1'b0}};
    else if (mv_z) z_q <= z_q + one_w;
  end
  always @(posedge i_clk) begin
    if (i_rst) lded_q <= 1'b0;
    else if (i_load) lded_q <= 1'b1;
  end

  // Distance-left and last-step flags: set by a load, updated by a step
  // of their axis (x + 1 == a after the step: x == a - 2 before it). Not
  // reset: o_done is 1 until the first load (lded_q).
  always @(posedge i_clk) begin
    if (i_load) begin
      rx_q <= |i_xe;
      lx_q <= i_xe == one_w;
    end else if (mv_x) begin
      rx_q <= ~lx_q;
      lx_q <= x_q == am2_q;
    end
  end
  always @(posedge i_clk) begin
    if (i_load) begin
      ry_q <= |i_ye;
      ly_q <= i_ye == one_w;
    end else if (mv_y) begin
      ry_q <= ~ly_q;
      ly_q <= y_q == bm2_q;
    end
  end
  always @(posedge i_clk) begin
    if (i_load) begin
      rz_q <= |i_ze;
      lz_q <= i_ze == one_w;
    end else if (mv_z) begin
      rz_q <= ~lz_q;
      lz_q <= z_q == cm2_q;
    end
  end

  // Discriminants: the d are cleared by the load; then every clock of the
  // preparation and every step that changes the discriminant moves the d,
  // the candidates and the half. The candidates and d are not reset: they
  // are read only when act_q is high or in the load phases, both of which
  // begin with a load. (Clear and reset are written inside the enable, as
  // the iCE40 flip-flop has them: each enable is one LUT of i_cmd.)
  always @(posedge i_clk) begin
    if (end_xy) begin
      dxy11_q <= i_load ? {DW{1'b0}} : (gxy_q & ~p2_q) ? sxy1 : sxy2;
      dxy12_q <= i_load ? {DW{1'b0}} : gxy_q ? sxy2 : sxy3;
      dxy22_q <= i_load ? {DW{1'b0}} : (gxy_q & ~f22_q) ? sxy3 : sxy4;
    end
  end
  always @(posedge i_clk) begin
    if (end_xz) begin
      dxz11_q <= i_load ? {DW{1'b0}} : (gxz_q & ~p2_q) ? sxz1 : sxz2;
      dxz12_q <= i_load ? {DW{1'b0}} : gxz_q ? sxz2 : sxz3;
      dxz22_q <= i_load ? {DW{1'b0}} : (gxz_q & ~f22_q) ? sxz3 : sxz4;
    end
  end
  always @(posedge i_clk) begin
    if (end_yz) begin
      dyz11_q <= i_load ? {DW{1'b0}} : (gyz_q & ~p2_q) ? syz1 : syz2;
      dyz12_q <= i_load ? {DW{1'b0}} : gyz_q ? syz2 : syz3;
      dyz22_q <= i_load ? {DW{1'b0}} : (gyz_q & ~f22_q) ? syz3 : syz4;
    end
  end
  always @(posedge i_clk) begin
    if (en_xy) begin
      cxy1_q <= gxy_q ? vxy11 : vxy12;
      cxy2_q <= gxy_q ? vxy12 : vxy22;
    end
    if (en_xz) begin
      cxz1_q <= gxz_q ? vxz11 : vxz12;
      cxz2_q <= gxz_q ? vxz12 : vxz22;
    end
    if (en_yz) begin
      cyz1_q <= gyz_q ? vyz11 : vyz12;
      cyz2_q <= gyz_q ? vyz12 : vyz22;
    end
  end
  // The halves: 0 from a reset and at L1 (the candidates, not reset, are
  // the sums' values only from L1: no unknown value reaches an output).
  always @(posedge i_clk) begin
    if (en_xy) hxy_q <= (i_rst | p1_q) ? {HW{1'b0}} : gxy_q ? cxy1_q : cxy2_q;
    if (en_xz) hxz_q <= (i_rst | p1_q) ? {HW{1'b0}} : gxz_q ? cxz1_q : cxz2_q;
    if (en_yz) hyz_q <= (i_rst | p1_q) ? {HW{1'b0}} : gyz_q ? cyz1_q : cyz2_q;
  end

  // The next step and whether one can come: 000 and not active from the
  // load; computed at L4 from the prepared state, then after every step.
  // s_q is cleared at L1 (p1_q; it is not read before L4), so that i_load
  // is one LUT away from every register; act_q and the step enables are
  // cleared by the load itself. The selects g are 1 while loading (set at
  // L0 to L3). s_q and g are not reset: read only while loading or act_q.
  // (Every enable here is one LUT of i_cmd.)
  always @(posedge i_clk) begin
    if (p1_q | p4_q | go) s_q <= p1_q ? 3'b000 : {selz_n, sely_n, selx_n};
  end
  always @(posedge i_clk) begin
    if (i_load | ldph_q | go) gxy_q <= (i_load | pre_q) | selx_n;
  end
  always @(posedge i_clk) begin
    if (i_load | ldph_q | go) gxz_q <= (i_load | pre_q | (p4_q & act_q)) | selx_n;
  end
  always @(posedge i_clk) begin
    if (i_load | ldph_q | go) gyz_q <= (i_load | pre_q) | sely_n;
  end
  always @(posedge i_clk) begin
    if (i_load | ldph_q | go) gz_q <= (i_load | pre_q) | selz_n;
  end
  // ox = ~ry & ~rz etc. after the flags' change: taken at L1 (the flags
  // are the load's), then by the steps of the other axes (a Y step makes
  // ry = ~ly). Read at L4 and while act_q (not reset).
  always @(posedge i_clk) begin
    if (p1_q | go) begin
      ox_q <= p1_q ? ~ry_q & ~rz_q : my_q ? ly_q & ~rz_q : mz_q ? ~ry_q & lz_q : ox_q;
      oy_q <= p1_q ? ~rx_q & ~rz_q : mx_q ? lx_q & ~rz_q : mz_q ? ~rx_q & lz_q : oy_q;
      oz_q <= p1_q ? ~rx_q & ~ry_q : mx_q ? lx_q & ~ry_q : my_q ? ~rx_q & ly_q : oz_q;
    end
  end
  // fx = lx & ox after the flags' change (at L4 from the load's flags;
  // an X step makes lx = (x == a - 2), a Y step ox = ly & ~rz, ...); at L3
  // the zero move's "done" (read at L4 by act_n and the step enables).
  wire done_n = ~(rx_q | ry_q | rz_q);
  always @(posedge i_clk) begin
    if (p3_q | p4_q | go) begin
      fx_q <= p3_q ? done_n : p4_q ? lx_q & ox_q : mx_q ? (x_q == am2_q) & ox_q : my_q ? lx_q & ly_q & ~rz_q : lx_q & ~ry_q & lz_q;
      fy_q <= p3_q ? done_n : p4_q ? ly_q & oy_q : my_q ? (y_q == bm2_q) & oy_q : mx_q ? ly_q & lx_q & ~rz_q : ly_q & ~rx_q & lz_q;
      fz_q <= p3_q ? done_n : p4_q ? lz_q & oz_q : mz_q ? (z_q == cm2_q) & oz_q : mx_q ? lz_q & lx_q & ~ry_q : lz_q & ~rx_q & ly_q;
    end
  end
  always @(posedge i_clk) begin
    if (i_rst | i_load) begin
      act_q <= 1'b0;
      {mx_q, my_q, mz_q} <= 3'b000;
      {kxy_q, kxz_q, kyz_q} <= 3'b000;
    end else if (p4_q | go) begin
      act_q <= act_n;
      {mx_q, my_q, mz_q} <= {mx_n, my_n, mz_n};
      {kxy_q, kxz_q, kyz_q} <= {kxy_n, kxz_n, kyz_n};
    end
  end

  // (The copies' clear differs by a term that never holds: kept apart.)
  always @(posedge i_clk) begin
    if (i_rst | i_load | (p4_q & act_q)) {kdxy_q, kdxz_q, kdyz_q} <= 3'b000;
    else if (p4_q | go) {kdxy_q, kdxz_q, kdyz_q} <= {kxy_n, kxz_n, kyz_n};
  end

  // Output pulse: the axis that stepped in the previous clock.
  always @(posedge i_clk) begin
    if (i_rst | i_load) begin
      o_step_x <= 1'b0;
      o_step_y <= 1'b0;
      o_step_z <= 1'b0;
    end else begin
      o_step_x <= mv_x;
      o_step_y <= mv_y;
      o_step_z <= mv_z;
    end
  end

  assign o_dir_x = xneg_q;
  assign o_dir_y = yneg_q;
  assign o_dir_z = zneg_q;
  assign o_done = ~lded_q | ~(rx_q | ry_q | rz_q);
  assign o_ready = ~ldph_q;
  assign o_x = x_q & {W{lded_q}};
  assign o_y = y_q & {W{lded_q}};
  assign o_z = z_q & {W{lded_q}};
  assign o_exy = {hxy_q, e0xy_q};
  assign o_exz = {hxz_q, e0xz_q};
  assign o_eyz = {hyz_q, e0yz_q};

`ifdef FORMAL
  // ------------------------------------------------------------- formal
  // Proved at a small W by rtl/interp3/formal/prove.sh (ctest interp3_formal):
  // every property below holds in every reachable state, for every move
  // and every command and load sequence (1-induction from reset).
  //
  // The discriminants in exact arithmetic: the products are taken at
  // their full width (W x (W+1) bits), the differences in FW = 2W+3 bits,
  // so nothing wraps; the outputs, sign-extended, must equal them, so no
  // addition ever overflowed.
  localparam integer EW = W + 2;
  localparam integer FW = 2 * W + 3;
  // The move: the last one loaded, the zero move before any load (the
  // constants' registers are not reset).
  reg loaded_f;
  always @(posedge i_clk) begin
    if (i_rst) loaded_f <= 1'b0;
    else if (i_load) loaded_f <= 1'b1;
  end
  wire [W-1:0] a_f = loaded_f ? a_q : {W{1'b0}};  // |XE|
  wire [W-1:0] b_f = loaded_f ? b_q : {W{1'b0}};  // |YE|
  wire [W-1:0] c_f = loaded_f ? ~ncz_q : {W{1'b0}};  // |ZE|
  wire [W:0] x2_f = {o_x, 1'b1};  // 2x + 1
  wire [W:0] y2_f = {o_y, 1'b1};
  wire [W:0] z2_f = {o_z, 1'b1};
  wire [2*W:0] ay_f = a_f * y2_f;
  wire [2*W:0] az_f = a_f * z2_f;
  wire [2*W:0] bx_f = b_f * x2_f;
  wire [2*W:0] bz_f = b_f * z2_f;
  wire [2*W:0] cx_f = c_f * x2_f;
  wire [2*W:0] cy_f = c_f * y2_f;
  wire [FW-1:0] exy_x = {2'b00, ay_f} - {2'b00, bx_f};
  wire [FW-1:0] exz_x = {2'b00, az_f} - {2'b00, cx_f};
  wire [FW-1:0] eyz_x = {2'b00, bz_f} - {2'b00, cy_f};
  // Outputs sign-extended, and the range bounds 2A, -2B etc.
  wire signed [FW-1:0] exy_f = $signed({{(FW-EW){o_exy[EW-1]}}, o_exy});
  wire signed [FW-1:0] exz_f = $signed({{(FW-EW){o_exz[EW-1]}}, o_exz});
  wire signed [FW-1:0] eyz_f = $signed({{(FW-EW){o_eyz[EW-1]}}, o_eyz});
  wire signed [FW-1:0] a2_f = $signed({{(FW-W-1){1'b0}}, a_f, 1'b0});
  wire signed [FW-1:0] b2_f = $signed({{(FW-W-1){1'b0}}, b_f, 1'b0});
  wire signed [FW-1:0] c2_f = $signed({{(FW-W-1){1'b0}}, c_f, 1'b0});
  // The initial discriminants a - b, a - c, b - c in W + 2 bits, and
  // their halves (the initial halves).
  wire [EW-1:0] dxy_f = {2'b00, a_f} - {2'b00, b_f};
  wire [EW-1:0] dxz_f = {2'b00, a_f} - {2'b00, c_f};
  wire [EW-1:0] dyz_f = {2'b00, b_f} - {2'b00, c_f};
  wire [HW-1:0] ixy_f = dxy_f[EW-1:1], ixz_f = dxz_f[EW-1:1], iyz_f = dyz_f[EW-1:1];
  // The updates in HW bits, and the operands while loading.
  wire [HW-1:0] a_h = {1'b0, a_f};
  wire [HW-1:0] b_h = {1'b0, b_f};
  wire [HW-1:0] nb_f = {HW{1'b0}} - b_h;
  wire [HW-1:0] nc_f = {HW{1'b0}} - {1'b0, c_f};
  wire [HW-1:0] ah_f = {2'b00, a_f[W-1:1]};
  wire [HW-1:0] bh_f = {2'b00, b_f[W-1:1]};
  wire [HW-1:0] nbh_f = ~bh_f;
  wire [HW-1:0] nch_f = ~{2'b00, c_f[W-1:1]};
  wire [HW-1:0] zero_h = {HW{1'b0}};
  // The selection of the current state (docs/algorithm.md).
  wire selx_f = rx_q & (~ry_q | ~hxy_q[HW-1]) & (~rz_q | ~hxz_q[HW-1]);
  wire sely_f = ~selx_f & ry_q & (~rz_q | ~hyz_q[HW-1]);
  wire selz_f = ~selx_f & ~sely_f & rz_q;
  wire [W:0] xp1_f = {1'b0, o_x} + {{W{1'b0}}, 1'b1};
  wire [W:0] yp1_f = {1'b0, o_y} + {{W{1'b0}}, 1'b1};
  wire [W:0] zp1_f = {1'b0, o_z} + {{W{1'b0}}, 1'b1};

  reg past_valid_f;
  initial past_valid_f = 1'b0;
  always @(posedge i_clk) past_valid_f <= 1'b1;

  // The first clock is a reset (the state before it is arbitrary).
  always @(*) begin
    if (!past_valid_f) assume (i_rst);
  end

  // Invariants of every state.
  always @(*) begin
    if (past_valid_f) begin
      // The move's constants and the load phases.
      assert (lded_q == loaded_f);
      if (loaded_f) begin
        assert (nbz_q == ~b_f);
        assert (am2_q == a_f - two_w && bm2_q == b_f - two_w && cm2_q == c_f - two_w);
      end else begin
        assert (!ldph_q && !act_q);
      end
      assert (e0xy_q == (a_f[0] ^ b_f[0]) && e0xz_q == (a_f[0] ^ c_f[0]) && e0yz_q == (b_f[0] ^ c_f[0]));
      assert ({2'b00, p1_q} + {2'b00, p2_q} + {2'b00, p3_q} + {2'b00, p4_q} <= 3'd1);
      assert (ldph_q == (p1_q | p2_q | p3_q | p4_q));
      assert (f22_q == (p1_q | p3_q | p4_q) && pre_q == (p1_q | p2_q | p3_q));
      assert ({mx_q, my_q, mz_q} == ({sx, sy, sz} & {3{act_q}}));
      assert ({kxy_q, kxz_q, kyz_q} == ({~sz, ~sy, ~sx} & {3{act_q}}));
      assert ({kdxy_q, kdxz_q, kdyz_q} == {kxy_q, kxz_q, kyz_q});
      // The selects: 1 while loading, s_q's bit while a step can come.
      if (ldph_q) assert (gxy_q && gxz_q && gyz_q && gz_q);
      if (act_q) assert (gxy_q == sx && gxz_q == sx && gyz_q == sy && gz_q == sz);
      if (ldph_q & ~p1_q | act_q) assert (ox_q == (~ry_q & ~rz_q) && oy_q == (~rx_q & ~rz_q) && oz_q == (~rx_q & ~ry_q));
      if (p4_q) assert (fx_q == ~(rx_q | ry_q | rz_q) && fy_q == fx_q && fz_q == fx_q);
      if (act_q) assert (fx_q == (lx_q & ox_q) && fy_q == (ly_q & oy_q) && fz_q == (lz_q & oz_q));
      // The operands: the halves after L0 and L1, then the updates.
      if (p1_q | p2_q) begin
        assert (oa_q == ah_f && ob_q == bh_f && onb_q == nbh_f && onc_q == nch_f);
        assert (oa2_q == oa_q && onc2_q == onc_q);
        assert (cixy_q == (a_f[0] | ~b_f[0]) && cixz_q == (a_f[0] | ~c_f[0]) && ciyz_q == (b_f[0] | ~c_f[0]));
      end else if (p3_q | p4_q | act_q) begin
        assert (oa_q == a_h && ob_q == b_h && onb_q + 1'b1 == nb_f && onc_q + 1'b1 == nc_f);
        assert (oa2_q == oa_q && onc2_q == onc_q);
        assert (cixy_q && cixz_q && ciyz_q);
      end
      // No axis passes its end; the flags are the comparisons they stand for.
      assert (o_x <= a_f && o_y <= b_f && o_z <= c_f);
      if (loaded_f) begin
        assert (rx_q == (o_x < a_f) && ry_q == (o_y < b_f) && rz_q == (o_z < c_f));
        assert (lx_q == (xp1_f == {1'b0, a_f}) && ly_q == (yp1_f == {1'b0, b_f}) && lz_q == (zp1_f == {1'b0, c_f}));
      end
      assert (o_done == (o_x == a_f && o_y == b_f && o_z == c_f));
      // At most one pulse per clock.
      assert (!(o_step_x && o_step_y) && !(o_step_x && o_step_z) && !(o_step_y && o_step_z));
      if (ldph_q) begin
        // Preparing: no step can come; nothing travelled yet.
        assert (!act_q);
        if (!p1_q) assert (s_q == 3'b000);
        assert (o_x == {W{1'b0}} && o_y == {W{1'b0}} && o_z == {W{1'b0}});
        assert (!o_step_x && !o_step_y && !o_step_z);
        // The sums, clock by clock (docs/rtl-3axis.md, "Timing").
        if (p1_q) begin
          assert (sval(dxy11_q) == zero_h && sval(dxy22_q) == zero_h);
          assert (sval(dxz11_q) == zero_h && sval(dxz22_q) == zero_h);
          assert (sval(dyz11_q) == zero_h && sval(dyz22_q) == zero_h);
        end
        if (p2_q) begin
          assert (sval(dxy11_q) == nbh_f + cixy_q && sval(dxy22_q) == ah_f);
          assert (sval(dxz11_q) == nch_f + cixz_q && sval(dxz22_q) == ah_f);
          assert (sval(dyz11_q) == nch_f + ciyz_q && sval(dyz22_q) == bh_f);
        end
        if (p3_q) begin
          assert (sval(dxy11_q) == ixy_f && sval(dxy12_q) == ixy_f && sval(dxy22_q) == ixy_f);
          assert (sval(dxz11_q) == ixz_f && sval(dxz12_q) == ixz_f && sval(dxz22_q) == ixz_f);
          assert (sval(dyz11_q) == iyz_f && sval(dyz12_q) == iyz_f && sval(dyz22_q) == iyz_f);
        end
        if (p4_q) begin
          assert (cxy1_q == ixy_f && cxy2_q == ixy_f);
          assert (cxz1_q == ixz_f && cxz2_q == ixz_f);
          assert (cyz1_q == iyz_f && cyz2_q == iyz_f);
          assert (sval(dxy11_q) == ixy_f + nb_f && sval(dxy12_q) == ixy_f + a_h && sval(dxy22_q) == ixy_f + a_h);
          assert (sval(dxz11_q) == ixz_f + nc_f && sval(dxz12_q) == ixz_f + a_h && sval(dxz22_q) == ixz_f + a_h);
          assert (sval(dyz11_q) == iyz_f + nc_f && sval(dyz12_q) == iyz_f + b_h && sval(dyz22_q) == iyz_f + b_h);
        end
      end else begin
        // Ready: the three discriminant invariants, exactly, and their
        // ranges: Exy in [-2B, 2A], Exz in [-2C, 2A], Eyz in [-2C, 2B].
        assert (exy_f == $signed(exy_x));
        assert (exz_f == $signed(exz_x));
        assert (eyz_f == $signed(eyz_x));
        assert (exy_f >= -b2_f && exy_f <= a2_f);
        assert (exz_f >= -c2_f && exz_f <= a2_f);
        assert (eyz_f >= -c2_f && eyz_f <= b2_f);
        // A step can come while the move is not done; it is the contract's
        // selection of this state.
        assert (act_q == ~o_done);
        if (act_q) assert (s_q == {selz_f, sely_f, selx_f});
        // The candidates are the halves after each step.
        if (act_q) begin
          assert (cxy1_q == hxy_q + nb_f && cxy2_q == hxy_q + a_h);
          assert (cxz1_q == hxz_q + nc_f && cxz2_q == hxz_q + a_h);
          assert (cyz1_q == hyz_q + nc_f && cyz2_q == hyz_q + b_h);
          // and the sums two steps ahead.
          assert (sval(dxy11_q) == cxy1_q + nb_f && sval(dxy12_q) == cxy1_q + a_h && sval(dxy22_q) == cxy2_q + a_h);
          assert (sval(dxz11_q) == cxz1_q + nc_f && sval(dxz12_q) == cxz1_q + a_h && sval(dxz22_q) == cxz2_q + a_h);
          assert (sval(dyz11_q) == cyz1_q + nc_f && sval(dyz12_q) == cyz1_q + b_h && sval(dyz22_q) == cyz2_q + b_h);
        end
      end
      // One step per clock: a command while ready and not done moves
      // exactly one axis, one with distance left.
      assert ({1'b0, mv_x} + {1'b0, mv_y} + {1'b0, mv_z} == {1'b0, go});
      assert (!(mv_x && !rx_q) && !(mv_y && !ry_q) && !(mv_z && !rz_q));
      assert (go == (i_cmd && !ldph_q && !o_done));
    end
  end
`endif

endmodule
