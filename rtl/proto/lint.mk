# Lint runs of rtl/proto (see rtl/Makefile): the step loop prototype at the
# width of the measure (W = 24) and at the ends of its range (W = 4, 30).
$(foreach w,4 24 30,$(eval $(call lint_run,dloop_w$(w),dloop,proto/dloop/dloop.f,-GW=$(w))))
