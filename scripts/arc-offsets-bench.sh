#!/usr/bin/env bash
# The curved-part offsets benchmark of BENCHMARKS.md (issue 32): a sheet of
# parts bounded by lines and arcs (10k arcs), offset at 100 distances by
# segvoronoi on the arcs, and as 16-chord polygons by segvoronoi, GEOS's
# buffer and Clipper's offset, in one run; times and output sizes (pieces,
# arcs, vertices, G-code lines), printed as markdown on standard output.
#
#   bash scripts/arc-offsets-bench.sh                 # the table as published
#   bash scripts/arc-offsets-bench.sh --arcs 2000 --runs 1
#
# GEOS and Clipper are compiled in when libgeos-dev and libpolyclipping-dev
# are there (bench/build.rs). Installs nothing; not run by CI.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
(cd "$repo/bench" && cargo build --release --quiet --bin arc_offsets) >&2
"$repo/bench/target/release/arc_offsets" "$@"
