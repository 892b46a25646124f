# The iCEBreaker bitstream of the board with the host link (link_top,
# rtl/board/board.f), built by `make synth` and reported in its table as
# icebreaker_link (UP5K, at the board's 12 MHz with the pins of link.pcf;
# included from designs.mk). Also: make -C rtl/synth BUILD=... link-bitstream
# (included before the Makefile's first target: keep its default goal)
.DEFAULT_GOAL := all
LINK_DIR := $(BUILD)/icebreaker_link
LINK_V := icebreaker/link_top.v $(shell $(RTL)/filelist $(RTL)/board/board.f)
LINK_INC := $(addprefix -I,$(shell $(RTL)/filelist --incdirs $(RTL)/board/board.f))
# The included tables (.vh) are inputs too: an edited table re-synthesises.
LINK_VH := $(foreach d,$(shell $(RTL)/filelist --incdirs $(RTL)/board/board.f),$(wildcard $(d)/*.vh))
# nextpnr's placement seed (`make synth` reports seed 1)
SEED ?= 1

.PHONY: link-bitstream
link-bitstream: $(LINK_DIR)/link.bin
	@echo "icebreaker link bitstream: $<"

$(LINK_DIR)/netlist.json: $(LINK_V) $(LINK_VH)
	@mkdir -p $(@D)
	@echo "synth: yosys icebreaker_link"
	@$(YOSYS) -q -l $(@D)/yosys.log -p "read_verilog $(LINK_INC) $(LINK_V); synth_ice40 -abc9 -top link_top -json $@"

$(LINK_DIR)/report.json: $(LINK_DIR)/netlist.json icebreaker/link.pcf
	@echo "synth: nextpnr-ice40 --up5k icebreaker_link"
	@$(NEXTPNR) -q --up5k --package sg48 --freq 12 --seed $(SEED) --json $< --pcf icebreaker/link.pcf \
		--report $@ --asc $(@D)/link.asc -l $(@D)/nextpnr.log

$(LINK_DIR)/link.bin: $(LINK_DIR)/report.json
	@icepack $(@D)/link.asc $@

$(BUILD)/parts/icebreaker_link.json: $(LINK_DIR)/link.bin summary.cmake
	@mkdir -p $(@D)
	@cmake -DREPORT=$(LINK_DIR)/report.json -DPART=$@ -P summary.cmake

$(BUILD)/summary.json: $(BUILD)/parts/icebreaker_link.json
