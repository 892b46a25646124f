// dloop: a timing prototype (issue 15) of paper A's step loop alone, the
// recurrence of docs/algorithm.md "Circular" inside one quadrant (and the
// line's, with constant operands), built two steps ahead in the manner of
// interp3_core (docs/rtl-3axis.md, "Timing structure"). Not a core: no
// end-point rule, no quadrant crossing, no k; it answers what that
// structure costs in LCs and what Fmax it reaches (docs/rtl-proto.md).
//
// The recurrence: D (W + 2 bits), SUB, ADD; arc a = 1 or line a = 0.
//   inward  (g = 1, D >= 0): D -= SUB, SUB -= 2a
//   outward (g = 0, D <  0): D += ADD, ADD += 2a
// Arc: SUB = 2|in| - 1, ADD = 2|out| + 1; line: SUB = B, ADD = A.
//
// Kept two steps ahead (every value modulo 2^(W+2); only the candidate that
// becomes D must be in range, and it is, being the contract's D):
//   c_in  = D - SUB,                c_out = D + ADD         (candidates)
//   d_ii  = D - SUB - (SUB - 2a),   d_io  = D - SUB + ADD,
//   d_oo  = D + ADD + (ADD + 2a)                            (two ahead)
// with the operands P1 = -SUB + 4a, P2 = -SUB + 2a, P3 = -SUB,
// P4 = ADD + 2a, P5 = ADD + 4a and the five sums
//   S1 = d_ii + P1, S2 = d_io + P2, S3 = d_oo + P3, S4 = d_io + P4, S5 = d_oo + P5:
//   inward:  D <= c_in,  c_in <= d_ii, c_out <= d_io,
//            d_ii <= S1, d_io <= S2, d_oo <= S4;   P3 <= P2, P2 <= P1, P1 += 2a
//   outward: D <= c_out, c_in <= d_io, c_out <= d_oo,
//            d_ii <= S2, d_io <= S3, d_oo <= S5;   P4 <= P5, P5 += 2a
// The next choice is sign(g ? c_in : c_out): one LUT of registered signs.
//
// Timing structure (every chain starts at registers, at most 13 bits at
// W = 24, at most two LUTs behind it, none in front):
//   - split sums: each of d, c, D is {H, k, L} standing for
//     ((H + k) << LW) + L: adding an operand is L + op_lo (+ 1) -> L', k'
//     and H + op_hi + k -> H', two chains that do not wait for each other;
//   - resolved signs: sign(H + k) of each d (one HW-bit chain), chosen into
//     the sign registers of c_in, c_out by the select;
//   - the P1..P3 operands are kept inverted (~(-P) = P - 1, the adder's
//     carry-in adds the 1), P2, P3, P4 are shifted copies; the counters P1,
//     P5 add 2a to their low part and, by a registered "it overflows" flag,
//     1 to their high part (no 26-bit ripple);
//   - the selects are six copies of g, each computing its own next value
//     (so that yosys does not merge them), 2..54 multiplexers each, and
//     two more (sn_q, sp_q) are the operands' shift enables;
//   - every clock enable is one LUT of registers and i_cmd / i_load (the
//     load-phase flag has a copy per enable: abc built them on a shared
//     LUT otherwise, two levels into 250 flip-flops' enables).
//
// Timing: i_load in a clock (edge L0) takes SUB, ADD, arc and sets D = 0;
// edges L1, L2 form the candidates, sums and operands with the datapath's
// own adders; o_ready is high from L2 on and a command is taken from the
// clock after. In every clock with o_ready and i_cmd high one step is
// taken; o_pulse is high in the clock after it with its choice o_g and the
// D after it (o_d: H + k, one more chain on the observe path only).
//
// Reset: synchronous, on the load phases, o_ready and o_pulse only (the
// rest is read only after a load has set it).
`default_nettype none

module dloop #(
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
  reg rdy_q;  // prepared: commands are taken
  reg ld1_q;  // load phase 1: the clock after edge L0
  reg ld2_q;  // load phase 2: the clock after edge L1
  reg ldp_q;  // ld1_q | ld2_q, in three copies, one per enable (ldn_q, ldpp_q:
  reg ldn_q;  // yosys would merge equal flip-flops, and abc would then build
  reg ldpp_q; // the three enables on one shared LUT "ldp | i_load": two levels)
  reg pul_q;  // o_pulse
  reg og_q;   // o_g
  reg a_q;    // the move is an arc

  // Selects: g, the choice of the step now (D >= 0), in six copies:
  reg gm_q;   // signs, output
  reg gii_q;  // d_ii
  reg gio_q;  // d_io
  reg goo_q;  // d_oo
  reg gc_q;   // c_in, c_out
  reg gd_q;   // D
  // Operand shift enables: the step now is inward (sn) / outward (sp).
  reg sn_q;
  reg sp_q;

  wire step = i_cmd & rdy_q;
  // Each enable is one LUT of registers (no enable formed from another).
  wire en = step | ldp_q | i_load;           // d, c, D, signs, selects
  wire en_n = (i_cmd & sn_q) | ldn_q | i_load;  // P1..P3
  wire en_p = (i_cmd & sp_q) | ldpp_q | i_load;  // P4, P5

  // ---- state, split {H, k, L}
  reg [HW-1:0] dii_h, dio_h, doo_h, cin_h, cout_h, dd_h;
  reg          dii_k, dio_k, doo_k, cin_k, cout_k, dd_k;
  reg [LW-1:0] dii_l, dio_l, doo_l, cin_l, cout_l, dd_l;
  reg scin_q;   // sign of c_in  (1: negative)
  reg scout_q;  // sign of c_out

  // ---- operands
  reg [N-1:0] n1_q;  // ~(-P1) = ~(SUB - 4a)  (counter: += 2a on inward)
  reg [N-1:0] n2_q;  // ~(SUB - 2a)
  reg [N-1:0] n3_q;  // ~SUB
  reg [N-1:0] p4_q;  // ADD + 2a
  reg [N-1:0] p5_q;  // ADD + 4a                (counter: += 2a on outward)
  reg         f1_q;  // n1's low part overflows on its next += 2a
  reg         f5_q;  // p5's low part overflows on its next += 2a

  // ---- the five sums
  wire [LW:0] s1_l = {1'b0, dii_l} + {1'b0, n1_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};
  wire [LW:0] s2_l = {1'b0, dio_l} + {1'b0, n2_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};
  wire [LW:0] s3_l = {1'b0, doo_l} + {1'b0, n3_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};
  wire [LW:0] s4_l = {1'b0, dio_l} + {1'b0, p4_q[LW-1:0]};
  wire [LW:0] s5_l = {1'b0, doo_l} + {1'b0, p5_q[LW-1:0]};
  wire [HW-1:0] s1_h = dii_h + n1_q[N-1:LW] + {{(HW - 1) {1'b0}}, dii_k};
  wire [HW-1:0] s2_h = dio_h + n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, dio_k};
  wire [HW-1:0] s3_h = doo_h + n3_q[N-1:LW] + {{(HW - 1) {1'b0}}, doo_k};
  wire [HW-1:0] s4_h = dio_h + p4_q[N-1:LW] + {{(HW - 1) {1'b0}}, dio_k};
  wire [HW-1:0] s5_h = doo_h + p5_q[N-1:LW] + {{(HW - 1) {1'b0}}, doo_k};

  // ---- resolved signs of the d (H + k: one chain each)
  wire [HW-1:0] rii = dii_h + {{(HW - 1) {1'b0}}, dii_k};
  wire [HW-1:0] rio = dio_h + {{(HW - 1) {1'b0}}, dio_k};
  wire [HW-1:0] roo = doo_h + {{(HW - 1) {1'b0}}, doo_k};
  wire s_ii = rii[HW-1];
  wire s_io = rio[HW-1];
  wire s_oo = roo[HW-1];

  // ---- control
  always @(posedge i_clk) begin
    if (i_rst) begin
      rdy_q <= 1'b0;
      ld1_q <= 1'b0;
      ld2_q <= 1'b0;
      ldp_q <= 1'b0;
      ldpp_q <= 1'b0;
      pul_q <= 1'b0;
    end else begin
      ld1_q <= i_load;
      ld2_q <= ld1_q & ~i_load;
      ldp_q <= i_load | ld1_q;
      // ld2_q & rdy_q never holds: it keeps ldpp_q apart from ldp_q.
      ldpp_q <= i_load | ld1_q | (ld2_q & rdy_q);
      if (i_load) rdy_q <= 1'b0;
      else if (ld2_q) rdy_q <= 1'b1;
      pul_q <= step & ~i_load;
    end
  end

  always @(posedge i_clk) begin
    ldn_q <= i_load | ld1_q;  // not reset: a shift of the operands before the first load is harmless
    if (i_load) a_q <= i_arc;
    if (step) og_q <= gm_q;
  end

  // The selects. Edge L1 sets them for phase 2 (d_ii takes S1, d_io S3,
  // d_oo S5, c_in d_io, c_out d_oo, the signs likewise); edge L2 to 1
  // (D = 0: the first step goes inward); a step to the next choice.
  always @(posedge i_clk) begin
    if (en) begin
      if (i_load) begin
        gm_q <= 1'b0;
        gii_q <= 1'b0;
        gio_q <= 1'b0;
        goo_q <= 1'b0;
        gc_q <= 1'b0;
        gd_q <= 1'b0;
      end else if (ld1_q) begin
        gm_q <= 1'b0;
        gii_q <= 1'b1;
        gio_q <= 1'b0;
        goo_q <= 1'b0;
        gc_q <= 1'b0;
        gd_q <= 1'b0;
      end else if (ld2_q) begin
        gm_q <= 1'b1;
        gii_q <= 1'b1;
        gio_q <= 1'b1;
        goo_q <= 1'b1;
        gc_q <= 1'b1;
        gd_q <= 1'b1;
      end else begin
        gm_q <= gm_q ? ~scin_q : ~scout_q;
        gii_q <= gii_q ? ~scin_q : ~scout_q;
        gio_q <= gio_q ? ~scin_q : ~scout_q;
        goo_q <= goo_q ? ~scin_q : ~scout_q;
        gc_q <= gc_q ? ~scin_q : ~scout_q;
        gd_q <= gd_q ? ~scin_q : ~scout_q;
      end
    end
  end

  // Operand shift enables: 1 / 0 from the load phases (edge L2: D = 0, the
  // first step goes inward), then each its own copy of the choice (sp_q
  // negated). Not reset: until a load they only shift operands no step reads.
  always @(posedge i_clk) begin
    if (en) begin
      if (ldp_q) begin
        sn_q <= 1'b1;
        sp_q <= 1'b0;
      end else begin
        sn_q <= sn_q ? ~scin_q : ~scout_q;
        sp_q <= sp_q ? scout_q : scin_q;
      end
    end
  end

  // ---- datapath
  always @(posedge i_clk) begin
    if (en) begin
      if (i_load) begin
        {dii_h, dii_k, dii_l} <= {N + 1{1'b0}};
        {dio_h, dio_k, dio_l} <= {N + 1{1'b0}};
        {doo_h, doo_k, doo_l} <= {N + 1{1'b0}};
      end else begin
        {dii_h, dii_k, dii_l} <= gii_q ? {s1_h, s1_l} : {s2_h, s2_l};
        {dio_h, dio_k, dio_l} <= gio_q ? {s2_h, s2_l} : {s3_h, s3_l};
        {doo_h, doo_k, doo_l} <= goo_q ? {s4_h, s4_l} : {s5_h, s5_l};
      end
      {cin_h, cin_k, cin_l} <= gc_q ? {dii_h, dii_k, dii_l} : {dio_h, dio_k, dio_l};
      {cout_h, cout_k, cout_l} <= gc_q ? {dio_h, dio_k, dio_l} : {doo_h, doo_k, doo_l};
      scin_q <= gm_q ? s_ii : s_io;
      scout_q <= gm_q ? s_io : s_oo;
    end
    if (en) begin  // D = 0 from the load until the first step
      if (i_load | ldp_q) {dd_h, dd_k, dd_l} <= {N + 1{1'b0}};
      else {dd_h, dd_k, dd_l} <= gd_q ? {cin_h, cin_k, cin_l} : {cout_h, cout_k, cout_l};
    end
  end

  // ---- operands
  always @(posedge i_clk) begin
    if (en_n) begin
      if (i_load) begin
        n1_q <= ~{1'b0, i_sub};
        n2_q <= ~{1'b0, i_sub};
        n3_q <= ~{1'b0, i_sub};
        f1_q <= i_arc & (i_sub[LW-1:1] == {(LW - 1) {1'b0}});
      end else begin
        n1_q[LW-1:0] <= n1_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        n1_q[N-1:LW] <= n1_q[N-1:LW] + {{(HW - 1) {1'b0}}, f1_q};
        f1_q <= a_q & (n1_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        n2_q <= n1_q;
        n3_q <= n2_q;
      end
    end
    if (en_p) begin
      if (i_load) begin
        p5_q <= {1'b0, i_add};
        p4_q <= {1'b0, i_add};
        f5_q <= i_arc & (i_add[LW-1:1] == {(LW - 1) {1'b1}});
      end else begin
        p5_q[LW-1:0] <= p5_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        p5_q[N-1:LW] <= p5_q[N-1:LW] + {{(HW - 1) {1'b0}}, f5_q};
        f5_q <= a_q & (p5_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        p4_q <= p5_q;
      end
    end
  end

  assign o_ready = rdy_q;
  assign o_pulse = pul_q;
  assign o_g = og_q;
  assign o_d = {dd_h + {{(HW - 1) {1'b0}}, dd_k}, dd_l};

endmodule
