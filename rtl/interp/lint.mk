# Lint runs of rtl/interp (see rtl/Makefile): the core and the peripheral
# at W = 8 and W = 24, the datapath at the smallest width used, W = 3.
$(eval $(call lint_run,interp_core_w8,interp_core,interp/interp.f,-GW=8))
$(eval $(call lint_run,interp_core_w24,interp_core,interp/interp.f,-GW=24))
$(eval $(call lint_run,interp_top_w8,interp_top,interp/interp.f,-GW=8))
$(eval $(call lint_run,interp_top_w24,interp_top,interp/interp.f,-GW=24))
$(eval $(call lint_run,interp_dp_w3,interp_dp,interp/interp.f,-GW=3))
