#!/usr/bin/env bash
# The builds on two threads under ThreadSanitizer (issue 33): the library's
# unit tests of its threads (and of splitting on two threads), and the
# integration tests of `threads.rs`
# (builds in halves on every family, the same diagram at every thread
# count), compiled with -Zsanitizer=thread and an instrumented standard
# library. Needs the nightly toolchain with rust-src:
#   rustup toolchain install nightly --component rust-src
# Not run by CI (the nightly toolchain is not on a new machine; about 10
# minutes on 2 cores). Exit status: the tests' (a race fails them).
set -euo pipefail
cd "$(dirname "$0")/.."
target="$(rustc -vV | sed -n 's/^host: //p')"
export RUSTFLAGS="-Zsanitizer=thread"
export RUSTDOCFLAGS="-Zsanitizer=thread"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target/tsan}"
cargo +nightly test -Zbuild-std --target "$target" --release --lib -- threads halves glue seam splitting_on_two_threads
cargo +nightly test -Zbuild-std --target "$target" --release -p segvoronoi-integration-tests --test threads -- "$@"
