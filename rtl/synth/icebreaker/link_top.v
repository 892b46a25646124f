// link_top: the board design with the host link on an iCEBreaker
// (iCE40UP5K-SG48, 12 MHz): board_top with its UART on the FTDI's second
// channel (RX pin 6, TX pin 9: /dev/ttyUSB1 on the host, 1 Mbaud 8N1),
// STEP/DIR of X, Y, Z and ENABLE on PMOD 1A (docs/board.md, "Pinout"),
// the red LED lit while a hold is asked for (watchdog or host), the green
// LED while the drivers are enabled. BTN_N resets.
`default_nettype none

module link_top (
    input  wire CLK,     // 12 MHz
    input  wire BTN_N,   // reset, active low
    input  wire RX,      // from the host (FTDI TXD)
    output wire TX,      // to the host (FTDI RXD)
    output wire LEDR_N,
    output wire LEDG_N,
    output wire P1A1,    // STEP X
    output wire P1A2,    // DIR X
    output wire P1A3,    // STEP Y
    output wire P1A4,    // DIR Y
    output wire P1A7,    // STEP Z
    output wire P1A8,    // DIR Z
    output wire P1A9     // ENABLE
);

  // Power-on and button reset, synchronous.
  reg [3:0] por_q = 4'd0;
  reg [1:0] btn_q = 2'b00;
  always @(posedge CLK) begin
    btn_q <= {btn_q[0], BTN_N};
    if (!btn_q[1]) por_q <= 4'd0;
    else if (por_q != 4'hF) por_q <= por_q + 1'b1;
  end
  wire rst = (por_q != 4'hF);

  wire [2:0] step, dir;
  wire enable, hold, unused_wdog;
  board_top #(.CLKS_PER_BIT(12)) u_board (
      .i_clk(CLK), .i_rst(rst), .i_rx(RX), .o_tx(TX), .o_step(step), .o_dir(dir),
      .o_enable(enable), .o_hold(hold), .o_wdog(unused_wdog)
  );

  assign {P1A7, P1A3, P1A1} = step;
  assign {P1A8, P1A4, P1A2} = dir;
  assign P1A9 = enable;
  assign LEDR_N = ~hold;
  assign LEDG_N = ~enable;

endmodule
