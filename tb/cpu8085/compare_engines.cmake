# Runs `contour sim85 HEX ARGS` with --engine iss and --engine rtl and fails
# unless stdout, the exit status and the --trace files are identical.
# -DCONTOUR=... -DHEX=... -DARGS="--cpm" -DWORK=<scratch dir>
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(MAKE_DIRECTORY ${WORK})
foreach(engine iss rtl)
  execute_process(
    COMMAND ${CONTOUR} sim85 ${HEX} ${args} --engine ${engine} --trace ${WORK}/${engine}.trace
    OUTPUT_VARIABLE out_${engine} ERROR_VARIABLE err_${engine} RESULT_VARIABLE rc_${engine})
endforeach()
if(NOT rc_iss EQUAL 0)
  message(FATAL_ERROR "iss run failed (${rc_iss}): ${err_iss}")
endif()
if(NOT rc_iss STREQUAL rc_rtl)
  message(FATAL_ERROR "exit status: iss ${rc_iss}, rtl ${rc_rtl}: ${err_rtl}")
endif()
if(NOT out_iss STREQUAL out_rtl)
  message(FATAL_ERROR "output differs\n--- iss\n${out_iss}\n--- rtl\n${out_rtl}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/iss.trace ${WORK}/rtl.trace
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "traces differ: ${WORK}/iss.trace ${WORK}/rtl.trace")
endif()
string(REGEX MATCH "T-states: [0-9]+" last "${out_rtl}")
message(STATUS "iss and rtl agree: ${last}")
