#!/usr/bin/env bash
# Builds and runs examples/c, the README's C quick start, as an outside project
# would: with CMake through find_package(segvoronoi) (shared, static and fully
# static) and with make through pkg-config (shared and `cc -static`). On the
# way it checks the install itself: `cmake --install --strip` strips both
# libraries, the Runtime component alone (the versioned library and its SONAME
# link) runs a program linked against the shared library, and with
# -DSEGVORONOI_INSTALL_CLI=ON the program bin/segvoronoi (component Cli) reads
# every file of examples/data.
#
#   bash scripts/test-c-examples.sh
#
# The package is built in a temporary tree. With CARGO_TARGET_DIR set, cargo
# works in that directory; scripts/test-all.sh shares one with c_tests/run.sh,
# so cargo has nothing left to compile and this takes seconds.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-c-examples.XXXXXX")"
trap 'rm -rf "$work"' EXIT
jobs="$(nproc 2>/dev/null || echo 2)"
strict="-Wall -Wextra -pedantic -Werror"
fail() { echo "test-c-examples: $*" >&2; exit 1; }

echo "--- the README's C quick start is examples/c/quickstart.c, docs/c-api.md's examples are medial_axis.c and offsets.c"
awk '/^## C quick start/ { s = 1 } s && /^```c$/ { c = 1; next } c && /^```$/ { exit } c' "$repo/README.md" \
  >"$work/readme_quickstart.c"
diff -u "$work/readme_quickstart.c" "$repo/examples/c/quickstart.c" \
  || fail "the C block under '## C quick start' in README.md and examples/c/quickstart.c differ"
awk '/^### The medial axis in C/ { s = 1 } s && /^```c$/ { c = 1; next } c && /^```$/ { exit } c' "$repo/docs/c-api.md" \
  >"$work/readme_medial_axis.c"
diff -u "$work/readme_medial_axis.c" "$repo/examples/c/medial_axis.c" \
  || fail "the C block under '### The medial axis in C' in docs/c-api.md and examples/c/medial_axis.c differ"
awk '/^### Offsets in C/ { s = 1 } s && /^```c$/ { c = 1; next } c && /^```$/ { exit } c' "$repo/docs/c-api.md" \
  >"$work/readme_offsets.c"
diff -u "$work/readme_offsets.c" "$repo/examples/c/offsets.c" \
  || fail "the C block under '### Offsets in C' in docs/c-api.md and examples/c/offsets.c differ"

echo "--- package with the program: configure, build, install with --strip, the Runtime and Cli components alone"
cmake -S "$repo" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DSEGVORONOI_INSTALL_CLI=ON >"$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j "$jobs" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
cmake --install "$work/build" --prefix "$work/prefix" --strip >/dev/null
cmake --install "$work/build" --prefix "$work/runtime" --component Runtime >/dev/null
cmake --install "$work/build" --prefix "$work/cli" --component Cli >/dev/null

libdir="$(dirname "$(ls "$work"/prefix/lib*/libsegvoronoi.so)")"
shared="$(ls "$libdir"/libsegvoronoi.so.*.*.*)"
soname="$(readelf -d "$shared" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')"
# Stripped: no static symbol table left in the shared library (its exports
# are in .dynsym), no debug sections in the static one (its symbols stay).
# (Listings go to files first: grep -q would end a pipe early, and pipefail.
# readelf rather than nm, whose LLVM plugin chokes on the embedded bitcode.)
readelf -S "$shared" >"$work/shared_sections.txt"
objdump -h "$libdir/libsegvoronoi.a" >"$work/static_sections.txt"
readelf -sW "$libdir/libsegvoronoi.a" >"$work/static_symbols.txt"
! grep -q '\.symtab' "$work/shared_sections.txt" || fail "$shared is not stripped"
! grep -q ' \.debug_' "$work/static_sections.txt" || fail "libsegvoronoi.a still has debug sections"
grep -q 'FUNC *GLOBAL .* segvoronoi_builder_new$' "$work/static_symbols.txt" || fail "libsegvoronoi.a lost its symbol table"
# Runtime is the versioned library and its SONAME link, nothing for development.
runtime_files="$(cd "$work/runtime" && find . ! -type d -printf '%f\n' | sort | tr '\n' ' ')"
expected_runtime="$(printf '%s\n' "$(basename "$shared")" "$soname" | sort | tr '\n' ' ')"
[ "$runtime_files" = "$expected_runtime" ] \
  || fail "the Runtime component holds '$runtime_files', expected '$expected_runtime'"
echo "stripped; Runtime component: $runtime_files"

echo "--- bin/segvoronoi: stripped, alone in the Cli component, reads every file of examples/data"
program="$work/prefix/bin/segvoronoi"
readelf -S "$program" >"$work/program_sections.txt"
! grep -q '\.symtab' "$work/program_sections.txt" || fail "$program is not stripped"
cli_files="$(cd "$work/cli" && find . ! -type d | sort | tr '\n' ' ')"
[ "$cli_files" = "./bin/segvoronoi " ] || fail "the Cli component holds '$cli_files', expected './bin/segvoronoi '"
"$program" --version | grep -qx "segvoronoi $(sed -n 's/^version = "\(.*\)"/\1/p' "$repo/Cargo.toml" | head -n1)" \
  || fail "segvoronoi --version: $("$program" --version)"
