# Checks the installed shared library's dynamic symbols (issue 28): every
# defined symbol is a function of the header with the version node
# SEGVORONOI_<SOVERSION> (the ABI version of the SONAME), plus that node;
# nothing of Rust's std is exported; and every function the header declares
# is exported.
#
#   cmake -DNM=nm -DLIB=libsegvoronoi.so -DHEADER=segvoronoi.h -P symbols.cmake
foreach(_var NM LIB HEADER)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "symbols.cmake: -D${_var}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${NM}" -D --defined-only "${LIB}"
                OUTPUT_VARIABLE _out RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${NM} -D --defined-only ${LIB} failed")
endif()
execute_process(COMMAND readelf -d "${LIB}" OUTPUT_VARIABLE _dynamic)
string(REGEX MATCH "Library soname: \\[libsegvoronoi\\.so\\.([0-9.]+)\\]" _ "${_dynamic}")
set(_soversion "${CMAKE_MATCH_1}")
if(_soversion STREQUAL "")
  message(FATAL_ERROR "${LIB} has no SONAME libsegvoronoi.so.X")
endif()
set(_node "SEGVORONOI_${_soversion}")

# The header's functions: `name(` after a return type, at a line's start.
file(STRINGS "${HEADER}" _decls REGEX "^[a-z].*[ *](segvoronoi_[a-z0-9_]+)\\(")
set(_declared "")
foreach(_line IN LISTS _decls)
  string(REGEX MATCH "(segvoronoi_[a-z0-9_]+)\\(" _ "${_line}")
  list(APPEND _declared "${CMAKE_MATCH_1}")
endforeach()
list(REMOVE_DUPLICATES _declared)
list(LENGTH _declared _n_declared)

string(REPLACE "\n" ";" _lines "${_out}")
set(_exported "")
set(_bad "")
set(_has_node FALSE)
foreach(_line IN LISTS _lines)
  if(_line STREQUAL "")
    continue()
  endif()
  if(_line MATCHES " A ${_node}$")
    set(_has_node TRUE)
  elseif(_line MATCHES " T (segvoronoi_[a-z0-9_]+)@@${_node}$")
    list(APPEND _exported "${CMAKE_MATCH_1}")
  else()
    list(APPEND _bad "${_line}")
  endif()
endforeach()
list(LENGTH _exported _n_exported)

if(_bad)
  string(REPLACE ";" "\n  " _bad "${_bad}")
  message(FATAL_ERROR "exported symbols other than segvoronoi_*@@${_node}:\n  ${_bad}")
endif()
if(NOT _has_node)
  message(FATAL_ERROR "no version node ${_node} in ${LIB}")
endif()
set(_missing ${_declared})
list(REMOVE_ITEM _missing ${_exported})
set(_extra ${_exported})
list(REMOVE_ITEM _extra ${_declared})
if(_missing OR _extra)
  message(FATAL_ERROR "header and library differ: declared, not exported: ${_missing}; exported, not declared: ${_extra}")
endif()
message(STATUS "${LIB}: ${_n_exported} functions, all @@${_node}, as declared in the header (${_n_declared}); nothing else exported")
