# Lint runs of rtl/interp (see rtl/Makefile): the core and the peripheral
# at W = 8 and W = 24, the datapath at the smallest width used, W = 3.
INTERP_CORE_SRCS := interp/interp_core.v interp/interp_dp.v interp/blk_prep.v interp/move_fifo.v
INTERP_TOP_SRCS := interp/interp_top.v interp/wb_regs.v interp/cmd_gen.v interp/step_out.v \
	interp/step_chan.v interp/pos_counter.v $(INTERP_CORE_SRCS)

LINT_TOPS += interp_core_w8 interp_core_w24 interp_top_w8 interp_top_w24 interp_dp_w3
interp_core_w8_TOP := interp_core
interp_core_w8_SRCS := $(INTERP_CORE_SRCS)
interp_core_w8_ARGS := -GW=8
interp_core_w24_TOP := interp_core
interp_core_w24_SRCS := $(INTERP_CORE_SRCS)
interp_core_w24_ARGS := -GW=24
interp_top_w8_TOP := interp_top
interp_top_w8_SRCS := $(INTERP_TOP_SRCS)
interp_top_w8_ARGS := -GW=8 -Iinterp
interp_top_w24_TOP := interp_top
interp_top_w24_SRCS := $(INTERP_TOP_SRCS)
interp_top_w24_ARGS := -GW=24 -Iinterp
interp_dp_w3_TOP := interp_dp
interp_dp_w3_SRCS := interp/interp_dp.v
interp_dp_w3_ARGS := -GW=3
