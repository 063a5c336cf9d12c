#!/usr/bin/env bash
# Builds the Python package (python/: PyO3 through maturin) into a fresh
# virtual environment exactly as a user would, `pip install ./python`, and
# runs its tests: pytest over python/tests (against shapely/GEOS, the
# README's examples, the Dask example on a local two-worker cluster) and
# the doctests of the installed package. Needs the Rust toolchain and
# Python 3.9+; installs python3-venv and fonts-dejavu-core with apt-get
# when missing. pip fetches maturin, numpy, shapely, pytest, fonttools,
# geopandas and dask from PyPI. SEGVORONOI_PY_MINIMAL=1 skips geopandas
# and dask (their tests are then skipped).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
python="${PYTHON:-python3}"

# python3-venv (Debian splits it out) and fonts-dejavu-core (the letters
# of tests/test_curved_fonts.py), where missing
need=()
"$python" -c "import venv, ensurepip" >/dev/null 2>&1 || need+=(python3-venv)
[ -e /usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf ] || need+=(fonts-dejavu-core)
if [ ${#need[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/segvoronoi-python.XXXXXX")"
trap 'rm -rf "$work"' EXIT
"$python" -m venv "$work/venv"
pip=("$work/venv/bin/python" -m pip --disable-pip-version-check -q)
"${pip[@]}" install --upgrade pip
# the package's own target directory, inside the temporary one: a clean build
CARGO_TARGET_DIR="$work/target" "${pip[@]}" install "$root/python"
"${pip[@]}" install pytest shapely numpy fonttools
if [ "${SEGVORONOI_PY_MINIMAL:-0}" != 1 ]; then
  "${pip[@]}" install geopandas "dask[distributed]"
fi

# From an empty directory, so that `segvoronoi` is the installed package
# and not python/segvoronoi (which has no compiled module).
# the program, for the LibreCAD drawings against GEOS (test_dxf_parts_geos)
cargo build --quiet --release -p segvoronoi-cli
export SEGVORONOI_CLI="$root/target/release/segvoronoi"

mkdir "$work/run"
cd "$work/run"
"$work/venv/bin/python" -m pytest -q -p no:cacheprovider --doctest-modules --pyargs segvoronoi "$root/python/tests"