mkdir "$work/cli-out"
for input in "$repo"/examples/data/*; do
  name="$(basename "$input")"
  case "$name" in README.md) continue ;; esac
  out="$work/cli-out/$name"
  "$program" "$input" --stats --medial-axis "$out.axis.geojson" --offset -1 --offsets "$out.offsets.wkt" --svg "$out.svg" \
    2>"$out.stats" || { cat "$out.stats" >&2; fail "segvoronoi $name failed"; }
  grep -q '^segment_sites=[1-9]' "$out.stats" || fail "segvoronoi $name: no segment sites in --stats"
  grep -q '"MultiLineString"' "$out.axis.geojson" || fail "segvoronoi $name: no GeoJSON medial axis"
  tail -c 16 "$out.svg" | grep -q '</svg>' || fail "segvoronoi $name: the SVG is not complete"
done
echo "segvoronoi read $(ls "$work/cli-out"/*.svg | wc -l) files of examples/data"

mkdir "$work/example"
cp "$repo"/examples/c/{quickstart.c,medial_axis.c,offsets.c,CMakeLists.txt,Makefile} "$work/example/"

echo "--- examples/c through CMake: find_package(segvoronoi), shared and static"
cmake -S "$work/example" -B "$work/example-cmake" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_C_FLAGS="$strict" >"$work/example-configure.log" 2>&1 \
  || { cat "$work/example-configure.log"; exit 1; }
cmake --build "$work/example-cmake" -j "$jobs" >"$work/example-build.log" 2>&1 \
  || { cat "$work/example-build.log"; exit 1; }
"$work/example-cmake/quickstart" >"$work/out_cmake_shared.txt"
"$work/example-cmake/quickstart_static" >"$work/out_cmake_static.txt"
[ -x "$work/example-cmake/quickstart_fully_static" ] || fail "examples/c found no static libc: quickstart_fully_static not built"
"$work/example-cmake/quickstart_fully_static" >"$work/out_cmake_fully_static.txt"

echo "--- examples/c through make and pkg-config, shared and fully static (cc -static)"
make -s -C "$work/example" PKG_CONFIG_PATH="$libdir/pkgconfig" CFLAGS="-O2 $strict" >/dev/null
"$work/example/quickstart" >"$work/out_pkg_config.txt" # found through its RUNPATH
make -s -C "$work/example" PKG_CONFIG_PATH="$libdir/pkgconfig" CFLAGS="-O2 $strict" quickstart-static \
  >"$work/static-link.log" 2>&1 || { cat "$work/static-link.log"; fail "cc -static through pkg-config --static failed"; }
"$work/example/quickstart-static" >"$work/out_pkg_config_fully_static.txt"
for program in "$work/example/quickstart-static" "$work/example-cmake/quickstart_fully_static"; do
  readelf -lW "$program" >"$work/program_headers.txt"
  ! grep -q 'INTERP\|DYNAMIC' "$work/program_headers.txt" || fail "$program is not fully static"
done

# The three circumcentres of the four points, whatever their numbering.
cat >"$work/expected.txt" <<'EOF'
(-0.2, 1.35) r=1.36473
(1, -0.364286) r=1.06429
(2.2, 1.35) r=1.36473
EOF
for out in "$work"/out_*.txt; do
  sed 's/^vertex [0-9]*: //' "$out" | sort | diff -u "$work/expected.txt" - \
    || fail "$(basename "$out" .txt): unexpected output"
done
# A 4 x 2 rectangle: a disk of radius 1, five pieces, the middle line pruned.
printf 'largest disk: r=1\nmedial axis: 5 pieces\npruned: 1 pieces\n' >"$work/expected_medial_axis.txt"
"$work/example-cmake/medial_axis" | diff -u "$work/expected_medial_axis.txt" - \
  || fail "examples/c/medial_axis: unexpected output"
# The 10 x 10 square with a 2 x 2 hole: shrunk by 1, the 8 x 8 square less the
# hole grown by 1 (64 - (4 + 8 + pi)); by 2, four corners (4 x (4 - pi)), apart
# although the hole grown by 2 touches the shrunk square along its sides;
# grown by 1, the hole gone (100 + 40 + pi).
cat >"$work/expected_offsets.txt" <<'EOF'
d=-1: 2 loops, area 48.8584
  loop 0: outer, 4 pieces (0 arcs), area 64.0000, polyline area 64.0
  loop 1: hole, 8 pieces (4 arcs), area -15.1416, polyline area -15.1
d=-2: 4 loops, area 3.4336
  loop 0: outer, 3 pieces (1 arcs), area 0.8584, polyline area 0.9
  loop 1: outer, 3 pieces (1 arcs), area 0.8584, polyline area 0.9
  loop 2: outer, 3 pieces (1 arcs), area 0.8584, polyline area 0.9
  loop 3: outer, 3 pieces (1 arcs), area 0.8584, polyline area 0.9
d=1: 1 loops, area 143.1416
  loop 0: outer, 8 pieces (4 arcs), area 143.1416, polyline area 143.1
EOF
"$work/example-cmake/offsets" | diff -u "$work/expected_offsets.txt" - \
  || fail "examples/c/offsets: unexpected output"

echo "--- the programs linked against the shared library, with only the Runtime component"
mv "$work/prefix" "$work/prefix-gone"
runtime_libdir="$(dirname "$(ls "$work"/runtime/lib*/"$soname")")"
for program in "$work/example-cmake/quickstart" "$work/example/quickstart"; do
  LD_LIBRARY_PATH="$runtime_libdir" "$program" | cmp -s - "$work/out_cmake_shared.txt" \
    || fail "$program does not run against the Runtime component alone"
done
echo "--- examples/c: all passed (CMake shared, static and fully static, pkg-config shared and fully static, Runtime component, the program)"
