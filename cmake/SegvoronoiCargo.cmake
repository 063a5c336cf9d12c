# Builds the C API crate (capi/, package segvoronoi-capi) with cargo and
# defines the build-tree targets segvoronoi::segvoronoi (shared) and
# segvoronoi::segvoronoi_static. cargo names its staticlib after the crate's
# lib, libsegvoronoi_capi.a; the files here are libsegvoronoi.a and
# libsegvoronoi.so, as installed.
#
# Sets for SegvoronoiInstall.cmake:
#   SEGVORONOI_SOVERSION          ABI version in the SONAME (see capi/build.rs)
#   SEGVORONOI_SHARED_FILE        versioned shared library in the build tree
#   SEGVORONOI_SONAME_LINK        its SONAME link, libsegvoronoi.so.SOVERSION
#   SEGVORONOI_DEV_LINK           the unversioned link libsegvoronoi.so
#   SEGVORONOI_STATIC_FILE        static library in the build tree
#   SEGVORONOI_CLI_FILE           the segvoronoi program (SEGVORONOI_INSTALL_CLI)
#   SEGVORONOI_STATIC_SYSTEM_LIBS system libraries a program linking the
#                                 static library names (rustc's list less gcc_s)

find_program(SEGVORONOI_CARGO cargo HINTS "$ENV{CARGO_HOME}/bin" "$ENV{HOME}/.cargo/bin" REQUIRED)
find_program(SEGVORONOI_RUSTC rustc HINTS "$ENV{CARGO_HOME}/bin" "$ENV{HOME}/.cargo/bin" REQUIRED)

# Same rule as capi/build.rs: before 1.0 every minor release may break the ABI.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(SEGVORONOI_SOVERSION "0.${PROJECT_VERSION_MINOR}")
else()
  set(SEGVORONOI_SOVERSION "${PROJECT_VERSION_MAJOR}")
endif()

# Debug builds use cargo's dev profile; everything else the release profile.
if(CMAKE_BUILD_TYPE STREQUAL "Debug")
  set(_segvoronoi_profile_flag "")
  set(_segvoronoi_profile_dir debug)
else()
  set(_segvoronoi_profile_flag --release)
  set(_segvoronoi_profile_dir release)
endif()

# cargo's target directory: inside the build tree, unless CARGO_TARGET_DIR is
# set (as cargo itself does) or SEGVORONOI_CARGO_TARGET_DIR is given. Sharing
# one lets two build trees, or a build tree and `cargo build --release`,
# reuse each other's compilation (scripts/test-all.sh relies on it).
if(DEFINED ENV{CARGO_TARGET_DIR} AND NOT "$ENV{CARGO_TARGET_DIR}" STREQUAL "")
  set(_segvoronoi_cargo_dir_default "$ENV{CARGO_TARGET_DIR}")
else()
  set(_segvoronoi_cargo_dir_default "${CMAKE_CURRENT_BINARY_DIR}/cargo")
endif()
set(SEGVORONOI_CARGO_TARGET_DIR "${_segvoronoi_cargo_dir_default}" CACHE PATH
    "cargo's --target-dir for the segvoronoi build")
