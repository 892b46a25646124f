// dloop1: the step loop prototype of dloop.v (same recurrence, ports and
// timing contract but the load time) built ONE step ahead: the candidates
// only, no sums two steps ahead. A comparison for issue 15
// (docs/rtl-proto.md): the choice of the next step is the sign of the
// candidate the choice now picks, resolved (H + k) from the candidate
// registers in the clock of the step: a 13-bit chain and two LUTs, as long
// as the sums' own path.
//
// The recurrence (docs/algorithm.md "Circular" inside one quadrant; line
// with a = 0): inward (g = 1, D >= 0): D -= SUB, SUB -= 2a; outward:
// D += ADD, ADD += 2a. Kept (modulo 2^(W+2)):
//   c_in = D - SUB, c_out = D + ADD                              (candidates)
//   P2 = -SUB + 2a, P3 = -SUB, A0 = ADD, A1 = ADD + 2a           (operands)
//   inward:  D <= c_in,  c_in <= c_in + P2,  c_out <= c_in + A0;  P3 <= P2, P2 += 2a
//   outward: D <= c_out, c_in <= c_out + P3, c_out <= c_out + A1; A0 <= A1, A1 += 2a
//   next g = !sign(g ? c_in : c_out)
// c_in, c_out, D are split {H, k, L} = ((H + k) << LW) + L as in dloop.v;
// P2, P3 are kept inverted (~(-P)), the adders' carry-in adding the 1; the
// counters P2, A1 add 2a to their low part and, by a registered overflow
// flag, 1 to their high part.
//
// Timing: i_load in a clock (edge L0) takes SUB, ADD, arc, clears c_in,
// c_out, D and sets g; edge L1 forms c_in = -SUB, c_out = ADD and the
// operands with the datapath's own adders; o_ready is high from L1 on and
// a command is taken from the clock after. Then one step in every clock
// with o_ready and i_cmd high; o_pulse is high in the clock after it with
// its choice o_g and the D after it (o_d, resolved on the observe path).
//
// Reset: synchronous, on the load phase, o_ready and o_pulse only.
`default_nettype none

module dloop1 #(
    parameter integer W = 24  // magnitude width: SUB, ADD W + 1 bits, D and every sum W + 2 (4..30)
) (
    input  wire         i_clk,
    input  wire         i_rst,
    input  wire         i_load,   // take i_sub, i_add, i_arc; D = 0
    input  wire         i_arc,    // 1: arc, 0: line (constant operands)
    input  wire [W:0]   i_sub,    // arc: 2|c_in| - 1 (1 .. 2^(W+1) - 1); line: B
    input  wire [W:0]   i_add,    // arc: 2|c_out| + 1; line: A
    input  wire         i_cmd,    // one step in every clock where it and o_ready are high
    output wire         o_ready,  // loaded and prepared
    output wire         o_pulse,  // a step was taken at the last edge
    output wire         o_g,      // its choice: 1 inward (D was >= 0), 0 outward
    output wire [W+1:0] o_d       // D after it (observe path)
);

  localparam integer N = W + 2;   // width of D, the sums and the operands
  localparam integer LW = N / 2;  // low part of a split sum
  localparam integer HW = N - LW; // high part

  // ---- control
  reg rdy_q;   // prepared: commands are taken
  reg ld1_q;   // the load phase: the clock after edge L0, in three copies, one
  reg ldn_q;   // per enable (yosys would merge equal flip-flops, abc then
  reg ldpp_q;  // build the enables on one shared LUT "ld1 | i_load")
  reg pul_q;   // o_pulse
  reg og_q;    // o_g
  reg a_q;     // the move is an arc

  // Selects: g, the choice of the step now (D >= 0), in copies that each
  // compute their own next value (so that yosys does not merge them):
  reg gm_q;    // output
  reg gci_q;   // c_in
  reg gco_q;   // c_out
  reg gd_q;    // D
  reg sn_q;    // g: enable of the operands P2, P3
  reg sp_q;    // !g: enable of A0, A1

  wire step = i_cmd & rdy_q;
  // Each enable is one LUT of registers (no enable formed from another).
  wire en = step | ld1_q | i_load;               // c, D, selects
  wire en_n = (i_cmd & sn_q) | ldn_q | i_load;   // P2, P3
  wire en_p = (i_cmd & sp_q) | ldpp_q | i_load;  // A0, A1

  // ---- state, split {H, k, L}
  reg [HW-1:0] cin_h, cout_h, dd_h;
  reg          cin_k, cout_k, dd_k;
  reg [LW-1:0] cin_l, cout_l, dd_l;

  // ---- operands
  reg [N-1:0] n2_q;  // ~(-P2) = ~(SUB - 2a)  (counter: += 2a on inward)
  reg [N-1:0] n3_q;  // ~(-P3) = ~SUB
  reg [N-1:0] a0_q;  // ADD
  reg [N-1:0] a1_q;  // ADD + 2a              (counter: += 2a on outward)
  reg         f2_q;  // n2's low part overflows on its next += 2a
  reg         f1_q;  // a1's low part overflows on its next += 2a

  // ---- the four sums
  wire [LW:0] si_l = {1'b0, cin_l} + {1'b0, n2_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};   // c_in + P2
  wire [LW:0] so_l = {1'b0, cout_l} + {1'b0, n3_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};  // c_out + P3
  wire [LW:0] ti_l = {1'b0, cin_l} + {1'b0, a0_q[LW-1:0]};                        // c_in + A0
  wire [LW:0] to_l = {1'b0, cout_l} + {1'b0, a1_q[LW-1:0]};                       // c_out + A1
  wire [HW-1:0] si_h = cin_h + n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] so_h = cout_h + n3_q[N-1:LW] + {{(HW - 1) {1'b0}}, cout_k};
  wire [HW-1:0] ti_h = cin_h + a0_q[N-1:LW] + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] to_h = cout_h + a1_q[N-1:LW] + {{(HW - 1) {1'b0}}, cout_k};

  // ---- resolved signs of the candidates (H + k: one chain each)
  wire [HW-1:0] rin = cin_h + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] rout = cout_h + {{(HW - 1) {1'b0}}, cout_k};
  wire s_in = rin[HW-1];
  wire s_out = rout[HW-1];

  // ---- control
  always @(posedge i_clk) begin
    if (i_rst) begin
      rdy_q <= 1'b0;
      ld1_q <= 1'b0;
      ldpp_q <= 1'b0;
      pul_q <= 1'b0;
    end else begin
      ld1_q <= i_load;
      // ld1_q & rdy_q never holds: it keeps ldpp_q apart from ld1_q.
      ldpp_q <= i_load | (ld1_q & rdy_q);
      if (i_load) rdy_q <= 1'b0;
      else if (ld1_q) rdy_q <= 1'b1;
      pul_q <= step & ~i_load;
    end
  end

  always @(posedge i_clk) begin
    ldn_q <= i_load;  // not reset: a shift of the operands before the first load is harmless
    if (i_load) a_q <= i_arc;
    if (step) og_q <= gm_q;
  end

  // The selects: 1 from edge L0 (phase 1 takes c_in + P2 = -SUB and
  // c_in + A0 = ADD from the cleared candidates), then the next choice,
  // which at edge L1 is 1 again (c_in = 0 in phase 1: D = 0 goes inward).
  always @(posedge i_clk) begin
    if (en) begin
      if (i_load) begin
        gm_q <= 1'b1;
        gci_q <= 1'b1;
        gco_q <= 1'b1;
        gd_q <= 1'b1;
        sn_q <= 1'b1;
        sp_q <= 1'b0;
      end else begin
        gm_q <= gm_q ? ~s_in : ~s_out;
        gci_q <= gci_q ? ~s_in : ~s_out;
        gco_q <= gco_q ? ~s_in : ~s_out;
        gd_q <= gd_q ? ~s_in : ~s_out;
        sn_q <= sn_q ? ~s_in : ~s_out;
        sp_q <= sp_q ? s_out : s_in;
      end
    end
  end

  // ---- datapath
  always @(posedge i_clk) begin
    if (en) begin
      if (i_load) begin
        {cin_h, cin_k, cin_l} <= {N + 1{1'b0}};
        {cout_h, cout_k, cout_l} <= {N + 1{1'b0}};
      end else begin
        {cin_h, cin_k, cin_l} <= gci_q ? {si_h, si_l} : {so_h, so_l};
        {cout_h, cout_k, cout_l} <= gco_q ? {ti_h, ti_l} : {to_h, to_l};
      end
      // D = 0 from the load until the first step
      if (i_load | ld1_q) {dd_h, dd_k, dd_l} <= {N + 1{1'b0}};
      else {dd_h, dd_k, dd_l} <= gd_q ? {cin_h, cin_k, cin_l} : {cout_h, cout_k, cout_l};
    end
  end

  // ---- operands
  always @(posedge i_clk) begin
    if (en_n) begin
      if (i_load) begin
        n2_q <= ~{1'b0, i_sub};
        n3_q <= ~{1'b0, i_sub};
        f2_q <= i_arc & (i_sub[LW-1:1] == {(LW - 1) {1'b0}});
      end else begin
        n2_q[LW-1:0] <= n2_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        n2_q[N-1:LW] <= n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, f2_q};
        f2_q <= a_q & (n2_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        n3_q <= n2_q;
      end
    end
    if (en_p) begin
      if (i_load) begin
        a1_q <= {1'b0, i_add};
        a0_q <= {1'b0, i_add};
        f1_q <= i_arc & (i_add[LW-1:1] == {(LW - 1) {1'b1}});
      end else begin
        a1_q[LW-1:0] <= a1_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        a1_q[N-1:LW] <= a1_q[N-1:LW] + {{(HW - 1) {1'b0}}, f1_q};
        f1_q <= a_q & (a1_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        a0_q <= a1_q;
      end
    end
  end

  assign o_ready = rdy_q;
  assign o_pulse = pul_q;
  assign o_g = og_q;
  assign o_d = {dd_h + {{(HW - 1) {1'b0}}, dd_k}, dd_l};

endmodule
