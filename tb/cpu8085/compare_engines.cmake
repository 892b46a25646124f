# Runs `contour sim85 HEX ARGS` with --engine iss and --engine cpu and fails
# unless stdout, the exit status and the --trace files are identical.
# -DCONTOUR=... -DHEX=... -DARGS="--cpm" -DWORK=<scratch dir>
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(MAKE_DIRECTORY ${WORK})
foreach(engine iss cpu)
  execute_process(
    COMMAND ${CONTOUR} sim85 ${HEX} ${args} --engine ${engine} --trace ${WORK}/${engine}.trace
    OUTPUT_VARIABLE out_${engine} ERROR_VARIABLE err_${engine} RESULT_VARIABLE rc_${engine})
endforeach()
if(NOT rc_iss EQUAL 0)
  message(FATAL_ERROR "iss run failed (${rc_iss}): ${err_iss}")
endif()
if(NOT rc_iss STREQUAL rc_cpu)
  message(FATAL_ERROR "exit status: iss ${rc_iss}, cpu ${rc_cpu}: ${err_cpu}")
endif()
if(NOT out_iss STREQUAL out_cpu)
  message(FATAL_ERROR "output differs\n--- iss\n${out_iss}\n--- cpu\n${out_cpu}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/iss.trace ${WORK}/cpu.trace
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "traces differ: ${WORK}/iss.trace ${WORK}/cpu.trace")
endif()
string(REGEX MATCH "T-states: [0-9]+" last "${out_cpu}")
message(STATUS "iss and cpu agree: ${last}")
