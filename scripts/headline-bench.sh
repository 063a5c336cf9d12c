#!/usr/bin/env bash
# The headline table of BENCHMARKS.md and the README: every main workload
# (points, short and long segments, polygons, real coastlines, medial axis,
# offsets, splitting) against every peer that does it (Boost.Polygon's C++
# builder, boostvoronoi, spade, CGAL, GEOS, Clipper), in one run, printed as
# markdown on standard output (progress on standard error). 4 to 8 minutes
# on a 2-core machine, by its load.
#
#   bash scripts/headline-bench.sh                 # the table as published
#   bash scripts/headline-bench.sh --scale 0.05    # 1/20 the sizes (the real data stays whole)
#   bash scripts/headline-bench.sh --runs 5 --only points,offsets
#
# Arguments go to the `headline` program (bench/src/bin/headline.rs, which
# documents each workload). The peers are compiled in when their Debian
# packages are there (libboost-dev, libcgal-dev with libgmp-dev and
# libmpfr-dev, libgeos-dev, libpolyclipping-dev; a missing one's cells say
# "not built"). The real coastlines come from GSHHG through
# scripts/coastlines.py, which needs the gmt-gshhg-low package and Python's
# h5py; without them those two rows are left out, with a note. Installs
# nothing; not run by CI.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-headline.XXXXXX")"
trap 'rm -rf "$work"' EXIT

(cd "$repo/bench" && cargo build --release --quiet --bin headline) >&2
args=()
if python3 -c 'import h5py' 2>/dev/null && [ -f /usr/share/gmt-gshhg/binned_GSHHS_l.nc ]; then
  # the world's coastlines at low resolution; with borders and rivers they cross
  python3 "$repo/scripts/coastlines.py" --res l --layers coast -o "$work/coast.txt" >&2
  python3 "$repo/scripts/coastlines.py" --res l --layers coast,borders,rivers -o "$work/coast-split.txt" >&2
  args+=(--coast "$work/coast.txt" --coast-split "$work/coast-split.txt")
else
  echo "headline-bench: no GSHHG (gmt-gshhg-low) or no h5py: the real-coastline rows are left out" >&2
fi
cd "$repo"
"$repo/bench/target/release/headline" "${args[@]}" "$@"
