# `contour table1 --format json` on engine iss and on engine cpu (the
# Verilated board): every figure must be the same (the board is T-state
# exact); only the engine's name and how the period was found may differ,
# and the board's period must have been confirmed on the board.
# -DCONTOUR=...
foreach(engine iss cpu)
  execute_process(COMMAND ${CONTOUR} table1 --format json --engine ${engine} --progress
                  OUTPUT_VARIABLE out_${engine} ERROR_VARIABLE err_${engine} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "table1 --engine ${engine} exited with ${rc}: ${err_${engine}}")
  endif()
  # With progress on, a line on stderr says how long the run takes.
  if(NOT err_${engine} MATCHES "table1: engine ${engine}, about [0-9.]+ (s|min): ")
    message(FATAL_ERROR "table1 --engine ${engine}: no time estimate first on stderr: ${err_${engine}}")
  endif()
endforeach()
foreach(row linear circular)
  string(JSON m GET "${out_cpu}" ${row} period_min_method)
  if(NOT m MATCHES "confirmed on engine cpu")
    message(FATAL_ERROR "${row}: the board's period was not confirmed on the board: ${m}")
  endif()
endforeach()
foreach(engine iss cpu)
  set(j "${out_${engine}}")
  string(JSON j REMOVE "${j}" engine)
  string(JSON j REMOVE "${j}" linear period_min_method)
  string(JSON j REMOVE "${j}" circular period_min_method)
  set(cmp_${engine} "${j}")
endforeach()
if(NOT cmp_iss STREQUAL cmp_cpu)
  message(FATAL_ERROR "table1 differs between engines\n--- iss\n${out_iss}\n--- cpu\n${out_cpu}")
endif()
string(JSON tmax GET "${out_cpu}" linear tstates_max)
message(STATUS "table1: engines iss and cpu agree (linear tstates_max ${tmax})")
