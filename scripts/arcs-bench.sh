#!/usr/bin/env bash
# The circular-arc benchmark of BENCHMARKS.md (issue 31): three families of
# 100k arcs (rounded polygons, tangent chains, random arcs), each built by
# segvoronoi as arcs, as one chord an arc (the time per arc against the
# time per segment), and as 16-chord polylines through segvoronoi,
# Boost.Polygon (C++) and CGAL; then random arcs at 1k, 10k and 100k (the
# seed paper's experiment with arcs). One run, printed as markdown on
# standard output (progress on standard error). About 40 minutes on a
# 2-core machine at 100k arcs, nearly all of it CGAL on the 1.7M chords.
#
#   bash scripts/arcs-bench.sh                       # the table as published
#   bash scripts/arcs-bench.sh --arcs 10000          # 10k arcs a family
#   bash scripts/arcs-bench.sh --peers segvoronoi    # no Boost, no CGAL rows
#   bash scripts/arcs-bench.sh --runs 5 --only random --no-scaling
#
# Arguments go to the `arcs` program (bench/src/bin/arcs.rs, which documents
# each family). Boost.Polygon and CGAL are compiled in when their Debian
# packages are there (libboost-dev; libcgal-dev with libgmp-dev and
# libmpfr-dev); a missing one's rows say "not built". Installs nothing; not
# run by CI.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
(cd "$repo/bench" && cargo build --release --quiet --bin arcs) >&2
cd "$repo"
"$repo/bench/target/release/arcs" "$@"
