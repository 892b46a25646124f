# make lint (rtl/Makefile): the CPU, its synthesis wrapper (both variants)
# and the board.
CPU85_LINT_V := cpu8085/cpu8085.v cpu8085/cpu8085_alu.v cpu8085/cpu8085_decode.v
BOARD85_LINT_V := $(addprefix board8085/,board8085.v board8085_rom.v board8085_ram.v \
	board8085_mailbox.v board8085_io.v)

LINT_TOPS += cpu8085 cpu8085_wrap board8085 board8085_wrap
cpu8085_TOP := cpu8085
cpu8085_SRCS := $(CPU85_LINT_V)
cpu8085_wrap_TOP := cpu8085_wrap
cpu8085_wrap_SRCS := cpu8085/synth/cpu8085_wrap.v $(CPU85_LINT_V)
board8085_TOP := board8085
board8085_SRCS := $(BOARD85_LINT_V) $(CPU85_LINT_V)
board8085_wrap_TOP := cpu8085_wrap
board8085_wrap_SRCS := cpu8085/synth/cpu8085_wrap.v $(BOARD85_LINT_V) $(CPU85_LINT_V)
board8085_wrap_ARGS := -DDESIGN_BOARD
