# Compiles tb/cpu8085/board_tb.v with the board under Icarus and runs it.
# -DIVERILOG= -DVVP= -DOUT=<scratch> -DROM=<memh> -DSOURCES="a.v;b.v;..."
# -DINCDIRS="dir;..." (the file lists' +incdir+)
set(incflags "")
foreach(dir IN LISTS INCDIRS)
  list(APPEND incflags -I${dir})
endforeach()
execute_process(COMMAND ${IVERILOG} -g2005 ${incflags} -o ${OUT} ${SOURCES}
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "iverilog failed: ${err}${out}")
endif()
execute_process(COMMAND ${VVP} -n ${OUT} +rom=${ROM} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "PASS board_tb" OR out MATCHES "FAIL")
  message(FATAL_ERROR "board_tb under Icarus failed: ${out}${err}")
endif()