get_filename_component(_segvoronoi_cargo_dir "${SEGVORONOI_CARGO_TARGET_DIR}" ABSOLUTE
                       BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
set(_segvoronoi_out "${_segvoronoi_cargo_dir}/${_segvoronoi_profile_dir}")
set(SEGVORONOI_SHARED_FILE "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.so.${PROJECT_VERSION}")
set(SEGVORONOI_SONAME_LINK "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.so.${SEGVORONOI_SOVERSION}")
set(SEGVORONOI_DEV_LINK "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.so")
set(SEGVORONOI_STATIC_FILE "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.a")

# What a static link of a Rust library needs from the system, as rustc itself
# reports it for this toolchain and target (an empty staticlib has the same
# needs as ours: we depend on std and libc only).
set(_segvoronoi_probe "${CMAKE_CURRENT_BINARY_DIR}/native_libs_probe.rs")
file(WRITE "${_segvoronoi_probe}" "")
execute_process(
  COMMAND "${SEGVORONOI_RUSTC}" --crate-type staticlib --crate-name native_libs_probe
          --print native-static-libs -o "${CMAKE_CURRENT_BINARY_DIR}/libnative_libs_probe.a" "${_segvoronoi_probe}"
  RESULT_VARIABLE _segvoronoi_probe_result
  OUTPUT_VARIABLE _segvoronoi_probe_out
  ERROR_VARIABLE _segvoronoi_probe_out)
string(REGEX MATCH "native-static-libs: ([^\n]*)" _segvoronoi_native_line "${_segvoronoi_probe_out}")
if(NOT _segvoronoi_probe_result EQUAL 0 OR NOT CMAKE_MATCH_1)
  message(FATAL_ERROR "could not ask rustc which system libraries a static link needs:\n${_segvoronoi_probe_out}")
endif()
separate_arguments(_segvoronoi_native_flags UNIX_COMMAND "${CMAKE_MATCH_1}")
set(_segvoronoi_rustc_system_libs "")
foreach(_flag IN LISTS _segvoronoi_native_flags)
  string(REGEX REPLACE "^-l" "" _lib "${_flag}")
  list(APPEND _segvoronoi_rustc_system_libs "${_lib}")
endforeach()
list(REMOVE_DUPLICATES _segvoronoi_rustc_system_libs)
# What a program linking libsegvoronoi.a names (the static target's link
# interface, Libs.private of segvoronoi.pc): the same less gcc_s. Its unwinder
# (Rust's std unwinds panics to the C API's boundary) comes with the C
# compiler driver: gcc and clang link libgcc_s as needed into a dynamic
# program and libgcc_eh, its static twin, into a `-static` one, where an
# explicit -lgcc_s fails (there is no libgcc_s.a). The shared library below
# is linked with rustc's whole list.
set(SEGVORONOI_STATIC_SYSTEM_LIBS ${_segvoronoi_rustc_system_libs})
list(REMOVE_ITEM SEGVORONOI_STATIC_SYSTEM_LIBS gcc_s)
message(STATUS "segvoronoi: a static link needs ${SEGVORONOI_STATIC_SYSTEM_LIBS}")

# The shared library is linked here from the static one, not copied from
# cargo's cdylib: rustc gives the linker a version script of its own (all
# exports in the base version), and GNU ld and lld take the first script for a
# symbol, so a second one from build.rs cannot version the C API (GNU ld even
# refuses to combine them). Linking the whole staticlib with our script
# (cmake/segvoronoi.map.in) gives every segvoronoi_* function the version
# node SEGVORONOI_<SOVERSION> and keeps everything else local; --gc-sections
# drops what no export reaches. c_tests/symbols.cmake checks the result.
configure_file("${CMAKE_CURRENT_LIST_DIR}/segvoronoi.map.in" "${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.map" @ONLY)
set(_segvoronoi_system_link_flags "")
foreach(_lib IN LISTS _segvoronoi_rustc_system_libs)
  list(APPEND _segvoronoi_system_link_flags "-l${_lib}")
endforeach()

# cargo decides itself what is out of date, so it runs on every build; the
# copies keep the installed names stable whatever cargo's layout.
add_custom_target(segvoronoi_cargo ALL
  COMMAND "${SEGVORONOI_CARGO}" build --lib --locked ${_segvoronoi_profile_flag}
          --manifest-path "${PROJECT_SOURCE_DIR}/capi/Cargo.toml"
          --target-dir "${_segvoronoi_cargo_dir}"
  COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_CURRENT_BINARY_DIR}/lib"
  COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${_segvoronoi_out}/libsegvoronoi_capi.a" "${SEGVORONOI_STATIC_FILE}"
  COMMAND "${CMAKE_C_COMPILER}" -shared -o "${SEGVORONOI_SHARED_FILE}"
          -Wl,--whole-archive "${SEGVORONOI_STATIC_FILE}" -Wl,--no-whole-archive
          "-Wl,--version-script=${CMAKE_CURRENT_BINARY_DIR}/segvoronoi.map"
          "-Wl,-soname,libsegvoronoi.so.${SEGVORONOI_SOVERSION}" -Wl,--gc-sections -Wl,-z,defs
          ${_segvoronoi_system_link_flags}
  COMMAND "${CMAKE_COMMAND}" -E create_symlink "libsegvoronoi.so.${PROJECT_VERSION}"
          "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.so.${SEGVORONOI_SOVERSION}"
  COMMAND "${CMAKE_COMMAND}" -E create_symlink "libsegvoronoi.so.${SEGVORONOI_SOVERSION}"
          "${CMAKE_CURRENT_BINARY_DIR}/lib/libsegvoronoi.so"
  BYPRODUCTS ${SEGVORONOI_SHARED_FILE} ${SEGVORONOI_SONAME_LINK} ${SEGVORONOI_DEV_LINK} ${SEGVORONOI_STATIC_FILE}
  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
  COMMENT "cargo build segvoronoi (${_segvoronoi_profile_dir})"
  USES_TERMINAL
  VERBATIM)

