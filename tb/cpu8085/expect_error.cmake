# Runs COMMAND (a ;-list) and passes only if it exits with status RC and its
# stderr is one line matching PATTERN.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL RC)
  message(FATAL_ERROR "exit status ${rc}, expected ${RC}; stderr: ${err}")
endif()
string(STRIP "${err}" line)
if(line MATCHES "\n")
  message(FATAL_ERROR "more than one line on stderr: ${err}")
endif()
if(NOT line MATCHES "${PATTERN}")
  message(FATAL_ERROR "stderr '${line}' does not match '${PATTERN}'")
endif()
message(STATUS "as expected: ${line}")
