#!/usr/bin/env python3
"""Real inputs that cross themselves, from GSHHG: coastlines, national
borders and rivers, for the splitting tests, the CGAL cross-check and the
benchmark (issue 11).

Reads GMT's binned GSHHG files (Debian: gmt-gshhg-low has the crude, low
and intermediate resolutions, gmt-gshhg-high and gmt-gshhg-full the other
two; /usr/share/gmt-gshhg/binned_{GSHHS,border,river}_{c,l,i,h,f}.nc) and
writes the segments of the chosen layers inside a box in Boost.Polygon's
text format (src/boost_text.rs): every polyline cut into its chords.

Each layer is digitised separately (coast from WVS/WDB-II/Atlas of the
Cryosphere, borders and rivers from WDB-II), so combining layers gives real
crossings and overlaps: a border that runs a little past the shore, a
river that crosses the coast at its mouth or follows a border.

The binned format (netCDF-4, i.e. HDF5, read here with h5py; the layout
follows GMT's gmt_shore.c): the world is cut into square bins of
`Bin_size_in_minutes` (10 degrees at c/l, smaller at the higher
resolutions), bin b having its south-west corner at longitude
(b mod nx) * size and latitude 90 - (b div nx + 1) * size. A bin holds
`N_segments_in_a_bin` polylines from `Id_of_first_segment_in_a_bin` on,
each polyline its points from `Id_of_first_point_in_a_segment` on, each
point two 16-bit offsets from the bin's corner (read as unsigned, in units
of size / 65535). A coastline polyline clipped at the bin's sides has its
point count in the bits 9 and up of
`Embedded_npts_levels_exit_entry_for_a_segment`, its level (1 land, 2
lake, 3 island in lake, 4 pond, 5 Antarctic ice front, 6 Antarctic
grounding line) in bits 6-8 and its entry side in bits 3-5 (4: a closed
polygon inside the bin, possibly without its closing point); borders and
rivers store the point count and level in `N_points_for_a_segment` and
`Hierarchial_level_of_a_segment` (borders 1 national, 2 state, 3 marine;
rivers 1-4 permanent, 5-7 intermittent, 8-10 canals).

Coordinates are written in those units, as integers: x = 65535 * (bin
column) + offset, so a point on a bin's side is the same integer in both
bins and the polylines join exactly; longitudes from 180 degrees on are
moved by -360 degrees so that a box may straddle the prime meridian. The
box is rounded out to whole bins (a chord is never clipped). Consecutive
repeated points are dropped; a repeated chord (one polyline drawn twice)
is kept: real data has them and splitting must merge them.

GSHHG is distributed under the LGPL-3 (Debian package copyright: "Copyright
2014, The GMT Team, License: LGPL-3+"), and so are the files made from it.

    python3 scripts/coastlines.py --res l --layers coast,borders --box -10 30 35 60 -o /tmp/europe.txt
    python3 scripts/coastlines.py --fixtures          # rewrites tests/data/gshhg_*.txt
    python3 scripts/coastlines.py --fixtures --check  # compares with them

Needs `pip install h5py` and the gmt-gshhg packages.
"""

import argparse
import os
import sys

import h5py

DATA_DIR = "/usr/share/gmt-gshhg"
OUT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data")
UNITS = 65535  # offsets per bin side
FILE_STEM = {"coast": "GSHHS", "borders": "border", "rivers": "river"}
# Levels kept by default: the shoreline, lakes and islands and the
# Antarctic ice front (not the grounding line as well, which is the same
# coast a second time); national borders; permanent rivers.
DEFAULT_LEVELS = {"coast": {1, 2, 3, 4, 5}, "borders": {1}, "rivers": {1, 2, 3, 4}}

# The committed fixtures: (name, resolution, layers, box west east south north, what it shows).
FIXTURES = [
    ("gshhg_coast_c_europe", "c", "coast", (-10, 30, 30, 60), "the crude coastline of Europe alone"),
    (
        "gshhg_coast_borders_c_europe",
        "c",
        "coast,borders",
        (-10, 30, 30, 60),
        "crude coast and national borders of Europe: borders cross and touch the coast",
    ),
    (
        "gshhg_coast_rivers_l_westeurope",
        "l",
        "coast,rivers",
        (-10, 10, 40, 50),
        "low-resolution coast and permanent rivers of western Europe: rivers cross the coast at their mouths",
    ),
    (
        "gshhg_all_c_southamerica",
        "c",
        "coast,borders,rivers",
        (-80, -40, -30, -10),
        "crude coast, borders and rivers of South America: all three layers crossing",
    ),
    (
        "gshhg_all_l_centralafrica",
        "l",
        "coast,borders,rivers",
        (20, 30, 5, 15),
        "low-resolution borders and rivers of Chad, Sudan and the Central African Republic: a crossing snapped "
        "inside a straight run of collinear segments (a bent continuation, c_tests/cgal_split.cpp)",
    ),
]


