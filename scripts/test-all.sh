#!/usr/bin/env bash
# Sets up a fresh Debian/Ubuntu machine (Rust toolchain assumed) and runs every
# test of segvoronoi: cargo tests (unit, property, header, C API through cc,
# doctests), the fault-injection suite, then the CMake package installed into a
# temporary prefix and the downstream C tests and CGAL cross-check under ctest,
# and the C examples (examples/c) built against the installed package.
set -euo pipefail
cd "$(dirname "$0")/.."

step() { printf '\n=== %s ===\n' "$*"; }

need_packages=()
for pkg in cmake g++ pkg-config valgrind libcgal-dev libgmp-dev libmpfr-dev libboost-dev libgeos-dev libpolyclipping-dev librecad-data; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || need_packages+=("$pkg")
done
if [ ${#need_packages[@]} -gt 0 ]; then
  step "installing ${need_packages[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need_packages[@]}" >/dev/null
fi

step "formatting (rustfmt.toml; cargo fmt --check over the workspace, bench/ and python/)"
cargo fmt --version >/dev/null 2>&1 || rustup component add rustfmt
cargo fmt --all -- --check
(cd bench && cargo fmt -- --check)
(cd python && cargo fmt -- --check)

step "cargo test (workspace: library, C API via cc, header, properties, doctests)"
cargo test --workspace --quiet

step "fault injection (predicates perturbed or random; through Rust and through the C API)"
cargo test --quiet --release -p segvoronoi-integration-tests -p segvoronoi-capi --features segvoronoi-integration-tests/fault-injection,segvoronoi-capi/fault-injection --test fault_injection

# The package steps build the library with cargo in one shared target
# directory (CMake honours CARGO_TARGET_DIR), so the second compiles nothing.
package_target="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-package-target.XXXXXX")"
trap 'rm -rf "$package_target"' EXIT

step "CMake package, downstream C tests, CGAL cross-check, 60 s C-API fuzz under ASan/UBSan, readers under TSan and helgrind (ctest)"
CARGO_TARGET_DIR="$package_target" bash c_tests/run.sh

if [ "${SEGVORONOI_TSAN_RUST:-0}" = 1 ]; then
  step "concurrent readers with the library built with -Zsanitizer=thread (nightly)"
  CARGO_TARGET_DIR="$package_target" bash scripts/fuzz-c-api.sh --tsan-rust
fi

step "examples/c: the C quick start through find_package and pkg-config, also fully static; stripped install, Runtime component; the program (SEGVORONOI_INSTALL_CLI)"
CARGO_TARGET_DIR="$package_target" bash scripts/test-c-examples.sh

step "Python package: pip install ./python into a fresh venv, pytest and doctests"
bash scripts/test-python.sh
