# install_test.cmake (cmake -P): installs the build into a temporary prefix
# and runs every engine from there with the build tree out of reach
# (install_run.cmake does the runs and checks).
#   -DBUILD=build dir -DSOURCE=source dir -DHEX_DIR=assembled programs -DVERSION=x.y.z
cmake_minimum_required(VERSION 3.25)
string(RANDOM LENGTH 8 tag)
set(prefix /tmp/contour-install-${tag})
file(REMOVE_RECURSE ${prefix})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix}
                OUTPUT_QUIET RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif()
foreach(f bin/contour bin/contour-cosim share/doc/contour/LICENSE)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()

set(run ${CMAKE_COMMAND} -DPREFIX=${prefix} -DVERSION=${VERSION} -P ${CMAKE_CURRENT_LIST_DIR}/install_run.cmake)
# Preferred: a private mount namespace with an empty tmpfs over the build
# tree, i.e. the build deleted as far as the installed programs can tell.
execute_process(COMMAND unshare -rm sh -c "mount -t tmpfs none '${BUILD}' && test ! -e '${BUILD}/CMakeCache.txt'"
                RESULT_VARIABLE ns_rc OUTPUT_QUIET ERROR_QUIET)
if(ns_rc EQUAL 0)
  string(REPLACE ";" " " run_sh "${run}")
  execute_process(COMMAND unshare -rm sh -c "mount -t tmpfs none '${BUILD}' && ${run_sh}" RESULT_VARIABLE rc)
  set(how "build tree hidden by a tmpfs")
else()
  # Fallback: the assembled programs (the files an installed contour once
  # read from the build tree) moved aside during the runs, then put back.
  file(RENAME ${HEX_DIR} ${HEX_DIR}.hidden-by-install-test)
  execute_process(COMMAND ${run} RESULT_VARIABLE rc)
  file(RENAME ${HEX_DIR}.hidden-by-install-test ${HEX_DIR})
  set(how "${HEX_DIR} moved aside")
endif()
file(REMOVE_RECURSE ${prefix})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed contour failed (${how})")
endif()
message("install_relocated: every engine ran from the prefix (${how})")
