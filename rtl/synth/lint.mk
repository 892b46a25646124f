# Lint runs of rtl/synth (see rtl/Makefile): the timing wrapper around
# every design `make synth` builds, and the iCEBreaker board top.
$(foreach d,DP CORE TOP,$(eval $(call lint_run,timing_wrap_$(d),timing_wrap,interp/interp.f,synth/timing_wrap.v -DDESIGN_$(d))))
$(eval $(call lint_run,timing_wrap_CORE_FREE,timing_wrap,interp/interp.f,synth/timing_wrap.v -DDESIGN_CORE -DCMD_HIGH))
$(eval $(call lint_run,timing_wrap_INTERP3,timing_wrap,interp3/interp3.f,synth/timing_wrap.v -DDESIGN_INTERP3))
$(foreach d,DLOOP DLOOP_NOD DLOOP1 DLOOP1_NOD DLOOP1L DLOOP1L_NOD DLOOP1X DLOOP1X_NOD,$(eval $(call lint_run,timing_wrap_$(d),timing_wrap,proto/dloop/dloop.f,synth/timing_wrap.v -DDESIGN_$(d))))
$(eval $(call lint_run,timing_wrap_CPU8085,timing_wrap,cpu8085/cpu8085.f,synth/timing_wrap.v -DDESIGN_CPU8085))
$(eval $(call lint_run,timing_wrap_BOARD8085,timing_wrap,board8085/board8085.f,synth/timing_wrap.v -DDESIGN_BOARD8085))
$(eval $(call lint_run,icebreaker_top,icebreaker_top,interp/interp.f,synth/icebreaker/icebreaker_top.v))
# The datapath's timing stub of the analysis design core_nodp (designs.mk).
$(eval $(call lint_run,dp_stub,dp_stub,synth/dp_stub.f,))
