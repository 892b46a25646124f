// board_top: the board design with the host link (docs/board.md).
//
//   RX -> uart_rx -> link_rx -> link_ctrl ==Wishbone==> interp_top  (window INTERP)
//   TX <- uart_tx <- link_tx <- reply queue <-'          interp3_top (window AXIS3)
//                                                        board_ctl   (window LINK)
//
// STEP/DIR of X and Y come from interp3_top (chords, paper B) or from
// interp_top (lines and arcs, paper A), as LINK CTRL.PINS selects; Z from
// interp3_top. board_ctl's time scale drives interp3_top's clock enable.
// Synchronous, active-high reset.
`default_nettype none

module board_top #(
    parameter integer CLKS_PER_BIT = 12,  // clock / baud rate (12: 1 Mbaud at 12 MHz)
    parameter integer W = 16,             // coordinate width of interp_top (16 fits the UP5K)
    parameter integer W3 = 12,            // chord magnitude width of interp3_top (4095 steps: more than a cycle gives)
    parameter integer QAW = 7             // log2 of the chord queue depth (128 + 1 chords: 129 ms at 1 ms)
) (
    input  wire       i_clk,
    input  wire       i_rst,
    input  wire       i_rx,       // UART from the host
    output wire       o_tx,       // UART to the host
    output wire [2:0] o_step,     // STEP Z, Y, X
    output wire [2:0] o_dir,      // DIR Z, Y, X (1: minus)
    output wire       o_enable,   // driver enable
    output wire       o_hold,     // a hold is asked for (LED)
    output wire       o_wdog      // the watchdog has tripped (LED)
);

  // ------------------------------------------------------------- the link
  wire [7:0] rx_byte;
  wire rx_valid, rx_ferr;
  uart_rx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_rx (
      .i_clk(i_clk), .i_rst(i_rst), .i_rx(i_rx), .o_data(rx_byte), .o_valid(rx_valid), .o_ferr(rx_ferr)
  );

  wire fr_done, fr_bank, fr_crc_ok, fr_bad, ctl_busy;
  wire [7:0] fr_len, rd_addr, rd_data;
  link_rx #(.MAX(64)) u_lrx (
      .i_clk(i_clk), .i_rst(i_rst), .i_byte(rx_byte), .i_valid(rx_valid), .i_ferr(rx_ferr),
      .i_busy(ctl_busy), .o_done(fr_done), .o_bank(fr_bank), .o_len(fr_len), .o_crc_ok(fr_crc_ok),
      .o_bad(fr_bad), .i_rd_addr(rd_addr), .o_rd_data(rd_data)
  );

  wire m_cyc, m_we, m_ack;
  wire [6:0] m_adr;
  wire [31:0] m_dat_w, m_dat_r;
  wire [8:0] txq_in, txq_out;
  wire txq_push, txq_full, txq_valid, txq_pop;
  wire hold, stopped, frame_ok, refused, pins;
  link_ctrl #(.MAX(64)) u_ctl (
      .i_clk(i_clk), .i_rst(i_rst), .i_done(fr_done), .i_bank(fr_bank), .i_len(fr_len),
      .i_crc_ok(fr_crc_ok), .i_bad(fr_bad), .o_busy(ctl_busy), .o_rd_addr(rd_addr), .i_rd_data(rd_data),
      .o_wb_cyc(m_cyc), .o_wb_we(m_we), .o_wb_adr(m_adr), .o_wb_dat(m_dat_w), .i_wb_dat(m_dat_r),
      .i_wb_ack(m_ack), .o_tx_data(txq_in), .o_tx_push(txq_push), .i_tx_full(txq_full),
      .i_hold(hold), .i_stopped(stopped), .i_wdog(o_wdog), .i_pins(pins), .o_frame_ok(frame_ok), .o_refused(refused)
  );

  wire [9:0] unused_txq_level;
  wire [8:0] txq_used;  // bytes in the memory (head excluded)
  // link_ctrl pushes only when not full; its push is registered, so one
  // more byte can come after the flag is seen: full at 255 of the 256.
  assign txq_full = txq_used[8] | (&txq_used[7:0]);
  move_fifo #(.WIDTH(9), .AW(8)) u_txq (
      .i_clk(i_clk), .i_rst(i_rst), .i_flush(1'b0), .i_push(txq_push), .i_data(txq_in),
      .i_pop(txq_pop), .o_valid(txq_valid), .o_data(txq_out), .o_level(unused_txq_level),
      .o_used(txq_used)
  );

  wire [7:0] tx_char;
  wire tx_valid, tx_ready;
  link_tx u_ltx (
      .i_clk(i_clk), .i_rst(i_rst), .i_data(txq_out), .i_valid(txq_valid), .o_pop(txq_pop),
      .o_char(tx_char), .o_char_valid(tx_valid), .i_char_ready(tx_ready)
  );
  uart_tx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_tx (
      .i_clk(i_clk), .i_rst(i_rst), .i_data(tx_char), .i_valid(tx_valid), .o_ready(tx_ready), .o_tx(o_tx)
  );

  // -------------------------------------------------------------- the bus
  // Word address [6:5]: 0 INTERP, 1 AXIS3, 2 LINK (board.def); [4:0] the
  // word in the window, a byte address to the slave.
  wire [7:0] s_adr = {1'b0, m_adr[4:0], 2'b00};
  wire sel_i = m_adr[6:5] == 2'd0;
  wire sel_3 = m_adr[6:5] == 2'd1;
  wire sel_l = m_adr[6:5] == 2'd2;
  wire [31:0] dat_i, dat_3, dat_l;
  wire ack_i, ack_3, ack_l;
  assign m_dat_r = sel_i ? dat_i : sel_3 ? dat_3 : dat_l;
  assign m_ack = ack_i | ack_3 | ack_l;

  wire ce, enable;
  board_ctl u_bctl (
      .i_clk(i_clk), .i_rst(i_rst), .i_wb_cyc(m_cyc & sel_l), .i_wb_stb(m_cyc & sel_l), .i_wb_we(m_we),
      .i_wb_adr(s_adr), .i_wb_dat(m_dat_w), .o_wb_dat(dat_l), .o_wb_ack(ack_l),
      .i_frame_ok(frame_ok), .i_refused(refused), .o_ce(ce), .o_hold(hold), .o_stopped(stopped),
      .o_wdog(o_wdog), .o_enable(enable), .o_pins(pins)
  );

  wire i_step_x, i_dir_x, i_step_y, i_dir_y;
  wire unused_pulse, unused_pulse_y, unused_pulse_neg, unused_busy;
  interp_top #(.W(W), .QAW(4)) u_interp (
      .i_clk(i_clk), .i_rst(i_rst), .i_wb_cyc(m_cyc & sel_i), .i_wb_stb(m_cyc & sel_i), .i_wb_we(m_we),
      .i_wb_adr(s_adr), .i_wb_dat(m_dat_w), .o_wb_dat(dat_i), .o_wb_ack(ack_i), .i_cmd_pin(1'b0), .i_cmd_ce(ce),
      .o_step_x(i_step_x), .o_dir_x(i_dir_x), .o_step_y(i_step_y), .o_dir_y(i_dir_y),
      .o_pulse(unused_pulse), .o_pulse_y(unused_pulse_y), .o_pulse_neg(unused_pulse_neg), .o_busy(unused_busy)
  );

  wire a_step_x, a_dir_x, a_step_y, a_dir_y, a_step_z, a_dir_z, unused_a_busy;
  interp3_top #(.W(W3), .QAW(QAW)) u_axis3 (
      .i_clk(i_clk), .i_rst(i_rst), .i_ce(ce), .i_wb_cyc(m_cyc & sel_3), .i_wb_stb(m_cyc & sel_3),
      .i_wb_we(m_we), .i_wb_adr(s_adr), .i_wb_dat(m_dat_w), .o_wb_dat(dat_3), .o_wb_ack(ack_3),
      .o_step_x(a_step_x), .o_dir_x(a_dir_x), .o_step_y(a_step_y), .o_dir_y(a_dir_y),
      .o_step_z(a_step_z), .o_dir_z(a_dir_z), .o_busy(unused_a_busy)
  );

  // ------------------------------------------------------------- the pins
  assign o_step = {a_step_z, pins ? i_step_y : a_step_y, pins ? i_step_x : a_step_x};
  assign o_dir = {a_dir_z, pins ? i_dir_y : a_dir_y, pins ? i_dir_x : a_dir_x};
  assign o_enable = enable;
  assign o_hold = hold;

endmodule
