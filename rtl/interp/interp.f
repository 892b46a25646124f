// rtl/interp: paper A's interpolator, the one file list that CMake, lint,
// synthesis, formal and the co-simulation read (the format: rtl/filelist).
+incdir+interp
interp/interp_top.v
interp/wb_regs.v
interp/cmd_gen.v
interp/step_out.v
interp/step_chan.v
interp/pos_counter.v
interp/interp_core.v
interp/interp_dp.v
interp/blk_prep.v
interp/move_fifo.v
