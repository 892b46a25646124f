# Lint runs of rtl/proto (see rtl/Makefile): the step loop prototypes (two
# steps ahead: dloop, one: dloop1, one with a one-clock load: dloop1l, and crossings: dloop1x) at the width of the measure (W = 24) and
# at the ends of their range (W = 4, 30).
$(foreach m,dloop dloop1 dloop1l dloop1x,$(foreach w,4 24 30,$(eval $(call lint_run,$(m)_w$(w),$(m),proto/dloop/dloop.f,-GW=$(w)))))
