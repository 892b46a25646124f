// dloop1l: dloop1.v (the step loop one step ahead) with a load in ONE clock
// that may be the clock of a step (as interp_dp loads the next block in the
// clock of the last pulse), kept off the loop's paths (issue 15;
// docs/rtl-proto.md). A timing prototype, not a core.
//
// The load edge clears the candidates (the flip-flops' own synchronous
// reset: no choice in front of them) and forces the choice: the first step
// of a move always goes inward (D = 0) and the second outward (D = -SUB < 0:
// SUB >= 1, as for every arc; lines need B >= 1). So the load gives the
// operands values that, from c_in = c_out = 0, give the candidates after
// the first step, and become the move's own by the first step's ordinary
// updates: n3 = ~(2 SUB - 2a) with c_in taking c_out + P3 (its select 0
// for that step) = -2 SUB + 2a, n2 = ~(SUB - 2a); a0 = ADD - SUB
// (c_out = c_in + A0), a1 = ADD, and the first step updates A0, A1 as an
// outward step does. After it: P2 = -SUB + 4a, P3 = -SUB + 2a, A0 = ADD,
// A1 = ADD + 2a, as after any inward step. The block supplies the fields
// (a block preparation would compute them); only D's (-SUB, the observe
// path) is read after the load clock, at the first step.
//
// Otherwise as dloop1.v: c_in = D - SUB, c_out = D + ADD split {H, k, L};
// P2 = -SUB + 2a, P3 = -SUB, A0 = ADD, A1 = ADD + 2a;
//   inward:  D <= c_in,  c_in <= c_in + P2,  c_out <= c_in + A0;  P3 <= P2, P2 += 2a
//   outward: D <= c_out, c_in <= c_out + P3, c_out <= c_out + A1; A0 <= A1, A1 += 2a
//   next g = !sign(g ? c_in : c_out)
//
// Timing: i_load in a clock (edge L) starts the move (D = 0); a step in the
// same clock still gives its pulse (of the move before). From the next
// clock on, one step in every clock with i_cmd high; o_pulse is high in the
// clock after a step with its choice o_g and the D after it (o_d).
//
// Reset: synchronous, on o_ready, o_pulse and the first-step flag.
`default_nettype none

module dloop1l #(
    parameter integer W = 24  // magnitude width: SUB, ADD W + 1 bits, D and every sum W + 2 (4..30)
) (
    input  wire         i_clk,
    input  wire         i_rst,
    input  wire         i_load,   // start the block below (D = 0)
    input  wire         i_arc,    // a: 1 arc, 0 line
    // The block, every field W + 2 bits, two's complement:
    input  wire [W+1:0] i_s2,     // SUB - 2a   (arc: SUB = 2|c_in| - 1; line: B >= 1)
    input  wire [W+1:0] i_a0,     // ADD        (arc: 2|c_out| + 1; line: A)
    input  wire [W+1:0] i_f1,     // 2 SUB - 2a
    input  wire [W+1:0] i_f2,     // ADD - SUB (two's complement)
    input  wire [W+1:0] i_f3,     // -SUB: D after the first step (observe path only)
    input  wire         i_cmd,    // one step in every clock where it and o_ready are high
    output wire         o_ready,  // a block was loaded
    output wire         o_pulse,  // a step was taken at the last edge
    output wire         o_g,      // its choice: 1 inward (D was >= 0), 0 outward
    output wire [W+1:0] o_d       // D after it (observe path)
);

  localparam integer N = W + 2;   // width of D, the sums and the operands
  localparam integer LW = N / 2;  // low part of a split sum
  localparam integer HW = N - LW; // high part

  // ---- control
  reg rdy_q;   // a block was loaded: commands are taken
  reg fst_q;   // the next step is the move's first (inward); it forces the second outward
  reg pul_q;   // o_pulse
  reg og_q;    // o_g
  reg a_q;     // the move is an arc

  // Selects: g, the choice of the step now (D >= 0), in copies that each
  // compute their own next value (so that yosys does not merge them):
  reg gm_q;    // output
  reg gci_q;   // c_in
  reg gco_q;   // c_out
  reg gd_q;    // D
  reg sn_q;    // enable of P2, P3: g
  reg sp_q;    // enable of A0, A1: !g, and 1 at the first step

  wire step = i_cmd & rdy_q;
  wire en = step | i_load;                // c, D, selects, fst_q
  wire en_n = (i_cmd & sn_q) | i_load;    // P2, P3
  wire en_p = (i_cmd & sp_q) | i_load;    // A0, A1

  // ---- state, split {H, k, L}
  reg [HW-1:0] cin_h, cout_h, dd_h;
  reg          cin_k, cout_k, dd_k;
  reg [LW-1:0] cin_l, cout_l, dd_l;

  // ---- operands
  reg [N-1:0] n2_q;  // ~(-P2) = ~(SUB - 2a)  (counter: += 2a on inward)
  reg [N-1:0] n3_q;  // ~(-P3) = ~SUB         (first step: ~(2 SUB - 2a))
  reg [N-1:0] a0_q;  // ADD                   (first step: ADD - SUB)
  reg [N-1:0] a1_q;  // ADD + 2a              (counter: += 2a on outward; first step: ADD)
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
      pul_q <= 1'b0;
      fst_q <= 1'b0;
    end else begin
      if (i_load) rdy_q <= 1'b1;
      pul_q <= step;
      if (en) fst_q <= i_load;
    end
  end

  always @(posedge i_clk) begin
    if (i_load) a_q <= i_arc;
    if (step) og_q <= gm_q;
  end

  // The selects: the load sets them for the first step (inward; c_in takes
  // c_out + P3), the first step forces the second outward; then the next
  // choice.
  always @(posedge i_clk) begin
    if (en) begin
      if (i_load) begin
        gm_q <= 1'b1;
        gci_q <= 1'b0;
        gco_q <= 1'b1;
        gd_q <= 1'b1;
        sn_q <= 1'b1;
        sp_q <= 1'b1;
      end else if (fst_q) begin
        gm_q <= 1'b0;
        gci_q <= 1'b0;
        gco_q <= 1'b0;
        gd_q <= 1'b0;
        sn_q <= 1'b0;
        sp_q <= 1'b1;
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
      if (i_load) begin  // the flip-flops' reset: D = c_in = c_out = 0
        {cin_h, cin_k, cin_l} <= {N + 1{1'b0}};
        {cout_h, cout_k, cout_l} <= {N + 1{1'b0}};
        {dd_h, dd_k, dd_l} <= {N + 1{1'b0}};
      end else begin
        {cin_h, cin_k, cin_l} <= gci_q ? {si_h, si_l} : {so_h, so_l};
        {cout_h, cout_k, cout_l} <= gco_q ? {ti_h, ti_l} : {to_h, to_l};
        if (fst_q) {dd_h, dd_k, dd_l} <= {i_f3[N-1:LW], 1'b0, i_f3[LW-1:0]};
        else {dd_h, dd_k, dd_l} <= gd_q ? {cin_h, cin_k, cin_l} : {cout_h, cout_k, cout_l};
      end
    end
  end

  // ---- operands
  always @(posedge i_clk) begin
    if (en_n) begin
      if (i_load) begin
        n2_q <= ~i_s2;
        n3_q <= ~i_f1;
        f2_q <= i_arc & (i_s2[LW-1:1] == {(LW - 1) {1'b0}});
      end else begin
        n2_q[LW-1:0] <= n2_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        n2_q[N-1:LW] <= n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, f2_q};
        f2_q <= a_q & (n2_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        n3_q <= n2_q;
      end
    end
    if (en_p) begin
      if (i_load) begin
        a0_q <= i_f2;
        a1_q <= i_a0;
        f1_q <= i_arc & (i_a0[LW-1:1] == {(LW - 1) {1'b1}});
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
