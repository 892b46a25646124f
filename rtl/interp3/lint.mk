# Lint runs of rtl/interp3 (see rtl/Makefile): the core at the widths the
# regression uses (W = 4, exhaustive; W = 24, the engine) and at the ends of
# its accepted range (W = 2, 30).
$(foreach w,2 4 24 30,$(eval $(call lint_run,interp3_core_w$(w),interp3_core,interp3/interp3.f,-GW=$(w))))
