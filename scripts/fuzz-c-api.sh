#!/usr/bin/env bash
# The longer campaigns of c_tests/fuzz_c_api.c (the random driver through the
# C API) and c_tests/tsan_readers.c (concurrent readers), against the CMake
# package installed into a temporary prefix, as a downstream user builds.
# ctest runs both briefly (c_api_fuzz_asan, c_api_readers_*); this script is
# for the 100,000-case runs and for a ThreadSanitizer run with the Rust side
# instrumented too.
#
#   bash scripts/fuzz-c-api.sh                       # 100,000 cases, release, no sanitizer
#   bash scripts/fuzz-c-api.sh --asan -- --seconds 600 --allow-known
#   bash scripts/fuzz-c-api.sh -- --case 0x910a2dec89025cc1   # one case again
#   bash scripts/fuzz-c-api.sh --tsan-rust           # readers, library built with -Zsanitizer=thread (nightly)
#
# Options: --asan (driver under AddressSanitizer, UBSan and LeakSanitizer),
# --tsan-rust, --prefix DIR (use an installed package instead of building
# one); the arguments after -- go to the driver (default: --seed 1
# --iterations 100000). CARGO_TARGET_DIR is honoured.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
mode=plain
prefix=""
while [ $# -gt 0 ]; do
  case "$1" in
    --asan) mode=asan ;;
    --tsan-rust) mode=tsan-rust ;;
    --prefix) prefix="$2"; shift ;;
    --) shift; break ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
driver_args=("$@")
[ ${#driver_args[@]} -gt 0 ] || [ "$mode" = tsan-rust ] || driver_args=(--seed 1 --iterations 100000)

work="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-fuzz.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cc="${CC:-cc}"
strict=(-std=c99 -Wall -Wextra -Werror -pedantic -g)

if [ "$mode" = tsan-rust ]; then
  # The library itself instrumented. Without the rust-src component std is
  # not rebuilt, so std's own synchronisation is not seen (hence the ABI
  # override); the crate's code, its dependencies and the C side are.
  rustup toolchain list | grep -q '^nightly' || { echo "no nightly toolchain: nothing to do" >&2; exit 0; }
  target="${CARGO_TARGET_DIR:-$repo/target}/tsan"
  RUSTFLAGS="-Zsanitizer=thread -Cunsafe-allow-abi-mismatch=sanitizer" \
    cargo +nightly build --quiet --lib --release --locked --target x86_64-unknown-linux-gnu \
    --manifest-path "$repo/capi/Cargo.toml" --target-dir "$target"
  # gcc's libtsan lacks symbols rustc's instrumentation calls (__tsan_memcpy):
  # link the C side against rustc's own TSan runtime instead.
  lib="$work/lib"
  mkdir -p "$lib"
  cp "$target/x86_64-unknown-linux-gnu/release/libsegvoronoi_capi.so" "$lib/libsegvoronoi.so"
  soname="$(readelf -d "$lib/libsegvoronoi.so" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')"
  [ -z "$soname" ] || ln -sf libsegvoronoi.so "$lib/$soname"
  rt="$(rustc +nightly --print sysroot)/lib/rustlib/x86_64-unknown-linux-gnu/lib/librustc-nightly_rt.tsan.a"
  "$cc" "${strict[@]}" -O1 -fsanitize=thread -I"$repo/capi/include" -c "$repo/c_tests/tsan_readers.c" -o "$work/tsan_readers.o"
  "$cc" "$work/tsan_readers.o" -o "$work/tsan_readers" -Wl,--whole-archive "$rt" -Wl,--no-whole-archive \
    -L"$lib" -lsegvoronoi -lm -pthread -ldl -lstdc++ -Wl,-rpath,"$lib"
  TSAN_OPTIONS="halt_on_error=1:exitcode=66 ${TSAN_OPTIONS:-}" "$work/tsan_readers" "${driver_args[@]}"
  exit
fi

if [ -z "$prefix" ]; then
  prefix="$work/prefix"
  cmake -S "$repo" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" || { cat "$work/configure.log"; exit 1; }
  cmake --build "$work/build" >"$work/build.log" || { cat "$work/build.log"; exit 1; }
  cmake --install "$work/build" --prefix "$prefix" >/dev/null
fi
libdir="$(dirname "$(ls "$prefix"/lib*/libsegvoronoi.so | head -n1)")"

case "$mode" in
  plain) flags=(-O2) env=() ;;
  asan)  flags=(-O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
         env=(ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1") ;;
esac
"$cc" "${strict[@]}" "${flags[@]}" -I"$prefix/include" "$repo/c_tests/fuzz_c_api.c" -o "$work/fuzz_c_api" \
  -L"$libdir" -lsegvoronoi -lm -Wl,-rpath,"$libdir"
echo "--- fuzz_c_api ($mode) ${driver_args[*]}"
env "${env[@]}" "$work/fuzz_c_api" "${driver_args[@]}"
