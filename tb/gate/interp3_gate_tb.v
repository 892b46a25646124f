// interp3_gate_tb: interp3_core (RTL) and its synth_ice40 netlist
// (interp3_core_gate, with yosys' iCE40 cell models) side by side under
// Icarus, the same inputs into both, every output bit compared on every
// clock after the first reset (where the RTL bit is 0 or 1, the netlist's
// must equal it; no X reaches interp3_core's outputs after a reset (what
// is not reset is masked or read only after a load), so no RTL X is
// expected: an X in the RTL fails too). tb/gate/gate_sim.sh builds and runs it.
//
// Plusargs:
//   +mode=all     every move (|XE|, |YE|, |ZE| each 0..2^W - 1, the signs
//                 cycling through the 8 combinations) loaded once the
//                 previous one is done, the command high 7 clocks in 8
//                 (meant for W <= 4)
//   +mode=random  +clocks=N +seed=S: moves of small or full-width
//                 magnitudes, loaded when done or at random over a running
//                 move, the command gated at random, random resets
// Prints "PASS interp3_gate_tb ..." or "FAIL interp3_gate_tb" with the
// first differing clock, both sides' outputs and the running move.
`timescale 1ns / 1ps
`default_nettype none

module interp3_gate_tb;
  parameter integer W = 3;
  localparam integer OB = 7 + 6 * W + 6;  // output bits

  reg clk = 1'b0, rst = 1'b1, load = 1'b0, cmd = 1'b0;
  reg [W-1:0] xe = 0, ye = 0, ze = 0;
  reg xneg = 1'b0, yneg = 1'b0, zneg = 1'b0;

