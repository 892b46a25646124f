// interp_gate_tb: interp_core (RTL) and its synth_ice40 netlist
// (interp_core_gate, simulated with yosys' iCE40 cell models) side by side
// under Icarus, the same inputs into both, every output bit compared on
// every clock after the first reset: where the RTL bit is 0 or 1 the
// netlist's must be the same (an X or Z in the netlist is a difference);
// where the RTL bit is X (registers of interp_dp that a load sets and a
// reset leaves alone: o_pulse_y, o_xmag, ... before the first move) the
// netlist may hold anything (the clocks are counted), but only until a
// move is loaded: an X in the RTL after that fails (o_pulse_y and
// o_pulse_neg count only with o_pulse).
// tb/gate/gate_sim.sh builds and runs it.
//
// Plusargs:
//   +moves=FILE +n=N  the N blocks of FILE ($readmemh, one i_blk word a
//                 line; tb/gate/gate_moves.cpp writes it)
//   +mode=all     every block in order, pushed as soon as the queue takes
//                 it, the command high 7 clocks in 8: each move run once,
//                 back to back
//   +mode=random  +clocks=N +seed=S: random blocks of the file, pushed in
//                 bursts (also into a full queue), the command gated at
//                 random, random aborts and resets, and an abort whenever
//                 no move has ended for 150 clocks (the full-width lines)
// Prints "PASS interp_gate_tb ..." at the end, or "FAIL interp_gate_tb"
// with the first differing clock: each differing output with both
// sides' values, and the running move (block as pushed).
`timescale 1ns / 1ps
`default_nettype none

