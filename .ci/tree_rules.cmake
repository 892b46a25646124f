# tree_rules.cmake (cmake -DROOT=<source dir> -P): the rules that keep the
# tree showing the architecture (README, "Architecture"). Each broken rule
# is one line naming the file; exit status non-zero if any.
#
#   1. rtl/ is Verilog: no C or C++ source under it.
#   2. The layers: nothing under model/ or sw8085/ includes a header of
#      rtl/ or tb/, or a Verilated model (V*.h, verilated*.h).
#   3. One file list per core: every .v of rtl/<core>/ (but formal/) is
#      named by exactly one rtl/*/*.f (prototypes: rtl/proto/*/*.f), and
#      every name there exists.
#   4. One harness base: only tb/common/harness.hpp makes a VerilatedContext.
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
  message(FATAL_ERROR "tree_rules: -DROOT=<source dir> is required")
endif()
set(broken 0)
macro(rule_broken text)
  message("tree_rules: ${text}")
  math(EXPR broken "${broken} + 1")
endmacro()

# 1
file(GLOB_RECURSE cxx RELATIVE ${ROOT} ${ROOT}/rtl/*.cpp ${ROOT}/rtl/*.hpp ${ROOT}/rtl/*.h ${ROOT}/rtl/*.cc)
foreach(f IN LISTS cxx)
  rule_broken("${f}: C++ under rtl/ (rtl/ is Verilog; harnesses go to tb/)")
endforeach()

# 2
file(GLOB_RECURSE above RELATIVE ${ROOT} ${ROOT}/tb/*.hpp ${ROOT}/tb/*.h)
set(above_names "")
foreach(f IN LISTS above)
  get_filename_component(n ${f} NAME)
  list(APPEND above_names ${n})
endforeach()
file(GLOB_RECURSE lower RELATIVE ${ROOT} ${ROOT}/model/*.cpp ${ROOT}/model/*.hpp ${ROOT}/sw8085/*.cpp ${ROOT}/sw8085/*.hpp)
list(FILTER lower EXCLUDE REGEX "node_modules/")
foreach(f IN LISTS lower)
  file(STRINGS ${ROOT}/${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"<]*[\"<]([^\">]+)[\">].*$" "\\1" inc "${line}")
    get_filename_component(n ${inc} NAME)
    if(inc MATCHES "^(rtl|tb)/" OR n MATCHES "^V[a-z0-9_]+\\.h$" OR n MATCHES "^verilated" OR n IN_LIST above_names)
      rule_broken("${f}: includes ${inc}, from a layer above (rtl/ or tb/)")
    endif()
  endforeach()
endforeach()

# 3
file(GLOB lists RELATIVE ${ROOT}/rtl ${ROOT}/rtl/*/*.f ${ROOT}/rtl/proto/*/*.f)
set(listed "")
foreach(l IN LISTS lists)
  file(STRINGS ${ROOT}/rtl/${l} lines)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "//.*$" "" line "${line}")
    string(STRIP "${line}" line)
    if(line STREQUAL "" OR line MATCHES "^(-f|\\+incdir\\+)")
      continue()
    endif()
    if(NOT EXISTS ${ROOT}/rtl/${line})
      rule_broken("rtl/${l}: names rtl/${line}, which does not exist")
    endif()
    if(line IN_LIST listed)
      rule_broken("rtl/${line}: in more than one file list")
    endif()
    list(APPEND listed ${line})
  endforeach()
endforeach()
file(GLOB_RECURSE sources RELATIVE ${ROOT}/rtl ${ROOT}/rtl/*.v)
list(FILTER sources EXCLUDE REGEX "(^synth/|/formal/)")
foreach(v IN LISTS sources)
  if(NOT v IN_LIST listed)
    rule_broken("rtl/${v}: in no file list (rtl/<core>/<core>.f)")
  endif()
endforeach()

# 4
file(GLOB_RECURSE harnesses RELATIVE ${ROOT} ${ROOT}/tb/*.cpp ${ROOT}/tb/*.hpp ${ROOT}/sim/*.cpp ${ROOT}/sim/*.hpp)
foreach(f IN LISTS harnesses)
  if(f STREQUAL "tb/common/harness.hpp")
    continue()
  endif()
  file(STRINGS ${ROOT}/${f} made REGEX "(make_unique<VerilatedContext>|new VerilatedContext)")
  if(made)
    rule_broken("${f}: makes its own VerilatedContext (use tb/common/harness.hpp)")
  endif()
endforeach()

if(broken GREATER 0)
  message(FATAL_ERROR "tree_rules: ${broken} rule(s) broken")
endif()
message("tree_rules: rtl/ Verilog only, layers kept, one file list per core (${lists}), one harness base")
