// interp3_core: paper A's reference-pulse linear interpolator extended to
// three axes (X, Y, Z), one interpolation step per clock.
//
// Executes the contract of docs/algorithm.md, "Linear on three axes"; the golden model is
// contour::Linear3<W> (model/interp/linear3.hpp). Registers:
//
//   a, b, c        W bits    |XE|, |YE|, |ZE| of the loaded move
//   x, y, z        W bits    distance travelled, 0..a, 0..b, 0..c
//   exy, exz, eyz  W+2 bits  two's complement discriminants
//                            exy = a(2y+1) - b(2x+1), exz = a(2z+1) - c(2x+1),
//                            eyz = b(2z+1) - c(2y+1)
//   rx, ry, rz     1 bit     distance left: rx = (x < a) etc., kept as
//                            registered flags so that no W-bit comparator
//                            sits between the registers and the selection
//
// Selection, from three sign bits and three flags only:
//   X  if rx and (not ry or exy >= 0) and (not rz or exz >= 0)
//   Y  else if ry and (not rz or eyz >= 0)
//   Z  otherwise
// Update (additions only; 2a is a shifted left by one):
//   X: x+1, exy -= 2b, exz -= 2c   Y: y+1, exy += 2a, eyz -= 2c
//   Z: z+1, exz += 2a, eyz += 2b
// Each discriminant has one adder whose operand is a two-way choice (or
// nothing); the distance-left flag of the moving axis is cleared when its
// incremented coordinate equals its end.
//
// Timing: i_load in a clock loads a move (x = y = z = 0, exy = a - b,
// exz = a - c, eyz = b - c) and takes priority over i_cmd; it may abandon a
// running move. In every later clock where i_cmd is high and the move is not
// done, one axis steps. Outputs are registered: o_step_* is high for the one
// clock after the step, together with the state after it (the model's
// "state read after the pulse is the state after the move"). o_done is high
// from the clock after the last step (at once after loading (0, 0, 0)).
//
// Reset: synchronous, active high. Every register is reset (to the state of
// the zero move, which is done), so the invariants hold from reset on.
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
    // Command: one interpolation step in every clock where it is high.
    input  wire           i_cmd,
    // Output pulse, registered: high in the clock after the step.
    output reg            o_step_x,
    output reg            o_step_y,
    output reg            o_step_z,
    output wire           o_dir_x,  // 1: minus direction (constant per move)
    output wire           o_dir_y,
    output wire           o_dir_z,
    output wire           o_done,   // the move has reached its end point
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

  localparam integer EW = W + 2;  // discriminant width

  reg [W-1:0] a_q, b_q, c_q;
  reg xneg_q, yneg_q, zneg_q;
  reg [W-1:0] x_q, y_q, z_q;
  reg [EW-1:0] exy_q, exz_q, eyz_q;
  reg rx_q, ry_q, rz_q;

  // ---------------------------------------------------------- selection
  wire done = ~(rx_q | ry_q | rz_q);
  wire exy_ge = ~exy_q[EW-1];
  wire exz_ge = ~exz_q[EW-1];
  wire eyz_ge = ~eyz_q[EW-1];
  wire sel_x = rx_q & (~ry_q | exy_ge) & (~rz_q | exz_ge);
  wire sel_y = ~sel_x & ry_q & (~rz_q | eyz_ge);
  wire sel_z = ~sel_x & ~sel_y;
  wire go = i_cmd & ~done & ~i_load;
  wire mv_x = go & sel_x;
  wire mv_y = go & sel_y;
  wire mv_z = go & sel_z;

  // -------------------------------------------------------- next values
  // 2a, 2b, 2c in EW bits (an end is below 2^W, so its double below 2^(W+1)).
  wire [EW-1:0] a2 = {1'b0, a_q, 1'b0};
  wire [EW-1:0] b2 = {1'b0, b_q, 1'b0};
  wire [EW-1:0] c2 = {1'b0, c_q, 1'b0};
  wire [W-1:0] x_inc = x_q + 1'b1;
  wire [W-1:0] y_inc = y_q + 1'b1;
  wire [W-1:0] z_inc = z_q + 1'b1;

  reg [W-1:0] x_d, y_d, z_d;
  reg [EW-1:0] exy_d, exz_d, eyz_d;
  reg rx_d, ry_d, rz_d;

  // Step: only the moving axis and the two discriminants it appears in change.
  always @(*) begin
    x_d = x_q;
    y_d = y_q;
    z_d = z_q;
    exy_d = exy_q;
    exz_d = exz_q;
    eyz_d = eyz_q;
    rx_d = rx_q;
    ry_d = ry_q;
    rz_d = rz_q;
    if (mv_x) begin
      x_d = x_inc;
      rx_d = x_inc != a_q;
      exy_d = exy_q - b2;
      exz_d = exz_q - c2;
    end
    if (mv_y) begin
      y_d = y_inc;
      ry_d = y_inc != b_q;
      exy_d = exy_q + a2;
      eyz_d = eyz_q - c2;
    end
    if (mv_z) begin
      z_d = z_inc;
      rz_d = z_inc != c_q;
      exz_d = exz_q + a2;
      eyz_d = eyz_q + b2;
    end
  end

  // Load values: exy = a - b etc., exact in EW bits (|a - b| < 2^W).
  wire [EW-1:0] ld_xe = {2'b00, i_xe};
  wire [EW-1:0] ld_ye = {2'b00, i_ye};
  wire [EW-1:0] ld_ze = {2'b00, i_ze};

  // Move constants: the ends and signs, taken at load.
  always @(posedge i_clk) begin
    if (i_rst) begin
      a_q <= {W{1'b0}};
      b_q <= {W{1'b0}};
      c_q <= {W{1'b0}};
      xneg_q <= 1'b0;
      yneg_q <= 1'b0;
      zneg_q <= 1'b0;
    end else if (i_load) begin
      a_q <= i_xe;
      b_q <= i_ye;
      c_q <= i_ze;
      xneg_q <= i_xneg;
      yneg_q <= i_yneg;
      zneg_q <= i_zneg;
    end
  end

  // Interpolation state: cleared by a load, stepped by a command.
  always @(posedge i_clk) begin
    if (i_rst) begin
      x_q <= {W{1'b0}};
      y_q <= {W{1'b0}};
      z_q <= {W{1'b0}};
      exy_q <= {EW{1'b0}};
      exz_q <= {EW{1'b0}};
      eyz_q <= {EW{1'b0}};
      rx_q <= 1'b0;
      ry_q <= 1'b0;
      rz_q <= 1'b0;
    end else if (i_load) begin
      x_q <= {W{1'b0}};
      y_q <= {W{1'b0}};
      z_q <= {W{1'b0}};
      exy_q <= ld_xe - ld_ye;
      exz_q <= ld_xe - ld_ze;
      eyz_q <= ld_ye - ld_ze;
      rx_q <= |i_xe;
      ry_q <= |i_ye;
      rz_q <= |i_ze;
    end else begin
      x_q <= x_d;
      y_q <= y_d;
      z_q <= z_d;
      exy_q <= exy_d;
      exz_q <= exz_d;
      eyz_q <= eyz_d;
      rx_q <= rx_d;
      ry_q <= ry_d;
      rz_q <= rz_d;
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
  assign o_done = done;
  assign o_x = x_q;
  assign o_y = y_q;
  assign o_z = z_q;
  assign o_exy = exy_q;
  assign o_exz = exz_q;
  assign o_eyz = eyz_q;

`ifdef FORMAL
  // ------------------------------------------------------------- formal
  // Proved at a small W by rtl/interp3/formal/prove.sh (ctest interp3_formal):
  // every property below holds in every reachable state, for every move
  // and every command sequence (k-induction from reset).
  //
  // The discriminants in exact arithmetic: the products are taken at
  // their full width (W x (W+1) bits), the differences in FW = 2W+3 bits,
  // so nothing wraps; the registers, sign-extended, must equal them, so no
  // addition ever overflowed its W+2 bits.
  localparam integer FW = 2 * W + 3;
  wire [W:0] x2_f = {x_q, 1'b1};  // 2x + 1
  wire [W:0] y2_f = {y_q, 1'b1};
  wire [W:0] z2_f = {z_q, 1'b1};
  wire [2*W:0] ay_f = a_q * y2_f;
  wire [2*W:0] az_f = a_q * z2_f;
  wire [2*W:0] bx_f = b_q * x2_f;
  wire [2*W:0] bz_f = b_q * z2_f;
  wire [2*W:0] cx_f = c_q * x2_f;
  wire [2*W:0] cy_f = c_q * y2_f;
  wire [FW-1:0] exy_x = {2'b00, ay_f} - {2'b00, bx_f};
  wire [FW-1:0] exz_x = {2'b00, az_f} - {2'b00, cx_f};
  wire [FW-1:0] eyz_x = {2'b00, bz_f} - {2'b00, cy_f};
  // Registers sign-extended, and the range bounds 2A, -2B etc.
  wire signed [FW-1:0] exy_f = $signed({{(FW-EW){exy_q[EW-1]}}, exy_q});
  wire signed [FW-1:0] exz_f = $signed({{(FW-EW){exz_q[EW-1]}}, exz_q});
  wire signed [FW-1:0] eyz_f = $signed({{(FW-EW){eyz_q[EW-1]}}, eyz_q});
  wire signed [FW-1:0] a2_f = $signed({{(FW-EW){1'b0}}, a2});
  wire signed [FW-1:0] b2_f = $signed({{(FW-EW){1'b0}}, b2});
  wire signed [FW-1:0] c2_f = $signed({{(FW-EW){1'b0}}, c2});

  reg past_valid_f;
  initial past_valid_f = 1'b0;
  always @(posedge i_clk) past_valid_f <= 1'b1;

  // The first clock is a reset (the state before it is arbitrary).
  always @(*) begin
    if (!past_valid_f) assume (i_rst);
  end

  // Invariants of every state (docs/algorithm.md, "Linear on three axes", "Registers").
  always @(*) begin
    if (past_valid_f) begin
      // Three discriminant invariants, exactly.
      assert (exy_f == $signed(exy_x));
      assert (exz_f == $signed(exz_x));
      assert (eyz_f == $signed(eyz_x));
      // Their ranges: Exy in [-2B, 2A], Exz in [-2C, 2A], Eyz in [-2C, 2B].
      assert (exy_f >= -b2_f && exy_f <= a2_f);
      assert (exz_f >= -c2_f && exz_f <= a2_f);
      assert (eyz_f >= -c2_f && eyz_f <= b2_f);
      // No axis passes its end; the flags are the comparisons they stand for.
      assert (x_q <= a_q && y_q <= b_q && z_q <= c_q);
      assert (rx_q == (x_q < a_q) && ry_q == (y_q < b_q) && rz_q == (z_q < c_q));
      assert (o_done == (x_q == a_q && y_q == b_q && z_q == c_q));
      // At most one pulse per clock.
      assert (!(o_step_x && o_step_y) && !(o_step_x && o_step_z) && !(o_step_y && o_step_z));
      // The moving axis is never one with no distance left.
      assert (!(go && sel_x && !rx_q) && !(go && sel_y && !ry_q) && !(go && sel_z && !rz_q));
    end
  end

  // Transitions, on the next-state values (the outputs are their
  // registered copies): a command while not done moves exactly one axis,
  // by exactly one unit, and nothing moves otherwise.
  always @(*) begin
    if (past_valid_f) begin
      assert ({1'b0, mv_x} + {1'b0, mv_y} + {1'b0, mv_z} == {1'b0, go});
      assert (x_d == x_q + {{(W-1){1'b0}}, mv_x});
      assert (y_d == y_q + {{(W-1){1'b0}}, mv_y});
      assert (z_d == z_q + {{(W-1){1'b0}}, mv_z});
    end
  end
`endif

endmodule