module interp_gate_tb;
  parameter integer W = 3;
  localparam integer QAW = 4;
  localparam integer BB = 9 + 4 * W;  // BLK_BITS, interp_block.vh
  localparam integer NMAX = 1 << 15;

  reg [BB-1:0] moves[0:NMAX-1];
  integer n_moves;

  reg clk = 1'b0, rst = 1'b1, abort = 1'b0, cmd = 1'b0, push = 1'b0;
  reg [BB-1:0] blk = {BB{1'b0}};

  // ------------------------------------------------ the two designs
`define OUTS(p) \
  wire p``full, p``pulse, p``pulse_y, p``pulse_neg, p``pulse_last, p``busy, p``xneg, p``yneg, p``arc; \
  wire [QAW+1:0] p``level; wire [W-1:0] p``xmag, p``ymag; wire [W+1:0] p``d; wire [1:0] p``q; wire [2:0] p``k;
`define CONN(p) \
  .i_clk(clk), .i_rst(rst), .i_abort(abort), .i_cmd(cmd), .i_push(push), .i_blk(blk), \
  .o_full(p``full), .o_level(p``level), .o_pulse(p``pulse), .o_pulse_y(p``pulse_y), \
  .o_pulse_neg(p``pulse_neg), .o_pulse_last(p``pulse_last), .o_busy(p``busy), \
  .o_xmag(p``xmag), .o_xneg(p``xneg), .o_ymag(p``ymag), .o_yneg(p``yneg), \
  .o_d(p``d), .o_q(p``q), .o_k(p``k), .o_arc(p``arc)

  `OUTS(r_)
  `OUTS(g_)
  interp_core #(.W(W), .QAW(QAW)) rtl (`CONN(r_));
  interp_core_gate gate (`CONN(g_));

  wire [4*W+QAW+20:0] r_all = {r_full, r_level, r_pulse, r_pulse_y, r_pulse_neg, r_pulse_last, r_busy,
                               r_xmag, r_xneg, r_ymag, r_yneg, r_d, r_q, r_k, r_arc};
  wire [4*W+QAW+20:0] g_all = {g_full, g_level, g_pulse, g_pulse_y, g_pulse_neg, g_pulse_last, g_busy,
                               g_xmag, g_xneg, g_ymag, g_yneg, g_d, g_q, g_k, g_arc};

  // For the X rule: o_pulse_y and o_pulse_neg qualified by o_pulse (X in
  // the RTL until the first pulse after a reset; they mean nothing without it).
  wire [4*W+QAW+20:0] r_qual = {r_full, r_level, r_pulse, r_pulse & r_pulse_y, r_pulse & r_pulse_neg,
                                r_pulse_last, r_busy, r_xmag, r_xneg, r_ymag, r_yneg, r_d, r_q, r_k, r_arc};

  // ------------------------------------- the running move, for reports
  // A shadow of the queue: blocks in push order, the head taken when the
  // RTL's datapath pops (rtl.pop); cleared by a reset or an abort.
  reg [BB-1:0] shadow[0:63];
  integer sh_idx[0:63];
  integer sh_wr = 0, sh_rd = 0, cur_idx = -1, push_idx = -1;
  reg [BB-1:0] cur_blk = {BB{1'b0}};
  always @(posedge clk) begin
    if (rst | abort) begin
      sh_wr <= 0;
      sh_rd <= 0;
      cur_idx <= -1;
    end else begin
      if (push & ~r_full) begin
        shadow[sh_wr % 64] <= blk;
        sh_idx[sh_wr % 64] <= push_idx;
        sh_wr <= sh_wr + 1;
      end
      if (rtl.pop) begin
        cur_blk <= shadow[sh_rd % 64];
        cur_idx <= sh_idx[sh_rd % 64];
        sh_rd <= sh_rd + 1;
      end
    end
  end

  task show_block(input [BB-1:0] b);
    $display("  running move: block #%0d of the file, %h: %s cw %0d sxn %0d syn %0d q %0d k %0d |xs| %0d |ys| %0d |xe| %0d |ye| %0d",
             cur_idx, b, b[0] ? "arc" : "line", b[1], b[2], b[3], b[5:4], b[8:6],
             b[9+:W], b[9+W+:W], b[9+2*W+:W], b[9+3*W+:W]);
  endtask

  // A difference: a bit the RTL defines (0 or 1) that the netlist does not
  // equal (another value, X or Z).
  function differs(input [63:0] r, input [63:0] g);
    integer b;
    begin
      differs = 1'b0;
      for (b = 0; b < 64; b = b + 1)
        if ((r[b] === 1'b0 || r[b] === 1'b1) && g[b] !== r[b]) differs = 1'b1;
    end
  endfunction

  task field(input [8*12-1:0] name, input [63:0] r, input [63:0] g);
    if (differs(r, g)) $display("  %0s: rtl %h gate %h", name, r, g);
  endtask

  localparam integer OB = 4 * W + QAW + 21;  // output bits
`include "differs.vh"

  // ------------------------------------------------------ the compare
  integer checked = 0, pulses = 0, moves_ended = 0, pushes = 0, refused = 0;
  integer aborts = 0, resets = 0, rtl_x = 0;
`include "clock.vh"
  always @(negedge clk) begin
    if (armed) begin
      checked = checked + 1;
      if (r_pulse === 1'b1) pulses = pulses + 1;
      if (r_pulse_last === 1'b1) moves_ended = moves_ended + 1;
      if (^r_all === 1'bx) rtl_x = rtl_x + 1;
      if ((r_all !== g_all && differs_all(r_all, g_all)) || (^r_qual === 1'bx && cur_idx != -1)) begin
        $display("FAIL interp_gate_tb W = %0d: clock %0d: the netlist differs from the RTL (or an X in the RTL with a move loaded)", W, clock);
        $display("  inputs: rst %b abort %b cmd %b push %b blk %h", rst, abort, cmd, push, blk);
        field("o_full", r_full, g_full);
        field("o_level", r_level, g_level);
        field("o_pulse", r_pulse, g_pulse);
        field("o_pulse_y", r_pulse_y, g_pulse_y);
        field("o_pulse_neg", r_pulse_neg, g_pulse_neg);
        field("o_pulse_last", r_pulse_last, g_pulse_last);
        field("o_busy", r_busy, g_busy);
        field("o_xmag", r_xmag, g_xmag);
        field("o_xneg", r_xneg, g_xneg);
        field("o_ymag", r_ymag, g_ymag);
        field("o_yneg", r_yneg, g_yneg);
        field("o_d", r_d, g_d);
        field("o_q", r_q, g_q);
        field("o_k", r_k, g_k);
        field("o_arc", r_arc, g_arc);
        $display("  all outputs: rtl  %b", r_all);
        $display("               gate %b", g_all);
        show_block(cur_blk);
        $finish;
      end
    end
  end

  // ---------------------------------------------------------- stimulus
  reg [8*8-1:0] mode;
  reg [8*512-1:0] path;
  integer clocks, seed, i, since_end, phase_push, phase_cmd, r;

  task step;  // one clock; inputs change 1 ns after the rising edge
    begin
      @(posedge clk);
      if (push & ~r_full & ~rst & ~abort) pushes = pushes + 1;
      if (push & r_full) refused = refused + 1;
      #1;
    end
  endtask

  initial begin
    if (!$value$plusargs("moves=%s", path)) begin
      $display("FAIL interp_gate_tb: no +moves=FILE");
      $finish;
    end
    if (!$value$plusargs("mode=%s", mode)) mode = "all";
    if (!$value$plusargs("clocks=%d", clocks)) clocks = 100000;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    if (!$value$plusargs("n=%d", n_moves) || n_moves < 1 || n_moves > NMAX) begin
      $display("FAIL interp_gate_tb: +n=N (1..%0d) missing", NMAX);
      $finish;
    end
    for (i = 0; i < NMAX; i = i + 1) moves[i] = {BB{1'bx}};
    $readmemh(path, moves, 0, n_moves - 1);
    for (i = 0; i < n_moves; i = i + 1)
      if (^moves[i] === 1'bx) begin
        $display("FAIL interp_gate_tb: block %0d of %0s unreadable", i, path);
        $finish;
      end
    r = $random(seed);
    rst = 1'b1;
    repeat (3) step;
    rst = 1'b0;
    if (mode == "all") begin
      // Every block once, pushed as soon as the queue takes it.
      i = 0;
      while (i < n_moves || r_level !== 0 || r_busy !== 1'b0) begin
        if (clock > 64 * n_moves + 1000) begin  // a move is at most 56 pulses at W = 3
          $display("FAIL interp_gate_tb W = %0d: clock %0d: the RTL never drains its queue (block %0d)", W, clock, i);
          $finish;
        end
        cmd = ($random(seed) & 7) != 0;
        push = i < n_moves && !r_full;
        blk = i < n_moves ? moves[i] : {BB{1'b0}};
        push_idx = i;
        step;
        if (push) i = i + 1;
        push = 1'b0;
      end
      repeat (8) step;
    end else begin
      since_end = 0;
      phase_push = 0;
      phase_cmd = 0;
      for (i = 0; i < clocks; i = i + 1) begin
        if (i % 256 == 0) begin
          phase_push = $unsigned($random(seed)) % 3;  // none, rare, bursts
          phase_cmd = $unsigned($random(seed)) % 3;   // always, 3 in 4, 1 in 8
        end
        push_idx = $unsigned($random(seed)) % n_moves;
        blk = moves[push_idx];
        case (phase_push)
          0: push = 1'b0;
          1: push = ($random(seed) & 31) == 0;
          default: push = ($random(seed) & 1) == 0;
        endcase
        case (phase_cmd)
          0: cmd = 1'b1;
          1: cmd = ($random(seed) & 3) != 0;
          default: cmd = ($random(seed) & 7) == 0;
        endcase
        since_end = (r_pulse_last === 1'b1 || !r_busy) ? 0 : since_end + 1;
        abort = ($unsigned($random(seed)) % 1500) == 0 || since_end > 150;
        rst = ($unsigned($random(seed)) % 4000) == 0;
        if (abort) aborts = aborts + 1;
        if (rst) resets = resets + 1;
        step;
      end
      push = 1'b0;
      abort = 1'b0;
      rst = 1'b0;
      repeat (8) step;
    end
    $display("PASS interp_gate_tb W = %0d mode %0s: %0d blocks in the file, %0d pushed (%0d refused while full), %0d moves ended, %0d pulses, %0d aborts, %0d resets, %0d clocks compared (%0d with an X in the RTL)",
             W, mode, n_moves, pushes, refused, moves_ended, pulses, aborts, resets, checked, rtl_x);
    $finish;
  end
endmodule
