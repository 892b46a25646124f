# The 3-axis interpolator core (rtl/interp3) for `make synth`, in its own
# timing wrapper (registered I/O, clock on SB_GB). Included by
# rtl/synth/Makefile; $(RTL) is rtl/. Figures: docs/rtl-3axis.md.
INTERP3_DIR := $(RTL)/interp3
DESIGNS += interp3_hx8k
interp3_hx8k_SRCS := $(INTERP3_DIR)/synth/interp3_wrap.v $(INTERP3_DIR)/interp3_core.v
interp3_hx8k_DEFS :=
interp3_hx8k_TOP := interp3_wrap
interp3_hx8k_DEV := hx8k
