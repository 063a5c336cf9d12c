# Installs the libraries, the header, the CMake package files and the
# pkg-config module. Every installed path is relative to the prefix, so the
# installed tree can be moved.
#
# Two components, split as distributions split a library into a runtime and a
# -dev package (CMake's own names, as in install(TARGETS ... COMPONENT Runtime
# NAMELINK_COMPONENT Development)):
#   Runtime      libsegvoronoi.so.X.Y.Z and its SONAME link libsegvoronoi.so.X.Y,
#                all a program linked against the library needs to run;
#   Development  the unversioned link libsegvoronoi.so (what -lsegvoronoi
#                finds at link time), the static library, the header, the CMake
#                package files and segvoronoi.pc;
#   Cli          bin/segvoronoi, the program, with -DSEGVORONOI_INSTALL_CLI=ON
#                (it links the library statically, as every Rust program does).
#   cmake --install build --component Runtime --prefix /usr
#
# Stripping: like every CMake project, the plain install keeps the symbol
# tables (distributions strip themselves and keep the debug information in a
# separate package), and `cmake --install build --strip` installs release
# libraries stripped. CMake strips only the targets it builds itself, and ours
# come from cargo, so the rules below do it: the shared library with
# --strip-unneeded (its exported symbols stay in .dynsym), the static library
# with --strip-debug only (a static library without its symbol table cannot be
# linked), as Debian's dh_strip does.

include(CMakePackageConfigHelpers)

install(FILES "${SEGVORONOI_SHARED_FILE}" "${SEGVORONOI_SONAME_LINK}"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Runtime
        PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
install(FILES "${SEGVORONOI_DEV_LINK}" DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Development)
install(FILES "${SEGVORONOI_STATIC_FILE}" DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT Development)
install(FILES "${PROJECT_SOURCE_DIR}/capi/include/segvoronoi.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" COMPONENT Development)

if(SEGVORONOI_INSTALL_CLI)
  install(PROGRAMS "${SEGVORONOI_CLI_FILE}" DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT Cli)
endif()

# `cmake --install --strip` (CMAKE_INSTALL_DO_STRIP) for the two libraries
# and the program: `file` as installed in `dir`.
function(_segvoronoi_install_strip component flag file dir)
  if(NOT CMAKE_STRIP)
    return()
  endif()
  get_filename_component(_name "${file}" NAME)
  if(IS_ABSOLUTE "${dir}")
    set(_installed "\$ENV{DESTDIR}${dir}/${_name}")
  else()
    set(_installed "\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${dir}/${_name}")
  endif()
  install(CODE "
    if(CMAKE_INSTALL_DO_STRIP)
      message(STATUS \"Stripping (${flag}): ${_installed}\")
      execute_process(COMMAND \"${CMAKE_STRIP}\" ${flag} \"${_installed}\" RESULT_VARIABLE _segvoronoi_strip)
      if(NOT _segvoronoi_strip EQUAL 0)
        message(FATAL_ERROR \"${CMAKE_STRIP} ${flag} ${_installed} failed\")
      endif()
    endif()" COMPONENT ${component})
endfunction()
_segvoronoi_install_strip(Runtime --strip-unneeded "${SEGVORONOI_SHARED_FILE}" "${CMAKE_INSTALL_LIBDIR}")
_segvoronoi_install_strip(Development --strip-debug "${SEGVORONOI_STATIC_FILE}" "${CMAKE_INSTALL_LIBDIR}")
if(SEGVORONOI_INSTALL_CLI)
  _segvoronoi_install_strip(Cli --strip-unneeded "${SEGVORONOI_CLI_FILE}" "${CMAKE_INSTALL_BINDIR}")
endif()

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
        DESTINATION "${SEGVORONOI_CMAKE_DIR}" COMPONENT Development)

# pkg-config: the prefix is found from the .pc file's own location.
set(_segvoronoi_pc_dir "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH SEGVORONOI_PC_TO_PREFIX "/prefix/${_segvoronoi_pc_dir}" "/prefix")
string(REGEX REPLACE "/$" "" SEGVORONOI_PC_TO_PREFIX "${SEGVORONOI_PC_TO_PREFIX}")
list(TRANSFORM SEGVORONOI_STATIC_SYSTEM_LIBS PREPEND "-l" OUTPUT_VARIABLE _segvoronoi_pc_libs)
list(JOIN _segvoronoi_pc_libs " " SEGVORONOI_PC_LIBS_PRIVATE)
configure_file("${CMAKE_CURRENT_LIST_DIR}/segvoronoi.pc.in" "${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.pc" @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.pc" DESTINATION "${_segvoronoi_pc_dir}" COMPONENT Development)
