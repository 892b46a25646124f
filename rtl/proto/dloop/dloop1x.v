// dloop1x: dloop1l.v (the step loop one step ahead, one-clock load) with
// quadrant crossings in flight (issue 15; docs/rtl-proto.md). A timing
// prototype, not a core: no end-point rule, no k (an arc runs on round the
// circle as long as commands come).
//
// A crossing is the inward step from |in| = 1: after it the inward axis is
// the old outward one, SUB' = ADD - 2, ADD' = 1, and the candidates are
// c_in = c_in - ADD + 2, c_out = c_in + 1. While |in| = 1 ("armed", i1_q)
// the inward step's operands already hold those values: P2 = -(ADD - 2)
// (n2 = ~(ADD - 2), from the copy r = ADD - 2 when armed, from ~ADD on
// each outward step while armed) and the inward ADD operand ta = 1; the
// loop's sums and choices are dloop1l's, unchanged. The crossing step's
// ordinary updates then give the new quadrant's P3 = -SUB', P2 = -SUB' + 2
// (also when the new |in| is 1 again); ADD + 2a, the true ADD and r take
// the constants 3, 1, -1 by the flip-flops' reset/set. |in| = 1 and
// |in| = 2 are registers (i1_q, i2_q), set on inward steps from a compare
// of n2 or, at a crossing, of the true ADD (registered compares a3_q, a5_q).
//
// Everything else as dloop1l.v: c_in = D - SUB, c_out = D + ADD split
// {H, k, L}; P2 = -SUB + 2a (n2), P3 = -SUB (n3), ta = ADD (1 when armed),
// A1 = ADD + 2a (a1), at = ADD, r = ADD - 2;
//   inward:  D <= c_in,  c_in <= c_in + P2,  c_out <= c_in + ta
//   outward: D <= c_out, c_in <= c_out + P3, c_out <= c_out + A1
//   next g = !sign(g ? c_in : c_out)
// The load clears the candidates and forces the first two choices (in,
// out); the block's fields make the first step's operands. Arcs must start
// with |in| >= 2 (SUB >= 3); lines need B >= 1.
//
// Timing: i_load in a clock (edge L) starts the move (D = 0); a step in the
// same clock still gives its pulse. From the next clock on, one step in
// every clock with i_cmd high; o_pulse is high in the clock after a step
// with its choice o_g, o_cross (it crossed onto the next quadrant) and the
// D after it (o_d).
//
// Reset: synchronous, on o_ready, o_pulse and the first-step flag.
`default_nettype none

module dloop1x #(
    parameter integer W = 24  // magnitude width: SUB, ADD W + 1 bits, D and every sum W + 2 (4..30)
) (
    input  wire         i_clk,
    input  wire         i_rst,
    input  wire         i_load,   // start the block below (D = 0)
    input  wire         i_arc,    // a: 1 arc, 0 line
    // The block, every field W + 2 bits, two's complement:
    input  wire [W+1:0] i_s2,     // SUB - 2a   (arc: SUB = 2|c_in| - 1; line: B >= 1)
    input  wire [W+1:0] i_a0,     // ADD        (arc: 2|c_out| + 1; line: A)
    input  wire [W+1:0] i_r,      // ADD - 2
    input  wire [W+1:0] i_f1,     // 2 SUB - 2a
    input  wire [W+1:0] i_f2,     // ADD - SUB (two's complement)
    input  wire [W+1:0] i_f3,     // -SUB: D after the first step (observe path only)
    input  wire         i_cmd,    // one step in every clock where it and o_ready are high
    output wire         o_ready,  // a block was loaded
    output wire         o_pulse,  // a step was taken at the last edge
    output wire         o_g,      // its choice: 1 inward (D was >= 0), 0 outward
    output wire         o_cross,  // it crossed onto the next quadrant
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
  reg ox_q;    // o_cross
  reg a_q;     // the move is an arc (n2's counter); a copy for a1's:
  reg ap_q;    // (the counters' chains are far apart; reset, so that yosys does not merge the two)

  // Selects: g, the choice of the step now (D >= 0), in copies that each
  // compute their own next value (so that yosys does not merge them):
  reg gm_q;    // output
  reg gci_q;   // c_in
  reg gco_q;   // c_out
  reg gd_q;    // D
  reg sn_q;    // enable of P2, P3: g
  reg sp_q;    // enable of ta, a1, at: !g, and 1 at the first step
  reg sr_q;    // enable of r: !g (0 at the first step)
  reg i1_q;    // |in| = 1: armed, the next inward step crosses
  reg i2_q;    // |in| = 2: the next inward step arms

  wire step = i_cmd & rdy_q;
  // The enables, each i_load | i_cmd & (x | y) of registers x, y: one LUT4
  // each, instantiated for synthesis (abc built one from another's product
  // otherwise: two levels into their flip-flops' enables).
  wire en;     // c, D, selects, fst_q: a step or the load
  wire en_n;   // n3, i1, i2: inward
  wire en_n2;  // n2: inward, or outward while armed
  wire en_t;   // ta: outward, first step, arming
  wire en_p;   // a1, at: outward, first step, crossing
  wire en_r;   // r: outward, crossing
`ifdef SYNTHESIS
  localparam [15:0] EN_LUT = 16'hFFA8;  // O = I3 | I0 & (I1 | I2)
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en (.O(en), .I0(i_cmd), .I1(rdy_q), .I2(1'b0), .I3(i_load));
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en_n (.O(en_n), .I0(i_cmd), .I1(sn_q), .I2(1'b0), .I3(i_load));
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en_n2 (.O(en_n2), .I0(i_cmd), .I1(sn_q), .I2(i1_q), .I3(i_load));
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en_t (.O(en_t), .I0(i_cmd), .I1(sp_q), .I2(i2_q), .I3(i_load));
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en_p (.O(en_p), .I0(i_cmd), .I1(sp_q), .I2(i1_q), .I3(i_load));
  SB_LUT4 #(.LUT_INIT(EN_LUT)) u_en_r (.O(en_r), .I0(i_cmd), .I1(sr_q), .I2(i1_q), .I3(i_load));
`else
  assign en = step | i_load;
  assign en_n = (i_cmd & sn_q) | i_load;
  assign en_n2 = (i_cmd & (sn_q | i1_q)) | i_load;
  assign en_t = (i_cmd & (sp_q | i2_q)) | i_load;
  assign en_p = (i_cmd & (sp_q | i1_q)) | i_load;
  assign en_r = (i_cmd & (sr_q | i1_q)) | i_load;
`endif
  // Reset/set of the operands (registers only; the iCE40 flip-flop resets
  // only when enabled): the crossing, and ta = 1 while armed or arming.
  wire xing = ~i_load & gm_q & i1_q;
  wire t_one = ~i_load & (i1_q | (gm_q & i2_q));

  // ---- state, split {H, k, L}
  reg [HW-1:0] cin_h, cout_h, dd_h;
  reg          cin_k, cout_k, dd_k;
  reg [LW-1:0] cin_l, cout_l, dd_l;

  // ---- operands
  reg [N-1:0] n2_q;  // ~(-P2) = ~(SUB - 2a)  (counter: += 2a on inward)
  reg [N-1:0] n3_q;  // ~(-P3) = ~SUB         (first step: ~(2 SUB - 2a))
  reg [N-1:0] ta_q;  // ADD, 1 when armed    (first step: ADD - SUB): the inward ADD operand
  reg [N-1:0] a1_q;  // ADD + 2a              (counter: += 2a on outward; first step: ADD)
  reg [N-1:0] at_q;  // ADD
  reg [N-1:0] r_q;   // ADD - 2
  reg         a3_q;  // at = 3 (a crossing now makes |in| = 1)
  reg         a5_q;  // at = 5 (... |in| = 2)
  reg         f2_q;  // n2's low part overflows on its next += 2a
  reg         f1_q;  // a1's low part overflows on its next += 2a

  // ---- the four sums
  wire [LW:0] si_l = {1'b0, cin_l} + {1'b0, n2_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};   // c_in + P2
  wire [LW:0] so_l = {1'b0, cout_l} + {1'b0, n3_q[LW-1:0]} + {{LW{1'b0}}, 1'b1};  // c_out + P3
  wire [LW:0] ti_l = {1'b0, cin_l} + {1'b0, ta_q[LW-1:0]};                        // c_in + ta
  wire [LW:0] to_l = {1'b0, cout_l} + {1'b0, a1_q[LW-1:0]};                       // c_out + A1
  wire [HW-1:0] si_h = cin_h + n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] so_h = cout_h + n3_q[N-1:LW] + {{(HW - 1) {1'b0}}, cout_k};
  wire [HW-1:0] ti_h = cin_h + ta_q[N-1:LW] + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] to_h = cout_h + a1_q[N-1:LW] + {{(HW - 1) {1'b0}}, cout_k};

  // ---- resolved signs of the candidates (H + k: one chain each)
  wire [HW-1:0] rin = cin_h + {{(HW - 1) {1'b0}}, cin_k};
  wire [HW-1:0] rout = cout_h + {{(HW - 1) {1'b0}}, cout_k};
  wire s_in = rin[HW-1];
  wire s_out = rout[HW-1];

  // ---- control
  always @(posedge i_clk) begin
    if (i_rst) begin
      ap_q <= 1'b0;
      rdy_q <= 1'b0;
      pul_q <= 1'b0;
      fst_q <= 1'b0;
    end else begin
      if (i_load) ap_q <= i_arc;
      if (i_load) rdy_q <= 1'b1;
      pul_q <= step;
      if (en) fst_q <= i_load;
    end
  end

  always @(posedge i_clk) begin
    if (i_load) a_q <= i_arc;
    if (step) begin
      og_q <= gm_q;
      ox_q <= gm_q & i1_q;
    end
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
        sr_q <= 1'b0;
      end else if (fst_q) begin
        gm_q <= 1'b0;
        gci_q <= 1'b0;
        gco_q <= 1'b0;
        gd_q <= 1'b0;
        sn_q <= 1'b0;
        sp_q <= 1'b1;
        sr_q <= 1'b1;
      end else begin
        gm_q <= gm_q ? ~s_in : ~s_out;
        gci_q <= gci_q ? ~s_in : ~s_out;
        gco_q <= gco_q ? ~s_in : ~s_out;
        gd_q <= gd_q ? ~s_in : ~s_out;
        sn_q <= sn_q ? ~s_in : ~s_out;
        sp_q <= sp_q ? s_out : s_in;
        sr_q <= sr_q ? s_out : s_in;
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
  // n2's other sources (arming: ~r; outward while armed: ~ADD), chosen by
  // registers, so that one LUT follows the counter's chain.
  wire n2_alt = gm_q ? i2_q : i1_q;
  // Kept nets: abc would otherwise put two LUTs behind the counter's chain.
  (* keep *) wire n2_sel = i_load | n2_alt;
  (* keep *) wire [N-1:0] n2_src = i_load ? ~i_s2 : gm_q ? ~r_q : ~at_q;
  wire n2_srcf = i_load ? (i_s2[LW-1:1] == {(LW - 1) {1'b0}}) & i_arc
               : gm_q ? (r_q[LW-1:1] == {(LW - 1) {1'b0}}) : (at_q[LW-1:1] == {(LW - 1) {1'b0}});
  always @(posedge i_clk) begin
    if (en_n2) begin
      if (n2_sel) begin
        n2_q <= n2_src;
        f2_q <= n2_srcf;
      end else begin
        n2_q[LW-1:0] <= n2_q[LW-1:0] + {{(LW - 2) {1'b0}}, a_q, 1'b0};
        n2_q[N-1:LW] <= n2_q[N-1:LW] + {{(HW - 1) {1'b0}}, f2_q};
        f2_q <= a_q & (n2_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
      end
    end
    if (en_n) begin
      if (i_load) begin
        n3_q <= ~i_f1;
        i1_q <= 1'b0;
        i2_q <= i_arc & (i_s2 == {{(N - 1) {1'b0}}, 1'b1});
      end else begin
        n3_q <= n2_q;
        i1_q <= i1_q ? a3_q : i2_q;
        i2_q <= i1_q ? a5_q : a_q & (n2_q == ~{{(N - 2) {1'b0}}, 2'b11});
      end
    end
    if (en_t) begin
      if (t_one) ta_q <= {{(N - 1) {1'b0}}, 1'b1};
      else if (i_load) ta_q <= i_f2;
      else ta_q <= a1_q;
    end
    if (en_p) begin
      if (xing) begin  // the new quadrant: ADD = 1
        a1_q <= {{(N - 2) {1'b0}}, 2'b11};
        at_q <= {{(N - 1) {1'b0}}, 1'b1};
        f1_q <= 1'b0;
        a3_q <= 1'b0;
        a5_q <= 1'b0;
      end else if (i_load) begin
        a1_q <= i_a0;
        at_q <= i_a0;
        f1_q <= i_arc & (i_a0[LW-1:1] == {(LW - 1) {1'b1}});
        a3_q <= i_a0 == {{(N - 2) {1'b0}}, 2'b11};
        a5_q <= i_a0 == {{(N - 3) {1'b0}}, 3'b101};
      end else begin
        a1_q[LW-1:0] <= a1_q[LW-1:0] + {{(LW - 2) {1'b0}}, ap_q, 1'b0};
        a1_q[N-1:LW] <= a1_q[N-1:LW] + {{(HW - 1) {1'b0}}, f1_q};
        f1_q <= ap_q & (a1_q[LW-1:1] == {{(LW - 2) {1'b1}}, 1'b0});
        at_q <= a1_q;
        a3_q <= a1_q == {{(N - 2) {1'b0}}, 2'b11};
        a5_q <= a1_q == {{(N - 3) {1'b0}}, 3'b101};
      end
    end
    if (en_r) begin
      if (xing) r_q <= {N{1'b1}};
      else if (i_load) r_q <= i_r;
      else r_q <= at_q;
    end
  end

  assign o_ready = rdy_q;
  assign o_pulse = pul_q;
  assign o_g = og_q;
  assign o_cross = ox_q;
  assign o_d = {dd_h + {{(HW - 1) {1'b0}}, dd_k}, dd_l};

endmodule
