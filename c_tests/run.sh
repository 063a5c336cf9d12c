#!/usr/bin/env bash
# Builds and installs segvoronoi's CMake package into a temporary prefix, then
# builds c_tests/ as a downstream project through find_package() and runs
# ctest (C API tests shared/static/ASan/valgrind, C++ header check, CGAL
# cross-check), and finally compiles a program through pkg-config.
#
#   bash c_tests/run.sh            # everything
#   CTEST_ARGS="-LE cgal" bash c_tests/run.sh   # without the CGAL cross-check
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-c-tests.XXXXXX")"
trap 'rm -rf "$work"' EXIT
jobs="$(nproc 2>/dev/null || echo 2)"
prefix="$work/prefix"

echo "--- package: configure, build, install into $prefix"
cmake -S "$repo" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j "$jobs"
cmake --install "$work/build" --prefix "$prefix" >/dev/null
# The package must not point back into the build or source tree.
if grep -rqs -e "$work/build" -e "$repo" "$prefix"; then
  echo "installed files refer to the build or source tree:" >&2
  grep -rls -e "$work/build" -e "$repo" "$prefix" >&2
  exit 1
fi
soname="$(readelf -d "$prefix"/lib*/libsegvoronoi.so | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')"
[ -n "$soname" ] && [ -e "$(dirname "$(ls "$prefix"/lib*/libsegvoronoi.so)")/$soname" ] \
  || { echo "installed libsegvoronoi.so has no SONAME or its link is missing" >&2; exit 1; }
echo "SONAME $soname"

# Moving the prefix must not break anything: every path is relative.
mv "$prefix" "$work/moved"
prefix="$work/moved"

echo "--- downstream: c_tests, copied out of the repository, through find_package(segvoronoi)"
mkdir "$work/consumer"
cp "$repo"/c_tests/*.c "$repo"/c_tests/*.cpp "$repo"/c_tests/*.hpp "$repo"/c_tests/*.cmake "$repo"/c_tests/CMakeLists.txt "$work/consumer/"
cp -r "$repo"/c_tests/fixtures "$work/consumer/"
# The cross-check's input generator is built from the source tree (cargo),
# and its real inputs (tests/data/gshhg_*.txt) are read from there.
cmake -S "$work/consumer" -B "$work/c_tests" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DSEGVORONOI_TESTGEN_SOURCE="$repo/testgen" -DSEGVORONOI_REAL_DATA="$repo/tests/data" >"$work/c_configure.log" || { cat "$work/c_configure.log"; exit 1; }
grep -E "using segvoronoi|WARNING|skipped" "$work/c_configure.log" || true
cmake --build "$work/c_tests" -j "$jobs"
# shellcheck disable=SC2086
ctest --test-dir "$work/c_tests" --output-on-failure -j "$jobs" ${CTEST_ARGS:-}
echo "--- CGAL cross-check: agreement per input (from the ctest log)"
grep -h "^family=" "$work/c_tests/Testing/Temporary/LastTest.log" | sort || echo "(no CGAL runs)"

echo "--- downstream: pkg-config, shared and static"
export PKG_CONFIG_PATH="$(dirname "$(ls -d "$prefix"/lib*/pkgconfig/segvoronoi.pc)")"
pkg-config --exists --print-errors "segvoronoi = $(sed -n 's/^version = "\(.*\)"/\1/p' "$repo/Cargo.toml" | head -n1)"
# shellcheck disable=SC2046
cc -std=c99 -Wall -Wextra -Werror -o "$work/pc_shared" "$work/consumer/test_c_api.c" \
  $(pkg-config --cflags --libs segvoronoi) -lm
LD_LIBRARY_PATH="$(pkg-config --variable=libdir segvoronoi)" "$work/pc_shared"
# shellcheck disable=SC2046
cc -std=c99 -Wall -Wextra -Werror -o "$work/pc_static" "$work/consumer/test_c_api.c" \
  $(pkg-config --cflags segvoronoi) "$(pkg-config --variable=libdir segvoronoi)/libsegvoronoi.a" \
  $(pkg-config --libs-only-l --static segvoronoi | sed 's/-lsegvoronoi//') -lm
"$work/pc_static"
echo "--- c_tests: all passed"
