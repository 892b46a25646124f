# Runs `contour sim85 <args> ${HEX}` (the args: first line of ${EXPECTED},
# `# args: ...`) and fails unless it exits 0 with stdout (CR dropped) equal
# to the rest of ${EXPECTED}.
file(READ ${EXPECTED} expected)
string(REGEX MATCH "^# args:[^\n]*" first "${expected}")
string(REGEX REPLACE "^# args: *" "" args "${first}")
separate_arguments(args UNIX_COMMAND "${args}")
string(REGEX REPLACE "^# args:[^\n]*\n" "" expected "${expected}")
execute_process(COMMAND ${CONTOUR} sim85 ${args} ${HEX}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contour sim85 ${args} ${HEX} exited with ${rc}: ${err}")
endif()
string(REPLACE "\r" "" out "${out}")
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "output differs from ${EXPECTED}\n--- got ---\n${out}--- expected ---\n${expected}")
endif()
