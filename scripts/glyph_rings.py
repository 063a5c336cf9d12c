#!/usr/bin/env python3
"""Flattens the outlines of a few glyphs of DejaVu Sans into rings.

The glyph fixtures tests/data/glyph_*.rings (read by tests/glyphs.rs, by
segvoronoi-testgen's `glyphs` family and so by the CGAL cross-check) come
from this script. It is a generation step only, never part of a build.

Source: DejaVu Sans (Debian package fonts-dejavu-core,
/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf). DejaVu's fonts are free
(the Bitstream Vera licence plus public-domain changes); a few hundred
coordinates of outline data derived from them are fine to keep in the tree.

Each contour of the glyph (TrueType: lines and quadratic Béziers, with the
implied on-curve points between consecutive off-curve ones) becomes one
ring: every quadratic piece is cut into CHORDS chords at equal parameter
steps, coordinates in font units (2048 per em) as the shortest decimal that
reads back the same double. Repeated consecutive points and the repeated
closing point are dropped. The script then checks exactly (rational
arithmetic on those doubles) that no two segments of a glyph cross or touch
except consecutive ones of a ring at their shared point, so the rings are a
legal input for `Builder::add_polygon`.

The rings format (shared with c_tests/cgal_crosscheck.cpp --polygon and
testgen/src/rings.rs): a line `rings R`, then for each of the R rings a
line with its point count K and K lines `x y`; the last point joins the
first. Lines starting with `#` are comments; blank lines are ignored.

Regenerate (needs `pip install fonttools` and fonts-dejavu-core):

    python3 scripts/glyph_rings.py            # writes tests/data/glyph_{B,8,g}.rings
    python3 scripts/glyph_rings.py --check    # exits 1 if a committed file differs
"""

import argparse
import os
import sys
from fractions import Fraction

from fontTools.pens.basePen import BasePen
from fontTools.ttLib import TTFont

FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
# Three letters with holes: B and 8 have two, g in DejaVu Sans one (its
# descender is open, a single outline around one bowl).
GLYPHS = {"B": "B", "8": "8", "g": "g"}
# Chords per quadratic piece.
CHORDS = 12
OUT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data")


class FlatteningPen(BasePen):
    """Collects each contour as a list of points, curves cut into chords."""

    def __init__(self, glyph_set):
        super().__init__(glyph_set)
        self.rings = []
        self.current = []

    def _moveTo(self, pt):
        self.current = [pt]

    def _lineTo(self, pt):
        self.current.append(pt)

    def _qCurveToOne(self, pt1, pt2):
        (x0, y0), (x1, y1), (x2, y2) = self.current[-1], pt1, pt2
        for k in range(1, CHORDS + 1):
            t = k / CHORDS
            u = 1.0 - t
            if k == CHORDS:
                self.current.append(pt2)  # the on-curve point exactly
            else:
                self.current.append((u * u * x0 + 2 * u * t * x1 + t * t * x2, u * u * y0 + 2 * u * t * y1 + t * t * y2))

    def _curveToOne(self, pt1, pt2, pt3):
        raise ValueError("cubic curve in a TrueType glyph")

    def _closePath(self):
        ring = []
        for p in self.current:
            p = (float(p[0]), float(p[1]))
            if not ring or ring[-1] != p:
                ring.append(p)
        while len(ring) > 1 and ring[0] == ring[-1]:
            ring.pop()
        self.rings.append(ring)
        self.current = []

    _endPath = _closePath


def orient(a, b, c):
    det = (Fraction(b[0]) - Fraction(a[0])) * (Fraction(c[1]) - Fraction(a[1])) - (Fraction(b[1]) - Fraction(a[1])) * (
        Fraction(c[0]) - Fraction(a[0])
    )
    return (det > 0) - (det < 0)


def on_segment(a, b, p):
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def closed_meet(s, t):
    o1, o2, o3, o4 = orient(*s, t[0]), orient(*s, t[1]), orient(*t, s[0]), orient(*t, s[1])
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return (
        (o1 == 0 and on_segment(*s, t[0]))
        or (o2 == 0 and on_segment(*s, t[1]))
        or (o3 == 0 and on_segment(*t, s[0]))
        or (o4 == 0 and on_segment(*t, s[1]))
    )


def check_legal(rings):
    """Raises unless segments meet only as neighbours in a ring, at one point."""
    segments = []
    for r, ring in enumerate(rings):
        n = len(ring)
        if n < 3:
            raise ValueError(f"ring {r} has {n} points")
        for k in range(n):
            segments.append((r, k, (ring[k], ring[(k + 1) % n]), n))
    boxes = [(min(s[0][0], s[1][0]), max(s[0][0], s[1][0]), min(s[0][1], s[1][1]), max(s[0][1], s[1][1])) for _, _, s, _ in segments]
    for i, (ri, ki, s, n) in enumerate(segments):
        for j in range(i + 1, len(segments)):
            rj, kj, t, _ = segments[j]
            bi, bj = boxes[i], boxes[j]
            if bi[1] < bj[0] or bj[1] < bi[0] or bi[3] < bj[2] or bj[3] < bi[2]:
                continue
            neighbours = ri == rj and ((kj - ki) % n in (1, n - 1))
            if neighbours:
                # sharing one endpoint: only a collinear fold back overlaps
                shared = s[1] if s[1] in t else s[0]
                far_s = s[0] if shared == s[1] else s[1]
                far_t = t[0] if shared == t[1] else t[1]
                if orient(shared, far_s, far_t) == 0 and (on_segment(shared, far_s, far_t) or on_segment(shared, far_t, far_s)):
                    raise ValueError(f"ring {ri}: segments {ki} and {kj} overlap")
                continue
            if closed_meet(s, t):
                raise ValueError(f"segments {ri}:{ki} and {rj}:{kj} meet")


def rings_text(char, glyph_name, rings):
    return rings_file(
        [
            f"# DejaVu Sans (fonts-dejavu-core, free licence), glyph '{char}' ({glyph_name}), font units (2048/em)",
            f"# each quadratic piece flattened into {CHORDS} chords; generated by scripts/glyph_rings.py",
        ],
        rings,
    )


def rings_file(comments, rings):
    """The rings format: the comment lines, `rings R`, then each ring."""
    lines = comments + [f"rings {len(rings)}"]
    for ring in rings:
        lines.append(str(len(ring)))
        lines.extend(f"{repr(x)} {repr(y)}" for x, y in ring)
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare with the committed files instead of writing")
    parser.add_argument("--font", default=FONT)
    args = parser.parse_args()
    font = TTFont(args.font)
    cmap, glyph_set = font.getBestCmap(), font.getGlyphSet()
    differ = False
    for char, label in GLYPHS.items():
        name = cmap[ord(char)]
        pen = FlatteningPen(glyph_set)
        glyph_set[name].draw(pen)
        check_legal(pen.rings)
        text = rings_text(char, name, pen.rings)
        path = os.path.normpath(os.path.join(OUT_DIR, f"glyph_{label}.rings"))
        if args.check:
            with open(path) as f:
                if f.read() != text:
                    print(f"{path} differs", file=sys.stderr)
                    differ = True
        else:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(text)
            print(f"{path}: {len(pen.rings)} rings, {sum(len(r) for r in pen.rings)} points")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
