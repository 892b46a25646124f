# Runs `contour sim85 ${ARGS} ${HEX}` and compares its stdout with
# ${EXPECTED} (minus its first line, `# args: ...`). Exit status must be 0.
execute_process(COMMAND ${CONTOUR} sim85 ${ARGS} ${HEX}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contour sim85 ${ARGS} ${HEX} exited with ${rc}: ${err}")
endif()
file(READ ${EXPECTED} expected)
string(REGEX REPLACE "^# args:[^\n]*\n" "" expected "${expected}")
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "output differs from ${EXPECTED}\n--- got ---\n${out}--- expected ---\n${expected}")
endif()
