// rtl/cpu8085: the T-state-exact Verilog 8085.
cpu8085/cpu8085.v
+incdir+cpu8085
