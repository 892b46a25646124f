# Lint runs of rtl/board (see rtl/Makefile): the board at its default and
# at a slow baud rate, and the chord peripheral at the ends of its widths.
$(eval $(call lint_run,board_top,board_top,board/board.f,))
$(eval $(call lint_run,board_top_9600,board_top,board/board.f,-GCLKS_PER_BIT=1250))
$(foreach w,2 16 30,$(eval $(call lint_run,interp3_top_w$(w),interp3_top,board/board.f,-GW=$(w))))
$(eval $(call lint_run,link_top,link_top,board/board.f,synth/icebreaker/link_top.v))
