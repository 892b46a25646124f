// rtl/board8085: the board that runs the 8085 program (CPU included).
board8085/board8085.v
board8085/board8085_rom.v
board8085/board8085_ram.v
board8085/board8085_mailbox.v
board8085/board8085_io.v
-f cpu8085/cpu8085.f
