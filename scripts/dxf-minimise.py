#!/usr/bin/env python3
"""Minimise a DXF drawing on which the CLI fails: drop entities (delta
debugging) while the CLI's standard error still contains the message.

    python3 scripts/dxf-minimise.py DRAWING.dxf "nearer than its own" [CLI options...]

Keeps LINE, ARC, CIRCLE, LWPOLYLINE and POINT entities (the others the
diagram leaves out); runs `target/release/segvoronoi` (or $SEGVORONOI)
with `--split-crossings` and the options given. Writes the minimised
drawing to min.dxf (or $OUT) and prints its entities' codes.
"""
import os
import subprocess
import sys

repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
program = os.environ.get("SEGVORONOI", os.path.join(repo, "target", "release", "segvoronoi"))
out = os.environ.get("OUT", "min.dxf")
drawing, needle, extra = sys.argv[1], sys.argv[2], sys.argv[3:]

lines = [line.strip() for line in open(drawing, errors="replace")]
pairs = list(zip(lines[0::2], lines[1::2]))
entities, inside, current = [], False, None
for code, value in pairs:
    if code == "2" and value == "ENTITIES":
        inside = True
        continue
    if not inside:
        continue
    if code == "0":
        if current is not None:
            entities.append(current)
        if value == "ENDSEC":
            break
        current = [(code, value)]
    else:
        current.append((code, value))
keep = [e for e in entities if e[0][1] in ("LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POINT")]


def write(chosen, path):
    with open(path, "w") as f:
        f.write("0\nSECTION\n2\nENTITIES\n")
        for entity in chosen:
            for code, value in entity:
                f.write(f"{code}\n{value}\n")
        f.write("0\nENDSEC\n0\nEOF\n")


def fails(chosen):
    write(chosen, out)
    run = subprocess.run([program, out, "--split-crossings"] + extra, capture_output=True, text=True, timeout=60)
    return needle in run.stderr


if not fails(keep):
    sys.exit(f"{drawing}: the message does not come up with its entities alone")
parts = 2
while len(keep) >= 2:
    chunk = max(1, len(keep) // parts)
    for i in range(0, len(keep), chunk):
        candidate = keep[:i] + keep[i + chunk:]
        if candidate and fails(candidate):
            keep, parts = candidate, max(parts - 1, 2)
            break
    else:
        if chunk == 1:
            break
        parts = min(len(keep), parts * 2)
write(keep, out)
for entity in keep:
    print([value for code, value in entity if code in ("0", "10", "20", "11", "21", "40", "50", "51", "42", "70")])
