# install_run.cmake (cmake -P): runs the installed contour's engines and
# compares their output with paper A's figures (Fig. 2: line 6 5).
#   -DPREFIX=install prefix -DVERSION=x.y.z
cmake_minimum_required(VERSION 3.25)
set(fig2 "\\+X \\+Y \\+X \\+Y \\+X \\+Y \\+X \\+Y \\+X \\+Y \\+X\n")  # a regex
set(failed 0)
# expect(<expected stdout regex> <args>...): exit status 0 and stdout matching.
function(expect pattern)
  execute_process(COMMAND ${PREFIX}/bin/contour ${ARGN}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${pattern}")
    string(SUBSTRING "${out}" 0 400 shown)
    message("FAIL contour ${ARGN}: status ${rc}\n${shown}${err}")
    set(failed 1 PARENT_SCOPE)
  else()
    message("ok   contour ${ARGN}")
  endif()
endfunction()

expect("^contour ${VERSION}\n$" --version)
foreach(engine model core iss cpu)
  expect("^${fig2}$" line 6 5 --format steps --engine ${engine})
endforeach()
file(WRITE ${PREFIX}/hlt.bin "v")  # 76h: HLT
foreach(engine iss cpu)
  expect("^T-states: 5\n$" sim85 ${PREFIX}/hlt.bin --engine ${engine})
endforeach()
expect("The paper.s measure: the longest routine" table1 --no-progress)
expect("^100.00% PASS 8 PASSED, 0 FAILED\n" cosim --suite paper --rate 4k --engines model,core,iss,cpu --no-progress)
if(failed)
  message(FATAL_ERROR "the installed contour failed")
endif()
