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
  localparam integer K = (HW * 3) / 8;  // low part of the carry-select adders (9 of 25 bits)
  localparam integer NG = (HW + 7) / 8;  // copies of each multiplexer select: one per 8 bits

  // p + q (mod 2^HW) as a carry-select adder: the low K bits, and the high
  // part both without and with their carry-in, chosen by the low part's
  // carry-out; each carry chain is about half as long as a plain adder's.
  // (p - ~q is p + q + 1 in one chain.)
  function automatic [HW-1:0] csel_add(input [HW-1:0] p, input [HW-1:0] q);
    reg [K:0] lo;
    reg [HW-K-1:0] hi0, hi1;
    begin
      lo = {1'b0, p[K-1:0]} + {1'b0, q[K-1:0]};
      hi0 = p[HW-1:K] + q[HW-1:K];
      hi1 = p[HW-1:K] - ~q[HW-1:K];
      csel_add = {lo[K] ? hi1 : hi0, lo[K-1:0]};
    end
  endfunction

  // ------------------------------------------------------------ registers
  // Move constants, taken at the load (L0) or prepared from it (L1).
  reg [W-1:0] a_q, b_q;               // |XE|, |YE|
  reg [W-1:0] nbz_q, ncz_q;           // ~|YE|, ~|ZE| (so that no adder needs an inverter)
  reg xneg_q, yneg_q, zneg_q;
  reg [W-1:0] am2_q, bm2_q, cm2_q;    // a - 2, b - 2, c - 2 (mod 2^W)
  reg e0xy_q, e0xz_q, e0yz_q;         // low bits of the discriminants
  reg [HW-1:0] nb_q, nc_q;            // -b, -c (L1)
  reg [HW-1:0] dxy_q, dxz_q, dyz_q;   // halves of the initial discriminants (L1)
  // Load phases: p1_q after L0, p2_q after L1, p3_q after L2; ldph_q any.
  // The multiplexers' selects, per discriminant and per 8 bits (fan-out):
  // z*_q = p1 or p2 (the new half is 0), ds*_q = p2 (the operands are the
  // initial half).
  reg p1_q, p2_q, p3_q, ldph_q;
  (* keep *) reg [NG-1:0] zxy_q, zxz_q, zyz_q;
  (* keep *) reg [NG-1:0] dsxy_q, dsxz_q, dsyz_q;
  // Interpolation state.
  reg [W-1:0] x_q, y_q, z_q;          // distance travelled
  reg rx_q, ry_q, rz_q;               // distance left: x < a
  reg lx_q, ly_q, lz_q;               // last step: x + 1 == a
  reg [HW-1:0] hxy_q, hxz_q, hyz_q;   // halves of exy, exz, eyz
  reg [HW-1:0] cxy1_q, cxy2_q;        // exy candidates: after X, after Y
  reg [HW-1:0] cxz1_q, cxz2_q;        // exz candidates: after X, after Z
  reg [HW-1:0] cyz1_q, cyz2_q;        // eyz candidates: after Y, after Z
  reg [2:0] s_q;                      // next step {Z, Y, X}; 000 while loading
  // Copies of the bit of s_q that picks each discriminant's first
  // candidate (X, X, Y): the multiplexers' selects, per 8 bits.
  (* keep *) reg [NG-1:0] sxy_q, sxz_q, syz_q;
  reg act_q;                          // ready and not done
  // Registered step enables: the axis that steps on a command (act_q and
  // s_q), and whether a command changes each discriminant.
  reg mx_q, my_q, mz_q;
  reg kxy_q, kxz_q, kyz_q;

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
  // The new half of each discriminant: the candidate of the stepping axis;
  // 0 in the clocks after L0 and L1; the second candidate (s_q = 000),
  // which is then the initial half, in the clock after L2.
  // (Each select copied to every bit of its group.)
  wire [HW-1:0] sxy_e, sxz_e, syz_e, zxy_e, zxz_e, zyz_e, dsxy_e, dsxz_e, dsyz_e;
  genvar gi;
  generate
    for (gi = 0; gi < HW; gi = gi + 1) begin : g_sel
      assign sxy_e[gi] = sxy_q[gi/8];
      assign sxz_e[gi] = sxz_q[gi/8];
      assign syz_e[gi] = syz_q[gi/8];
      assign zxy_e[gi] = zxy_q[gi/8];
      assign zxz_e[gi] = zxz_q[gi/8];
      assign zyz_e[gi] = zyz_q[gi/8];
      assign dsxy_e[gi] = dsxy_q[gi/8];
      assign dsxz_e[gi] = dsxz_q[gi/8];
      assign dsyz_e[gi] = dsyz_q[gi/8];
    end
  endgenerate
  wire [HW-1:0] mxy = ~zxy_e & ((sxy_e & cxy1_q) | (~sxy_e & cxy2_q));
  wire [HW-1:0] mxz = ~zxz_e & ((sxz_e & cxz1_q) | (~sxz_e & cxz2_q));
  wire [HW-1:0] myz = ~zyz_e & ((syz_e & cyz1_q) | (~syz_e & cyz2_q));
  // The operands: in the clock after L1 the initial half (so that both
  // candidates become it), then the move's constants.
  wire [HW-1:0] a_h = {1'b0, a_q};
  wire [HW-1:0] b_h = {1'b0, b_q};
  wire [HW-1:0] oxy1 = (dsxy_e & dxy_q) | (~dsxy_e & nb_q);
  wire [HW-1:0] oxy2 = (dsxy_e & dxy_q) | (~dsxy_e & a_h);
  wire [HW-1:0] oxz1 = (dsxz_e & dxz_q) | (~dsxz_e & nc_q);
  wire [HW-1:0] oxz2 = (dsxz_e & dxz_q) | (~dsxz_e & a_h);
  wire [HW-1:0] oyz1 = (dsyz_e & dyz_q) | (~dsyz_e & nc_q);
  wire [HW-1:0] oyz2 = (dsyz_e & dyz_q) | (~dsyz_e & b_h);
  // Which discriminants change in this clock (s_q is one-hot when act_q).
  wire en_xy = ldph_q | (i_cmd & kxy_q);
  wire en_xz = ldph_q | (i_cmd & kxz_q);
  wire en_yz = ldph_q | (i_cmd & kyz_q);

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
  // the halves it leaves alone; in the clock after L2 (p3_q, s_q = 000) the
  // initial halves, which are then both candidates of each discriminant.
  // Written as a sum of products, one term per step axis (two LUT levels).
  wire gxy1 = cxy1_q[HW-1], gxy2 = cxy2_q[HW-1], gxy0 = hxy_q[HW-1];  // 1: negative
  wire gxz1 = cxz1_q[HW-1], gxz2 = cxz2_q[HW-1], gxz0 = hxz_q[HW-1];
  wire gyz1 = cyz1_q[HW-1], gyz2 = cyz2_q[HW-1], gyz0 = hyz_q[HW-1];
  wire selx_n = ((sx | p3_q) & ~gxy1 & ~gxz1) | (sy & ~gxy2 & ~gxz0) | (sz & ~gxy0 & ~gxz2);
  wire sely_n = (sx & gxy1 & ~gyz0) | ((sy | p3_q) & gxy2 & ~gyz1) | (sz & gxy0 & ~gyz2);
  wire selz_n = (sx & gxz1 & gyz0) | (sy & gxz0 & gyz1) | ((sz | p3_q) & gxz2 & gyz2);
  // Distance left after the step on some axis: the step's own flag becomes
  // !l, the others stay.
  wire act_n = (sx & (~lx_q | ry_q | rz_q)) | (sy & (rx_q | ~ly_q | rz_q))
             | (sz & (rx_q | ry_q | ~lz_q)) | (p3_q & (rx_q | ry_q | rz_q));

  // ---------------------------------------------------------- preparation
  // L1: -b = ~b + 1 and a - b = a + ~b + 1 (x - ~y is x + y + 1: one carry
  // chain, the complement stored at L0), in W + 1 bits; the halves of the
  // differences (their low bits were taken at L0).
  wire [HW-1:0] nbz_h = {1'b1, nbz_q};
  wire [HW-1:0] ncz_h = {1'b1, ncz_q};
  wire [HW-1:0] zero_h = {HW{1'b0}};
  wire [HW-1:0] pre_nb = zero_h - ~nbz_h;
  wire [HW-1:0] pre_nc = zero_h - ~ncz_h;
  wire [HW-1:0] pre_xy = a_h - ~nbz_h;
  wire [HW-1:0] pre_xz = a_h - ~ncz_h;
  wire [HW-1:0] pre_yz = b_h - ~ncz_h;
  wire unused_pre = pre_xy[0] ^ pre_xz[0] ^ pre_yz[0];  // the low bits: e0, from L0
  wire [W-1:0] one_w = {{(W-1){1'b0}}, 1'b1};
  wire [W-1:0] two_w = {{(W-2){1'b0}}, 2'b10};

  // Move constants.
  always @(posedge i_clk) begin
    if (i_rst) begin
      a_q <= {W{1'b0}};
      b_q <= {W{1'b0}};
      nbz_q <= {W{1'b1}};
      ncz_q <= {W{1'b1}};
      xneg_q <= 1'b0;
      yneg_q <= 1'b0;
      zneg_q <= 1'b0;
      am2_q <= ~one_w;  // 0 - 2
      bm2_q <= ~one_w;
      cm2_q <= ~one_w;
      e0xy_q <= 1'b0;
      e0xz_q <= 1'b0;
      e0yz_q <= 1'b0;
    end else if (i_load) begin
      a_q <= i_xe;
      b_q <= i_ye;
      nbz_q <= ~i_ye;
      ncz_q <= ~i_ze;
      xneg_q <= i_xneg;
      yneg_q <= i_yneg;
      zneg_q <= i_zneg;
      am2_q <= i_xe - two_w;
      bm2_q <= i_ye - two_w;
      cm2_q <= i_ze - two_w;
      e0xy_q <= i_xe[0] ^ i_ye[0];
      e0xz_q <= i_xe[0] ^ i_ze[0];
      e0yz_q <= i_ye[0] ^ i_ze[0];
    end
  end
  always @(posedge i_clk) begin
    if (i_rst) begin
      nb_q <= {HW{1'b0}};
      nc_q <= {HW{1'b0}};
      dxy_q <= {HW{1'b0}};
      dxz_q <= {HW{1'b0}};
      dyz_q <= {HW{1'b0}};
    end else if (p1_q) begin
      nb_q <= pre_nb;
      nc_q <= pre_nc;
      dxy_q <= {pre_xy[HW-1], pre_xy[HW-1:1]};
      dxz_q <= {pre_xz[HW-1], pre_xz[HW-1:1]};
      dyz_q <= {pre_yz[HW-1], pre_yz[HW-1:1]};
    end
  end

  // Load phases (a load restarts them).
  always @(posedge i_clk) begin
    if (i_rst) begin
      p1_q <= 1'b0;
      p2_q <= 1'b0;
      p3_q <= 1'b0;
      ldph_q <= 1'b0;
      zxy_q <= {NG{1'b0}};
      zxz_q <= {NG{1'b0}};
      zyz_q <= {NG{1'b0}};
      dsxy_q <= {NG{1'b0}};
      dsxz_q <= {NG{1'b0}};
      dsyz_q <= {NG{1'b0}};
    end else begin
      p1_q <= i_load;
      p2_q <= p1_q & ~i_load;
      p3_q <= p2_q & ~i_load;
      ldph_q <= i_load | p1_q | p2_q;
      // Each copy XORs in (copy ^ original), 0 in every reachable state
      // (proved below), so that synthesis cannot merge the copies.
      zxy_q <= {NG{i_load | p1_q}} ^ zxy_q ^ {NG{p1_q | p2_q}};
      zxz_q <= {NG{i_load | p1_q}} ^ zxz_q ^ {NG{p1_q | p2_q}};
      zyz_q <= {NG{i_load | p1_q}} ^ zyz_q ^ {NG{p1_q | p2_q}};
      dsxy_q <= {NG{p1_q & ~i_load}} ^ dsxy_q ^ {NG{p2_q}};
      dsxz_q <= {NG{p1_q & ~i_load}} ^ dsxz_q ^ {NG{p2_q}};
      dsyz_q <= {NG{p1_q & ~i_load}} ^ dsyz_q ^ {NG{p2_q}};
    end
  end

  // Distance travelled: cleared by a load, counted by the steps.
  always @(posedge i_clk) begin
    if (i_rst | i_load) x_q <= {W{1'b0}};
    else if (mv_x) x_q <= x_q + one_w;
  end
  always @(posedge i_clk) begin
    if (i_rst | i_load) y_q <= {W{1'b0}};
    else if (mv_y) y_q <= y_q + one_w;
  end
  always @(posedge i_clk) begin
    if (i_rst | i_load) z_q <= {W{1'b0}};
    else if (mv_z) z_q <= z_q + one_w;
  end

  // Distance-left and last-step flags: set by a load, updated by a step
  // of their axis (x + 1 == a after the step: x == a - 2 before it).
  always @(posedge i_clk) begin
    if (i_rst) begin
      rx_q <= 1'b0;
      lx_q <= 1'b0;
    end else if (i_load) begin
      rx_q <= |i_xe;
      lx_q <= i_xe == one_w;
    end else if (mv_x) begin
      rx_q <= ~lx_q;
      lx_q <= x_q == am2_q;
    end
  end
  always @(posedge i_clk) begin
    if (i_rst) begin
      ry_q <= 1'b0;
      ly_q <= 1'b0;
    end else if (i_load) begin
      ry_q <= |i_ye;
      ly_q <= i_ye == one_w;
    end else if (mv_y) begin
      ry_q <= ~ly_q;
      ly_q <= y_q == bm2_q;
    end
  end
  always @(posedge i_clk) begin
    if (i_rst) begin
      rz_q <= 1'b0;
      lz_q <= 1'b0;
    end else if (i_load) begin
      rz_q <= |i_ze;
      lz_q <= i_ze == one_w;
    end else if (mv_z) begin
      rz_q <= ~lz_q;
      lz_q <= z_q == cm2_q;
    end
  end

  // Discriminants and their candidates: the halves are 0 from L1, the
  // candidates take the initial half at L2 (0 + it) and the half plus each
  // operand at L3; then each step of an axis in the discriminant moves all
  // three. The candidates are not reset: they are read only when act_q is
  // high or in the load phases, both of which begin with a load.
  always @(posedge i_clk) begin
    if (en_xy) begin
      cxy1_q <= csel_add(mxy, oxy1);
      cxy2_q <= csel_add(mxy, oxy2);
    end
  end
  always @(posedge i_clk) begin
    if (en_xz) begin
      cxz1_q <= csel_add(mxz, oxz1);
      cxz2_q <= csel_add(mxz, oxz2);
    end
  end
  always @(posedge i_clk) begin
    if (en_yz) begin
      cyz1_q <= csel_add(myz, oyz1);
      cyz2_q <= csel_add(myz, oyz2);
    end
  end
  always @(posedge i_clk) begin
    if (i_rst) begin
      hxy_q <= {HW{1'b0}};
      hxz_q <= {HW{1'b0}};
      hyz_q <= {HW{1'b0}};
    end else begin
      if (en_xy) hxy_q <= mxy;
      if (en_xz) hxz_q <= mxz;
      if (en_yz) hyz_q <= myz;
    end
  end

  // The next step and whether one can come: 000 and not active from the
  // load; computed at L3 from the prepared state, then after every step.
  // s_q and its copies are cleared at L1 (p1_q; they are not read before
  // L3), so that i_load is one LUT away from every register; act_q and the
  // step enables are cleared by the load itself.
  always @(posedge i_clk) begin
    if (i_rst | p1_q) begin
      s_q <= 3'b000;
      sxy_q <= {NG{1'b0}};
      sxz_q <= {NG{1'b0}};
      syz_q <= {NG{1'b0}};
    end else if (p3_q | go) begin
      s_q <= {selz_n, sely_n, selx_n};
      sxy_q <= {NG{selx_n}} ^ sxy_q ^ {NG{sx}};  // (copy ^ original) as above
      sxz_q <= {NG{selx_n}} ^ sxz_q ^ {NG{sx}};
      syz_q <= {NG{sely_n}} ^ syz_q ^ {NG{sy}};
    end
  end
  always @(posedge i_clk) begin
    if (i_rst | i_load) begin
      act_q <= 1'b0;
      {mx_q, my_q, mz_q} <= 3'b000;
      {kxy_q, kxz_q, kyz_q} <= 3'b000;
    end else if (p3_q | go) begin
      act_q <= act_n;
      {mx_q, my_q, mz_q} <= {selx_n, sely_n, selz_n} & {3{act_n}};
      {kxy_q, kxz_q, kyz_q} <= {~selz_n, ~sely_n, ~selx_n} & {3{act_n}};
    end
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
  assign o_done = ~(rx_q | ry_q | rz_q);
  assign o_ready = ~ldph_q;
  assign o_x = x_q;
  assign o_y = y_q;
  assign o_z = z_q;
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
  wire [W-1:0] c_f = ~ncz_q;  // |ZE|
  wire [W:0] x2_f = {x_q, 1'b1};  // 2x + 1
  wire [W:0] y2_f = {y_q, 1'b1};
  wire [W:0] z2_f = {z_q, 1'b1};
  wire [2*W:0] ay_f = a_q * y2_f;
  wire [2*W:0] az_f = a_q * z2_f;
  wire [2*W:0] bx_f = b_q * x2_f;
  wire [2*W:0] bz_f = b_q * z2_f;
  wire [2*W:0] cx_f = c_f * x2_f;
  wire [2*W:0] cy_f = c_f * y2_f;
  wire [FW-1:0] exy_x = {2'b00, ay_f} - {2'b00, bx_f};
  wire [FW-1:0] exz_x = {2'b00, az_f} - {2'b00, cx_f};
  wire [FW-1:0] eyz_x = {2'b00, bz_f} - {2'b00, cy_f};
  // Outputs sign-extended, and the range bounds 2A, -2B etc.
  wire signed [FW-1:0] exy_f = $signed({{(FW-EW){o_exy[EW-1]}}, o_exy});
  wire signed [FW-1:0] exz_f = $signed({{(FW-EW){o_exz[EW-1]}}, o_exz});
  wire signed [FW-1:0] eyz_f = $signed({{(FW-EW){o_eyz[EW-1]}}, o_eyz});
  wire signed [FW-1:0] a2_f = $signed({{(FW-W-1){1'b0}}, a_q, 1'b0});
  wire signed [FW-1:0] b2_f = $signed({{(FW-W-1){1'b0}}, b_q, 1'b0});
  wire signed [FW-1:0] c2_f = $signed({{(FW-W-1){1'b0}}, c_f, 1'b0});
  // The initial discriminants a - b, a - c, b - c in W + 2 bits.
  wire [EW-1:0] dxy_f = {2'b00, a_q} - {2'b00, b_q};
  wire [EW-1:0] dxz_f = {2'b00, a_q} - {2'b00, c_f};
  wire [EW-1:0] dyz_f = {2'b00, b_q} - {2'b00, c_f};
  // The selection of the current state (docs/algorithm.md).
  wire selx_f = rx_q & (~ry_q | ~hxy_q[HW-1]) & (~rz_q | ~hxz_q[HW-1]);
  wire sely_f = ~selx_f & ry_q & (~rz_q | ~hyz_q[HW-1]);
  wire selz_f = ~selx_f & ~sely_f & rz_q;
  wire [W:0] xp1_f = {1'b0, x_q} + {{W{1'b0}}, 1'b1};
  wire [W:0] yp1_f = {1'b0, y_q} + {{W{1'b0}}, 1'b1};
  wire [W:0] zp1_f = {1'b0, z_q} + {{W{1'b0}}, 1'b1};

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
      assert (nbz_q == ~b_q);
      assert (am2_q == a_q - two_w && bm2_q == b_q - two_w && cm2_q == c_f - two_w);
      assert (e0xy_q == (a_q[0] ^ b_q[0]) && e0xz_q == (a_q[0] ^ c_f[0]) && e0yz_q == (b_q[0] ^ c_f[0]));
      assert ({1'b0, p1_q} + {1'b0, p2_q} + {1'b0, p3_q} <= 2'd1);
      assert (ldph_q == (p1_q | p2_q | p3_q));
      assert (zxy_q == {NG{p1_q | p2_q}} && zxz_q == {NG{p1_q | p2_q}} && zyz_q == {NG{p1_q | p2_q}});
      assert (dsxy_q == {NG{p2_q}} && dsxz_q == {NG{p2_q}} && dsyz_q == {NG{p2_q}});
      assert (sxy_q == {NG{sx}} && sxz_q == {NG{sx}} && syz_q == {NG{sy}});
      assert ({mx_q, my_q, mz_q} == ({sx, sy, sz} & {3{act_q}}));
      assert ({kxy_q, kxz_q, kyz_q} == ({~sz, ~sy, ~sx} & {3{act_q}}));
      if (!p1_q) begin
        assert (nb_q == zero_h - b_h && nc_q == zero_h - {1'b0, c_f});
        assert ({dxy_q, e0xy_q} == dxy_f && {dxz_q, e0xz_q} == dxz_f && {dyz_q, e0yz_q} == dyz_f);
      end
      // No axis passes its end; the flags are the comparisons they stand for.
      assert (x_q <= a_q && y_q <= b_q && z_q <= c_f);
      assert (rx_q == (x_q < a_q) && ry_q == (y_q < b_q) && rz_q == (z_q < c_f));
      assert (lx_q == (xp1_f == {1'b0, a_q}) && ly_q == (yp1_f == {1'b0, b_q}) && lz_q == (zp1_f == {1'b0, c_f}));
      assert (o_done == (x_q == a_q && y_q == b_q && z_q == c_f));
      // At most one pulse per clock.
      assert (!(o_step_x && o_step_y) && !(o_step_x && o_step_z) && !(o_step_y && o_step_z));
      if (ldph_q) begin
        // Preparing: no step can come; nothing travelled yet.
        assert (!act_q);
        if (!p1_q) assert (s_q == 3'b000);
        assert (x_q == {W{1'b0}} && y_q == {W{1'b0}} && z_q == {W{1'b0}});
        assert (!o_step_x && !o_step_y && !o_step_z);
        if (p3_q) begin
          assert (cxy1_q == dxy_q && cxy2_q == dxy_q);
          assert (cxz1_q == dxz_q && cxz2_q == dxz_q);
          assert (cyz1_q == dyz_q && cyz2_q == dyz_q);
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
          assert (cxy1_q == hxy_q + nb_q && cxy2_q == hxy_q + a_h);
          assert (cxz1_q == hxz_q + nc_q && cxz2_q == hxz_q + a_h);
          assert (cyz1_q == hyz_q + nc_q && cyz2_q == hyz_q + b_h);
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
