// interp3_wrap: registered I/O around interp3_core for `make synth`, so that
// nextpnr's Fmax is register to register (as rtl/synth/timing_wrap.v does
// for the 2-axis core): every input comes from a serial-in shift register,
// every output goes into a parallel-load shift register read out on one
// pin. The state outputs (x, y, z, discriminants) are read out too, so
// nothing of the core is trimmed.
`default_nettype none

module interp3_wrap (
    input  wire i_clk_pin,
    input  wire i_ser,    // serial input
    input  wire i_load,   // load the output shift register
    output wire o_ser     // serial output
);

  localparam integer W = 24;
  localparam integer NI = 3 * W + 6;          // ends, signs, load, cmd, reset
  localparam integer NO = 7 + 3 * W + 3 * (W + 2);

  // The clock on a global buffer, explicitly (see rtl/synth/timing_wrap.v).
  wire i_clk;
`ifdef SYNTHESIS
  SB_GB u_clk_gb (.USER_SIGNAL_TO_GLOBAL_BUFFER(i_clk_pin), .GLOBAL_BUFFER_OUTPUT(i_clk));
`else
  assign i_clk = i_clk_pin;
`endif

  reg [NI-1:0] in_q;
  reg [NO-1:0] out_q;
  wire [NO-1:0] outs;

  always @(posedge i_clk) in_q <= {in_q[NI-2:0], i_ser};

  always @(posedge i_clk) begin
    if (i_load) out_q <= outs;
    else out_q <= {1'b0, out_q[NO-1:1]};
  end
  assign o_ser = out_q[0];

  interp3_core #(.W(W)) u_dut (
      .i_clk(i_clk), .i_rst(in_q[NI-1]),
      .i_load(in_q[0]), .i_cmd(in_q[1]),
      .i_xneg(in_q[2]), .i_yneg(in_q[3]), .i_zneg(in_q[4]),
      .i_xe(in_q[5 +: W]), .i_ye(in_q[5 + W +: W]), .i_ze(in_q[5 + 2 * W +: W]),
      .o_step_x(outs[0]), .o_step_y(outs[1]), .o_step_z(outs[2]),
      .o_dir_x(outs[3]), .o_dir_y(outs[4]), .o_dir_z(outs[5]), .o_done(outs[6]),
      .o_x(outs[7 +: W]), .o_y(outs[7 + W +: W]), .o_z(outs[7 + 2 * W +: W]),
      .o_exy(outs[7 + 3 * W +: W + 2]), .o_exz(outs[9 + 4 * W +: W + 2]),
      .o_eyz(outs[11 + 5 * W +: W + 2])
  );

endmodule
