# Lint runs of rtl/cpu8085 and rtl/board8085 (see rtl/Makefile).
$(eval $(call lint_run,cpu8085,cpu8085,cpu8085/cpu8085.f,))
$(eval $(call lint_run,board8085,board8085,board8085/board8085.f,))
