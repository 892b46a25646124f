// rtl/cpu8085: the T-state-exact Verilog 8085.
cpu8085/cpu8085.v
cpu8085/cpu8085_decode.v
+incdir+cpu8085
