# expect_run.cmake (cmake -DCOMMAND=<;-list> -DRC=<status> [-DPATTERN=<re>]
#                   [-DOUT_PATTERN=<re>] -P): runs COMMAND and passes only if
#   - it exits with status RC exactly (a crash or a signal never passes),
#   - with PATTERN: its stderr is one line matching PATTERN,
#   - with OUT_PATTERN: its stdout matches OUT_PATTERN.
# The top CMakeLists.txt names it CONTOUR_EXPECT_RUN for every folder.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED COMMAND OR NOT DEFINED RC)
  message(FATAL_ERROR "expect_run: -DCOMMAND and -DRC are required")
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL RC)
  message(FATAL_ERROR "exit status ${rc}, expected ${RC}; stderr: ${err}")
endif()
if(DEFINED PATTERN)
  string(STRIP "${err}" line)
  if(line MATCHES "\n")
    message(FATAL_ERROR "more than one line on stderr: ${err}")
  endif()
  if(NOT line MATCHES "${PATTERN}")
    message(FATAL_ERROR "stderr '${line}' does not match '${PATTERN}'")
  endif()
  message(STATUS "as expected: ${line}")
endif()
if(DEFINED OUT_PATTERN)
  if(NOT out MATCHES "${OUT_PATTERN}")
    message(FATAL_ERROR "stdout does not match '${OUT_PATTERN}':\n${out}")
  endif()
  message(STATUS "as expected: exit ${rc}, stdout matches '${OUT_PATTERN}'")
endif()