`define OUTS3(p) \
  wire p``sx, p``sy, p``sz, p``dx, p``dy, p``dz, p``done; \
  wire [W-1:0] p``x, p``y, p``z; wire [W+1:0] p``exy, p``exz, p``eyz;
`define CONN3(p) \
  .i_clk(clk), .i_rst(rst), .i_load(load), .i_xe(xe), .i_ye(ye), .i_ze(ze), \
  .i_xneg(xneg), .i_yneg(yneg), .i_zneg(zneg), .i_cmd(cmd), \
  .o_step_x(p``sx), .o_step_y(p``sy), .o_step_z(p``sz), .o_dir_x(p``dx), .o_dir_y(p``dy), \
  .o_dir_z(p``dz), .o_done(p``done), .o_x(p``x), .o_y(p``y), .o_z(p``z), \
  .o_exy(p``exy), .o_exz(p``exz), .o_eyz(p``eyz)

  `OUTS3(r_)
  `OUTS3(g_)
  interp3_core #(.W(W)) rtl (`CONN3(r_));
  interp3_core_gate gate (`CONN3(g_));

  wire [OB-1:0] r_all = {r_sx, r_sy, r_sz, r_dx, r_dy, r_dz, r_done, r_x, r_y, r_z, r_exy, r_exz, r_eyz};
  wire [OB-1:0] g_all = {g_sx, g_sy, g_sz, g_dx, g_dy, g_dz, g_done, g_x, g_y, g_z, g_exy, g_exz, g_eyz};

`include "differs.vh"

  // The running move: the last one loaded.
  reg [W-1:0] m_xe = 0, m_ye = 0, m_ze = 0;
  reg [2:0] m_neg = 0;
  always @(posedge clk)
    if (load & ~rst) begin
      m_xe <= xe;
      m_ye <= ye;
      m_ze <= ze;
      m_neg <= {xneg, yneg, zneg};
    end

  integer checked = 0, steps = 0, loads = 0, moves_done = 0, resets = 0, rtl_x = 0;
`include "clock.vh"
  always @(negedge clk) begin
    if (armed) begin
      checked = checked + 1;
      if (r_sx === 1'b1 || r_sy === 1'b1 || r_sz === 1'b1) steps = steps + 1;
      if (^r_all === 1'bx) rtl_x = rtl_x + 1;
      if ((r_all !== g_all && differs_all(r_all, g_all)) || ^r_all === 1'bx) begin
        $display("FAIL interp3_gate_tb W = %0d: clock %0d: the netlist differs from the RTL (or an X in the RTL)", W, clock);
        $display("  inputs: rst %b load %b cmd %b xe %0d ye %0d ze %0d neg %b%b%b", rst, load, cmd, xe, ye, ze,
                 xneg, yneg, zneg);
        $display("  outputs   step xyz dir xyz done  x y z  exy exz eyz");
        $display("  rtl       %b%b%b %b%b%b %b  %h %h %h  %h %h %h", r_sx, r_sy, r_sz, r_dx, r_dy, r_dz, r_done,
                 r_x, r_y, r_z, r_exy, r_exz, r_eyz);
        $display("  gate      %b%b%b %b%b%b %b  %h %h %h  %h %h %h", g_sx, g_sy, g_sz, g_dx, g_dy, g_dz, g_done,
                 g_x, g_y, g_z, g_exy, g_exz, g_eyz);
        $display("  running move: |XE| %0d |YE| %0d |ZE| %0d, negative xyz %b", m_xe, m_ye, m_ze, m_neg);
        $finish;
      end
    end
  end

  reg [8*8-1:0] mode;
  integer clocks, seed, i, n, r, phase_cmd;

  task step;
    begin
      @(posedge clk);
      if (load & ~rst) loads = loads + 1;
      #1;
    end
  endtask

  function [W-1:0] magnitude(input integer kind);
    begin
      if (kind == 0) magnitude = $unsigned($random(seed)) % 24;
      else magnitude = $random(seed);  // full width
    end
  endfunction

  initial begin
    if (!$value$plusargs("mode=%s", mode)) mode = "all";
    if (!$value$plusargs("clocks=%d", clocks)) clocks = 20000;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    r = $random(seed);
    rst = 1'b1;
    repeat (3) step;
    rst = 1'b0;
    if (mode == "all") begin
      n = 1 << (3 * W);
      for (i = 0; i < n; i = i + 1) begin
        {ze, ye, xe} = i;
        {xneg, yneg, zneg} = i % 8;
        load = 1'b1;
        cmd = 1'b1;
        step;
        load = 1'b0;
        moves_done = moves_done + 1;
        r = 0;
        while (r_done !== 1'b1) begin
          cmd = ($random(seed) & 7) != 0;
          step;
          r = r + 1;
          if (r > 8 << W) begin  // 3 (2^W - 1) steps, the command 7 in 8
            $display("FAIL interp3_gate_tb W = %0d: clock %0d: the RTL never ends the move |XE| %0d |YE| %0d |ZE| %0d",
                     W, clock, xe, ye, ze);
            $finish;
          end
        end
      end
      repeat (4) step;
    end else begin
      phase_cmd = 0;
      for (i = 0; i < clocks; i = i + 1) begin
        if (i % 256 == 0) phase_cmd = $unsigned($random(seed)) % 3;
        case (phase_cmd)
          0: cmd = 1'b1;
          1: cmd = ($random(seed) & 3) != 0;
          default: cmd = ($random(seed) & 7) == 0;
        endcase
        // A new move when the last one is done (sometimes a few clocks
        // later), or over a running one (1 in 64 clocks).
        load = (r_done === 1'b1 && ($random(seed) & 3) == 0) || ($random(seed) & 63) == 0;
        r = $unsigned($random(seed)) % 4;  // 0..2: small, 3: full width
        xe = magnitude(r == 3);
        ye = magnitude(r == 3 && ($random(seed) & 1));
        ze = magnitude(r == 3 && ($random(seed) & 1));
        {xneg, yneg, zneg} = $random(seed);
        rst = ($unsigned($random(seed)) % 3000) == 0;
        if (rst) resets = resets + 1;
        step;
      end
      load = 1'b0;
      rst = 1'b0;
      repeat (4) step;
    end
    $display("PASS interp3_gate_tb W = %0d mode %0s: %0d moves loaded, %0d steps, %0d resets, %0d clocks compared (%0d with an X in the RTL)",
             W, mode, loads, steps, resets, checked, rtl_x);
    $finish;
  end
endmodule
