# iCEBreaker bitstream: make -C rtl/synth BUILD=... icebreaker
# (icestorm pattern: .json -> .asc -> .bin)
ICEB_DIR := $(BUILD)/icebreaker
ICEB_V := icebreaker/icebreaker_top.v $(shell $(RTL)/filelist $(RTL)/interp/interp.f)
ICEB_INC := $(addprefix -I,$(shell $(RTL)/filelist --incdirs $(RTL)/interp/interp.f))

icebreaker: $(ICEB_DIR)/icebreaker.bin
	@echo "icebreaker: $<"

$(ICEB_DIR)/icebreaker.json: $(ICEB_V)
	@mkdir -p $(@D)
	@$(YOSYS) -q -l $(@D)/yosys.log -p "read_verilog $(ICEB_INC) $(ICEB_V); synth_ice40 -top icebreaker_top -json $@"

$(ICEB_DIR)/icebreaker.asc: $(ICEB_DIR)/icebreaker.json icebreaker/icebreaker.pcf
	@$(NEXTPNR) -q --up5k --package sg48 --freq 12 --json $< --pcf icebreaker/icebreaker.pcf --asc $@ -l $(@D)/nextpnr.log

$(ICEB_DIR)/icebreaker.bin: $(ICEB_DIR)/icebreaker.asc
	@icepack $< $@
