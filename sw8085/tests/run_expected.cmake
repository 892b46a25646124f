# Runs `contour sim85 ${ARGS} ${HEX}` and compares its stdout with
# ${EXPECTED} (minus its first line, `# args: ...`). Exit status must be 0.
# ${HEX} is the .hex assembled from the program the .expected file is named for.
execute_process(COMMAND ${CONTOUR} sim85 ${ARGS} ${HEX}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contour sim85 ${ARGS} ${HEX} exited with ${rc}: ${err}")
endif()
file(READ ${EXPECTED} expected)
string(REGEX REPLACE "^# args:[^\n]*\n" "" expected "${expected}")
# CP/M programs end lines with CR LF; compare lines, not line ends.
string(REPLACE "\r" "" out "${out}")
# `T-states: *` in the expected text: any count (when it is not hand-counted).
string(FIND "${expected}" "\nT-states: *\n" any_count)
if(any_count GREATER -1)
  string(REGEX REPLACE "\nT-states: [0-9]+\n" "\nT-states: *\n" out "${out}")
endif()
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "output differs from ${EXPECTED}\n--- got ---\n${out}--- expected ---\n${expected}")
endif()