def bins_in_box(nx, ny, size_deg, box):
    """The bins overlapping the box (west, east, south, north), in degrees,
    with longitudes taken in [-180, 180), and the box they cover."""
    west, east, south, north = box
    chosen, covered = [], [180, -180, 90, -90]
    for b in range(nx * ny):
        lon = (b % nx) * size_deg
        if lon >= 180:
            lon -= 360
        lat = 90 - (b // nx + 1) * size_deg
        if lon < east and lon + size_deg > west and lat < north and lat + size_deg > south:
            chosen.append(b)
            covered = [min(covered[0], lon), max(covered[1], lon + size_deg), min(covered[2], lat), max(covered[3], lat + size_deg)]
    return chosen, covered


def polylines(path, layer, box, levels):
    """The polylines of one layer in the box, as lists of integer (x, y),
    the bin size in minutes and the box the bins cover."""
    with h5py.File(path, "r") as f:
        size_minutes = int(f["Bin_size_in_minutes"][0])
        nx = int(f["N_bins_in_360_longitude_range"][0])
        ny = int(f["N_bins_in_180_degree_latitude_range"][0])
        first_seg = f["Id_of_first_segment_in_a_bin"][:]
        n_seg = f["N_segments_in_a_bin"][:]
        first_point = f["Id_of_first_point_in_a_segment"][:]
        # the 16-bit offsets are unsigned (gmt_shore_to_degree)
        dx = f["Relative_longitude_from_SW_corner_of_bin"][:].astype("uint16")
        dy = f["Relative_latitude_from_SW_corner_of_bin"][:].astype("uint16")
        if layer == "coast":
            info = f["Embedded_npts_levels_exit_entry_for_a_segment"][:]
            count = info >> 9
            level = (info >> 6) & 7
            closed = ((info >> 3) & 7) == 4
        else:
            count = f["N_points_for_a_segment"][:]
            level = f["Hierarchial_level_of_a_segment"][:]
            closed = None
        lines = []
        bins, covered = bins_in_box(nx, ny, size_minutes / 60.0, box)
        for b in bins:
            column = b % nx
            if column * size_minutes >= 180 * 60:
                column -= nx  # longitudes from 180 on: west of Greenwich
            row = ny - 1 - b // nx  # from the south pole up
            x0, y0 = column * UNITS, row * UNITS
            for s in range(int(first_seg[b]), int(first_seg[b]) + int(n_seg[b])):
                if int(level[s]) not in levels:
                    continue
                start = int(first_point[s])
                points = [(x0 + int(dx[k]), y0 + int(dy[k])) for k in range(start, start + int(count[s]))]
                if closed is not None and closed[s] and points and points[0] != points[-1]:
                    points.append(points[0])
                lines.append(points)
        return lines, size_minutes, covered


def segments_of(lines):
    out = []
    for points in lines:
        for a, b in zip(points, points[1:]):
            if a != b:
                out.append((a, b))
    return out


def make(resolution, layers, box, data_dir=DATA_DIR, levels=None):
    """The segments of the layers (a comma-separated list) in the box, the
    bin size in minutes and the box the bins cover."""
    segments = []
    size = covered = None
    for layer in layers.split(","):
        path = os.path.join(data_dir, "binned_%s_%s.nc" % (FILE_STEM[layer], resolution))
        if not os.path.exists(path):
            sys.exit("%s is missing: apt-get install gmt-gshhg-%s" % (path, {"c": "low", "l": "low", "i": "low", "h": "high", "f": "full"}[resolution]))
        lines, layer_size, covered = polylines(path, layer, box, (levels or DEFAULT_LEVELS)[layer])
        if size not in (None, layer_size):
            sys.exit("layers with different bin sizes cannot share coordinates")
        size = layer_size
        segments += segments_of(lines)
    return segments, size, covered


def text(segments):
    lines = ["0", str(len(segments))]
    lines += ["%d %d %d %d" % (a[0], a[1], b[0], b[1]) for a, b in segments]
    return "\n".join(lines) + "\n"


def version(data_dir, res):
    # From the resolution's own file: the packages ship the resolutions
    # apart (gmt-gshhg-full has only f), so the crude file may be missing.
    with h5py.File(os.path.join(data_dir, "binned_GSHHS_%s.nc" % res), "r") as f:
        return f.attrs["version"].decode()


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--res", default="l", choices="clihf", help="resolution: crude, low, intermediate, high, full")
    p.add_argument("--layers", default="coast", help="comma-separated: coast, borders, rivers")
    p.add_argument("--box", nargs=4, type=float, metavar=("WEST", "EAST", "SOUTH", "NORTH"), default=(-180, 180, -90, 90))
    p.add_argument("-o", "--out", help="output file (default: standard output)")
    p.add_argument("--data-dir", default=DATA_DIR)
    p.add_argument("--fixtures", action="store_true", help="write the committed fixtures into tests/data/")
    p.add_argument("--check", action="store_true", help="with --fixtures: compare with the committed files instead")
    args = p.parse_args()
    if args.fixtures:
        stale = 0
        for name, res, layers, box, _ in FIXTURES:
            segments, _, covered = make(res, layers, box, args.data_dir)
            path = os.path.join(OUT_DIR, name + ".txt")
            if args.check:
                with open(path) as f:
                    if f.read() != text(segments):
                        print("stale:", path)
                        stale += 1
            else:
                with open(path, "w") as f:
                    f.write(text(segments))
            print("%s: %d segments, bins covering %s" % (name, len(segments), covered), file=sys.stderr)
        sys.exit(1 if stale else 0)
    segments, size, covered = make(args.res, args.layers, tuple(args.box), args.data_dir)
    out = text(segments)
    if args.out:
        with open(args.out, "w") as f:
            f.write(out)
    else:
        sys.stdout.write(out)
    print(
        "GSHHG %s, resolution %s, %s, bins covering %s: %d segments (units of %g/65535 degrees)"
        % (version(args.data_dir, args.res), args.res, args.layers, covered, len(segments), size / 60.0),
        file=sys.stderr,
    )


if __name__ == "__main__":
    main()
