# Lint runs of rtl/synth (see rtl/Makefile): the iCEBreaker board top.
LINT_TOPS += icebreaker_top
icebreaker_top_TOP := icebreaker_top
icebreaker_top_SRCS := synth/icebreaker/icebreaker_top.v $(INTERP_TOP_SRCS)
icebreaker_top_ARGS := -Iinterp
