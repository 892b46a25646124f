# The designs of `make synth`, one line each, every one in the one timing
# wrapper (timing_wrap.v, which names them):
#
#   $(eval $(call design,<name>,<file list>,<DESIGN_ define>,<hx8k|up5k>,<nextpnr flags>))
#
#   core_*:      interp_core (datapath, block prep, queue) + step_out
#   top_*:       interp_top, the whole Wishbone peripheral
#   dp_*:        the datapath interp_dp alone
#   interp3_*:   the 3-axis core (figures: docs/rtl-3axis.md)
#   cpu8085_*:   the 8085 CPU alone (figures: docs/cpu8085.md)
#   board8085_*: the board, ROM = the board test program's image
#
# The interp designs (interp3 too) run nextpnr with --no-promote-globals: timing_wrap puts
# the clock on SB_GB itself, and without promotion nextpnr keeps high-fanout
# enables off the few global nets (faster here).
define design
DESIGNS += $(1)
$(1)_SRCS := timing_wrap.v $(shell $(RTL)/filelist $(RTL)/$(2))
$(1)_INC := $(shell $(RTL)/filelist --incdirs $(RTL)/$(2))
$(1)_DEFS := -DDESIGN_$(3)
$(1)_DEV := $(4)
$(1)_PNR := $(5)
endef

$(foreach dev,hx8k up5k,$(foreach d,CORE TOP DP,\
  $(eval $(call design,$(shell echo $(d) | tr A-Z a-z)_$(dev),interp/interp.f,$(d),$(dev),--no-promote-globals))))
$(eval $(call design,interp3_hx8k,interp3/interp3.f,INTERP3,hx8k,--no-promote-globals))
$(foreach dev,hx8k up5k,$(eval $(call design,cpu8085_$(dev),cpu8085/cpu8085.f,CPU8085,$(dev),)))
$(foreach dev,hx8k up5k,$(eval $(call design,board8085_$(dev),board8085/board8085.f,BOARD8085,$(dev),)))

# Analysis designs: not in `make synth`, built by
#   make -C rtl/synth BUILD=$PWD/build/synth-analysis analysis     (all)
#   make -C rtl/synth BUILD=$PWD/build/synth-analysis $PWD/build/synth-analysis/parts/<name>.json
# to tell which part of `core` holds its Fmax (docs/rtl.md, "What limits it"),
# and the timing prototypes of rtl/proto (docs/rtl-proto.md):
#   core_free_hx8k: core with its command tied high (the datapath free-running,
#                   the command no longer a late input of the step decision);
#   core_nodp_hx8k: core with interp_dp replaced by dp_stub.v (timing only:
#                   yosys reads both, drops interp_dp and renames dp_stub).
# $(5): yosys commands between reading the sources and synth_ice40.
define analysis_design
ANALYSIS += $(1)
$(1)_SRCS := timing_wrap.v $(3)
$(1)_INC := $(shell $(RTL)/filelist --incdirs $(RTL)/$(2))
$(1)_DEFS := $(4)
$(1)_YS := $(5)
$(1)_DEV := hx8k
$(1)_PNR := --no-promote-globals
endef
INTERP_SRCS := $(shell $(RTL)/filelist $(RTL)/interp/interp.f)
$(eval $(call analysis_design,core_free_hx8k,interp/interp.f,$(INTERP_SRCS),-DDESIGN_CORE -DCMD_HIGH))
$(eval $(call analysis_design,core_nodp_hx8k,interp/interp.f,$(INTERP_SRCS) dp_stub.v,-DDESIGN_CORE,delete interp_dp; rename dp_stub interp_dp;))
#   dloop_*:     the step loop prototype rtl/proto/dloop (docs/rtl-proto.md);
#                dloop_nod_* without its D output (the loop's own cost);
#                dloop1_*, dloop1_nod_*: the same one step ahead (dloop1.v);
#                dloop1l_*, dloop1l_nod_*: dloop1 with a one-clock load (dloop1l.v);
#                dloop1x_*, dloop1x_nod_*: dloop1l with crossings (dloop1x.v)
DLOOP_SRCS := $(shell $(RTL)/filelist $(RTL)/proto/dloop/dloop.f)
$(foreach d,DLOOP DLOOP_NOD DLOOP1 DLOOP1_NOD DLOOP1L DLOOP1L_NOD DLOOP1X DLOOP1X_NOD,\
  $(eval $(call analysis_design,$(shell echo $(d) | tr A-Z a-z)_hx8k,proto/dloop/dloop.f,$(DLOOP_SRCS),-DDESIGN_$(d))))

# The board with the host link: its iCEBreaker bitstream (icebreaker/link.mk).
include icebreaker/link.mk
