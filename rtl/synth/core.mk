# The interpolator core (rtl/interp) in the timing wrapper, on HX8K and UP5K.
#   core_*: interp_core (datapath, block prep, queue) + step_out (the
#           output stage): the issue's "core with its output stage and queue"
#   top_*:  interp_top, the whole Wishbone peripheral (core, output stage,
#           feed generator, position counters, registers)
#   dp_*:   the datapath interp_dp alone
INTERP_DIR := $(RTL)/interp
INTERP_V := $(addprefix $(INTERP_DIR)/,interp_top.v wb_regs.v cmd_gen.v step_out.v step_chan.v \
	pos_counter.v interp_core.v interp_dp.v blk_prep.v move_fifo.v)

DESIGNS += core_hx8k core_up5k top_hx8k top_up5k dp_hx8k dp_up5k
top_hx8k_SRCS := timing_wrap.v $(INTERP_V)
top_hx8k_DEFS := -DDESIGN_TOP
top_hx8k_INC := $(INTERP_DIR)
top_hx8k_DEV := hx8k
top_up5k_SRCS := $(top_hx8k_SRCS)
top_up5k_DEFS := -DDESIGN_TOP
top_up5k_INC := $(INTERP_DIR)
top_up5k_DEV := up5k
core_hx8k_SRCS := timing_wrap.v $(INTERP_V)
core_hx8k_DEFS := -DDESIGN_CORE
core_hx8k_INC := $(INTERP_DIR)
core_hx8k_DEV := hx8k
core_up5k_SRCS := $(core_hx8k_SRCS)
core_up5k_DEFS := -DDESIGN_CORE
core_up5k_INC := $(INTERP_DIR)
core_up5k_DEV := up5k
dp_hx8k_SRCS := timing_wrap.v $(INTERP_DIR)/interp_dp.v
dp_hx8k_DEFS := -DDESIGN_DP
dp_hx8k_INC := $(INTERP_DIR)
dp_hx8k_DEV := hx8k
dp_up5k_SRCS := $(dp_hx8k_SRCS)
dp_up5k_DEFS := -DDESIGN_DP
dp_up5k_INC := $(INTERP_DIR)
dp_up5k_DEV := up5k
# timing_wrap puts the clock on SB_GB itself; without promotion nextpnr
# keeps high-fanout enables off the global nets (faster here).
$(foreach d,core_hx8k core_up5k top_hx8k top_up5k dp_hx8k dp_up5k,$(eval $(d)_PNR := --no-promote-globals))
