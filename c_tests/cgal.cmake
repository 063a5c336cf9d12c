# Cross-check against CGAL's segment Delaunay graph (exact predicates).
# Included by c_tests/CMakeLists.txt after find_package(segvoronoi); adds the
# program segvoronoi_cgal_check and one test per input family, or skips with
# a warning when the CGAL headers, Boost headers, GMP or MPFR are missing.
#
# find_package(CGAL) is deliberately not used: its config also changes
# project-wide settings (build type), and the headers plus two libraries are
# all a header-only CGAL needs.

find_path(SEGVORONOI_CGAL_INCLUDE_DIR CGAL/Segment_Delaunay_graph_hierarchy_2.h)
find_path(SEGVORONOI_BOOST_INCLUDE_DIR boost/config.hpp)
find_library(SEGVORONOI_GMP_LIBRARY gmp)
find_library(SEGVORONOI_MPFR_LIBRARY mpfr)

if(NOT SEGVORONOI_CGAL_INCLUDE_DIR OR NOT SEGVORONOI_BOOST_INCLUDE_DIR
   OR NOT SEGVORONOI_GMP_LIBRARY OR NOT SEGVORONOI_MPFR_LIBRARY)
  message(WARNING "CGAL cross-check skipped: need the CGAL and Boost headers, GMP and MPFR "
                  "(Debian: libcgal-dev libboost-dev libgmp-dev libmpfr-dev)")
  return()
endif()

add_executable(segvoronoi_cgal_check ${CMAKE_CURRENT_LIST_DIR}/cgal_crosscheck.cpp)
set_target_properties(segvoronoi_cgal_check PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
target_include_directories(segvoronoi_cgal_check SYSTEM PRIVATE
  ${SEGVORONOI_CGAL_INCLUDE_DIR} ${SEGVORONOI_BOOST_INCLUDE_DIR})
# -O2 whatever the build type: CGAL unoptimised is too slow for 100k points.
target_compile_options(segvoronoi_cgal_check PRIVATE -O2)
# CGAL's interval filter switches the rounding mode; GCC must not fold
# floating-point expressions across that (CGAL's own setup adds the same).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(segvoronoi_cgal_check PRIVATE -frounding-math)
endif()
target_link_libraries(segvoronoi_cgal_check PRIVATE
  segvoronoi::segvoronoi ${SEGVORONOI_MPFR_LIBRARY} ${SEGVORONOI_GMP_LIBRARY})

# family, point count, timeout in seconds
set(_segvoronoi_cgal_runs
  "uniform 1000 60"
  "uniform 100000 300"
  "clustered 10000 120"
  "tiny 10000 120"
  "tiny-offset 10000 120"
  "huge 10000 120"
  "lattice 10000 120"
  "circle 2916 300"
  "collinear 1000 60")
foreach(_run IN LISTS _segvoronoi_cgal_runs)
  separate_arguments(_run)
  list(GET _run 0 _family)
  list(GET _run 1 _count)
  list(GET _run 2 _timeout)
  add_test(NAME cgal_${_family}_${_count} COMMAND segvoronoi_cgal_check ${_family} ${_count})
  set_tests_properties(cgal_${_family}_${_count} PROPERTIES TIMEOUT ${_timeout} LABELS cgal)
endforeach()
unset(_segvoronoi_cgal_runs)

# Regression inputs from library bugs this cross-check found: edge lengths
# that underflowed when squared (tiny lattice), and a repeated point that a
# walk with rounded distance comparisons missed (snapped, seed 3).
add_test(NAME cgal_tiny-lattice_2500 COMMAND segvoronoi_cgal_check tiny-lattice 2500)
add_test(NAME cgal_snapped_40_seed3 COMMAND segvoronoi_cgal_check snapped 40 3)
set_tests_properties(cgal_tiny-lattice_2500 cgal_snapped_40_seed3 PROPERTIES TIMEOUT 120 LABELS cgal)

# Few distinct coordinate values a hair apart: repeats, collinear and
# cocircular points and needle triangles, several seeds.
foreach(_seed 1 2 3 4 5)
  add_test(NAME cgal_snapped_150_seed${_seed} COMMAND segvoronoi_cgal_check snapped 150 ${_seed})
  set_tests_properties(cgal_snapped_150_seed${_seed} PROPERTIES TIMEOUT 60 LABELS cgal)
endforeach()
