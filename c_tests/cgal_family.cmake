# One generated cross-check run (a ctest entry of cgal.cmake):
#
#   cmake -DTESTGEN=segvoronoi-testgen -DCHECK=segvoronoi_cgal_check
#         -DFAMILY=name -DCOUNT=n -DSEED=seed -DINPUT=file.txt -P cgal_family.cmake
#
# writes the family's input to INPUT (kept, to rerun or debug by hand) and
# compares it: `segvoronoi_cgal_check --file INPUT --family FAMILY`, with
# --degenerate for the families the generator says are compared so, or
# `--polygon INPUT --family FAMILY` (the medial axis) for the ring families
# (the generator says "polygon"). Fails when either program does.
foreach(_var TESTGEN CHECK FAMILY COUNT SEED INPUT)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "cgal_family.cmake: ${_var} is not set")
  endif()
endforeach()
get_filename_component(_dir "${INPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${_dir}")
execute_process(COMMAND "${TESTGEN}" "${FAMILY}" "${COUNT}" "${SEED}" OUTPUT_FILE "${INPUT}" RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "segvoronoi-testgen ${FAMILY} ${COUNT} ${SEED}: ${_status}")
endif()
execute_process(COMMAND "${TESTGEN}" --comparison "${FAMILY}"
                OUTPUT_VARIABLE _comparison OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "segvoronoi-testgen --comparison ${FAMILY}: ${_status}")
endif()
set(_mode --file)
set(_flags --family "${FAMILY}")
if(_comparison STREQUAL "degenerate")
  list(APPEND _flags --degenerate)
elseif(_comparison STREQUAL "polygon")
  set(_mode --polygon)
endif()
execute_process(COMMAND "${CHECK}" ${_mode} "${INPUT}" ${_flags} RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "segvoronoi_cgal_check ${_mode} ${INPUT} ${_flags}: exit status ${_status}")
endif()
