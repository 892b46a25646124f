# Lint runs of rtl/interp3 (see rtl/Makefile): the core at the widths the
# regression uses (W = 4, exhaustive; W = 24, the engine) and at the ends of
# its accepted range (W = 2, 30).
LINT_TOPS += interp3_core_w2 interp3_core_w4 interp3_core_w24 interp3_core_w30
interp3_core_w2_TOP := interp3_core
interp3_core_w2_SRCS := interp3/interp3_core.v
interp3_core_w2_ARGS := -GW=2
interp3_core_w4_TOP := interp3_core
interp3_core_w4_SRCS := interp3/interp3_core.v
interp3_core_w4_ARGS := -GW=4
interp3_core_w24_TOP := interp3_core
interp3_core_w24_SRCS := interp3/interp3_core.v
interp3_core_w24_ARGS := -GW=24
interp3_core_w30_TOP := interp3_core
interp3_core_w30_SRCS := interp3/interp3_core.v
interp3_core_w30_ARGS := -GW=30
# The synthesis wrapper (rtl/interp3/synth, W = 24).
LINT_TOPS += interp3_wrap
interp3_wrap_TOP := interp3_wrap
interp3_wrap_SRCS := interp3/synth/interp3_wrap.v interp3/interp3_core.v
interp3_wrap_ARGS :=