# Build-tree targets, for add_subdirectory() and FetchContent users.
add_library(segvoronoi_shared SHARED IMPORTED GLOBAL)
set_target_properties(segvoronoi_shared PROPERTIES
  IMPORTED_LOCATION "${SEGVORONOI_SHARED_FILE}"
  IMPORTED_SONAME "libsegvoronoi.so.${SEGVORONOI_SOVERSION}"
  INTERFACE_INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}/capi/include")
add_dependencies(segvoronoi_shared segvoronoi_cargo)
add_library(segvoronoi::segvoronoi ALIAS segvoronoi_shared)

add_library(segvoronoi_static STATIC IMPORTED GLOBAL)
set_target_properties(segvoronoi_static PROPERTIES
  IMPORTED_LOCATION "${SEGVORONOI_STATIC_FILE}"
  IMPORTED_LINK_INTERFACE_LANGUAGES C
  INTERFACE_LINK_LIBRARIES "${SEGVORONOI_STATIC_SYSTEM_LIBS}"
  INTERFACE_INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}/capi/include")
add_dependencies(segvoronoi_static segvoronoi_cargo)
add_library(segvoronoi::segvoronoi_static ALIAS segvoronoi_static)

# The segvoronoi program (cli/, package segvoronoi-cli), when asked for: the
# same cargo, profile and target directory, in a cargo run of its own, so that
# the C library is the same with or without it (one run would unify the
# features of their dependencies). After the library's build, so that the two
# runs do not wait on each other's lock of the target directory.
if(SEGVORONOI_INSTALL_CLI)
  set(SEGVORONOI_CLI_FILE "${CMAKE_CURRENT_BINARY_DIR}/bin/segvoronoi")
  add_custom_target(segvoronoi_cli ALL
    COMMAND "${SEGVORONOI_CARGO}" build --bin segvoronoi --locked ${_segvoronoi_profile_flag}
            --manifest-path "${PROJECT_SOURCE_DIR}/cli/Cargo.toml"
            --target-dir "${_segvoronoi_cargo_dir}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_CURRENT_BINARY_DIR}/bin"
    COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${_segvoronoi_out}/segvoronoi" "${SEGVORONOI_CLI_FILE}"
    BYPRODUCTS ${SEGVORONOI_CLI_FILE}
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    COMMENT "cargo build segvoronoi-cli (${_segvoronoi_profile_dir})"
    USES_TERMINAL
    VERBATIM)
  add_dependencies(segvoronoi_cli segvoronoi_cargo)
endif()
