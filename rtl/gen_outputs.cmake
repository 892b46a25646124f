# gen_outputs.cmake: the shared tail of the table generators run with
# `cmake -P` (rtl/interp/regmap_gen.cmake, rtl/board/proto_gen.cmake).
# gen_outputs(TOOL SCRIPT) writes the generated texts ${h}, ${vh}, ${md}:
#   OUT_H     the C header (rewritten only when it changes, so nothing rebuilds needlessly)
#   WRITE_VH / WRITE_MD   the committed Verilog include / Markdown page
#   CHECK_VH / CHECK_MD   the committed copies, which must equal the texts
# DEF names the table in the error messages.
function(gen_outputs tool script)
  if(OUT_H)
    file(WRITE ${OUT_H}.tmp "${h}")
    file(COPY_FILE ${OUT_H}.tmp ${OUT_H} ONLY_IF_DIFFERENT)
    file(REMOVE ${OUT_H}.tmp)
  endif()
  if(WRITE_VH)
    file(WRITE ${WRITE_VH} "${vh}")
  endif()
  if(WRITE_MD)
    file(WRITE ${WRITE_MD} "${md}")
  endif()
  foreach(kind VH MD)
    if(CHECK_${kind})
      if(NOT EXISTS ${CHECK_${kind}})
        message(FATAL_ERROR "${tool}: ${CHECK_${kind}} is missing; regenerate it (see ${script})")
      endif()
      file(READ ${CHECK_${kind}} have)
      string(TOLOWER ${kind} k)
      if(NOT have STREQUAL "${${k}}")
        message(FATAL_ERROR "${tool}: ${CHECK_${kind}} is out of date with ${DEF}; regenerate it (see ${script})")
      endif()
    endif()
  endforeach()
endfunction()
