# Installs the libraries, the header, the CMake package files and the
# pkg-config module. Every installed path is relative to the prefix, so the
# installed tree can be moved.

include(CMakePackageConfigHelpers)

install(FILES "${SEGVORONOI_SHARED_FILE}" ${SEGVORONOI_SHARED_LINKS}
        DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT runtime
        PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
install(FILES "${SEGVORONOI_STATIC_FILE}" DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT development)
install(FILES "${PROJECT_SOURCE_DIR}/include/segvoronoi.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" COMPONENT development)

set(SEGVORONOI_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/segvoronoi")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/segvoronoiConfig.cmake.in"
  "${CMAKE_CURRENT_BINARY_DIR}/segvoronoiConfig.cmake"
  INSTALL_DESTINATION "${SEGVORONOI_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR)
# Before 1.0 a new minor version is not compatible (same rule as the SONAME).
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_segvoronoi_compat SameMinorVersion)
else()
  set(_segvoronoi_compat SameMajorVersion)
endif()
write_basic_package_version_file(
  "${CMAKE_CURRENT_BINARY_DIR}/segvoronoiConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY ${_segvoronoi_compat})
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/segvoronoiConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/segvoronoiConfigVersion.cmake"
        DESTINATION "${SEGVORONOI_CMAKE_DIR}" COMPONENT development)

# pkg-config: the prefix is found from the .pc file's own location.
set(_segvoronoi_pc_dir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH SEGVORONOI_PC_TO_PREFIX "/prefix/${_segvoronoi_pc_dir}" "/prefix")
string(REGEX REPLACE "/$" "" SEGVORONOI_PC_TO_PREFIX "${SEGVORONOI_PC_TO_PREFIX}")
list(TRANSFORM SEGVORONOI_STATIC_SYSTEM_LIBS PREPEND "-l" OUTPUT_VARIABLE _segvoronoi_pc_libs)
list(JOIN _segvoronoi_pc_libs " " SEGVORONOI_PC_LIBS_PRIVATE)
configure_file("${CMAKE_CURRENT_LIST_DIR}/segvoronoi.pc.in" "${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.pc" @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.pc" DESTINATION "${_segvoronoi_pc_dir}" COMPONENT development)
