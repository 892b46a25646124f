# The 8085 CPU (rtl/cpu8085) and the board (rtl/board8085) for `make synth`,
# in their own timing wrapper rtl/cpu8085/synth/cpu8085_wrap.v. Included by
# rtl/synth/Makefile (see docs/cpu8085.md, "Synthesis"); $(RTL) is rtl/.
#   cpu8085_*:  the CPU alone (bus, interrupt pins, retire strobe)
#   board8085_*: the board, ROM = the board test program's image
#               (rtl/board8085/synth/board_test.memh, path relative to rtl/synth)
CPU85_DIR := $(RTL)/cpu8085
BOARD85_DIR := $(RTL)/board8085
CPU85_V := $(CPU85_DIR)/cpu8085.v $(CPU85_DIR)/cpu8085_alu.v $(CPU85_DIR)/cpu8085_decode.v
BOARD85_V := $(addprefix $(BOARD85_DIR)/,board8085.v board8085_rom.v board8085_ram.v \
	board8085_mailbox.v board8085_io.v) $(CPU85_V)

DESIGNS += cpu8085_hx8k cpu8085_up5k board8085_hx8k board8085_up5k
cpu8085_hx8k_SRCS := $(CPU85_DIR)/synth/cpu8085_wrap.v $(CPU85_V)
cpu8085_hx8k_DEFS :=
cpu8085_hx8k_TOP := cpu8085_wrap
cpu8085_hx8k_DEV := hx8k
cpu8085_up5k_SRCS := $(cpu8085_hx8k_SRCS)
cpu8085_up5k_DEFS :=
cpu8085_up5k_TOP := cpu8085_wrap
cpu8085_up5k_DEV := up5k
board8085_hx8k_SRCS := $(CPU85_DIR)/synth/cpu8085_wrap.v $(BOARD85_V)
board8085_hx8k_DEFS := -DDESIGN_BOARD
board8085_hx8k_TOP := cpu8085_wrap
board8085_hx8k_DEV := hx8k
board8085_up5k_SRCS := $(board8085_hx8k_SRCS)
board8085_up5k_DEFS := $(board8085_hx8k_DEFS)
board8085_up5k_TOP := cpu8085_wrap
board8085_up5k_DEV := up5k
