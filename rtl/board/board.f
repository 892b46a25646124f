// rtl/board: the board design with the host link (docs/board.md): UART,
// SLIP frames with CRC-16, the frame engine as a Wishbone master, the
// 3-axis chord peripheral, the link's own registers; interp_top and
// interp3_core from their cores' lists.
+incdir+board
-f interp/interp.f
-f interp3/interp3.f
board/board_top.v
board/board_ctl.v
board/uart_rx.v
board/uart_tx.v
board/crc16_byte.v
board/link_rx.v
board/link_ctrl.v
board/link_tx.v
board/interp3_top.v
