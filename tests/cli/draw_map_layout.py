#!/usr/bin/python3
"""draw-map's layout of maps without positions (issue 64 item 11).

  draw_map_layout.py DARTCHECK WORKDIR

A map without positions of more than 16 darts is drawn as an exploded view
of its skeleton's layout. Checked on the pictures dartcheck writes:
- every dart is pinned (pos="x,y!" in the DOT) for the 48-dart cube, the
  800-dart 10x10 grid and the 3-G-map stacked-cubes;
- the grid's darts are at least 0.75 inch apart (the nodes' width: no two
  nodes overlap), computed here from the pins;
- the SVG sizes are bounded: the cube within 1500 pt a side, the grid
  within 3000 pt (dot drew it 1,381 x 7,645 pt, the tangle issue 64 shows);
- a map of at most 16 darts (the square shape, polygon:4) is still laid
  out by dot, unpinned.
"""
import math
import os
import re
import subprocess
import sys

from script_checks import check, finish

dartcheck, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)


def draw(shape, ext, *extra):
    out = os.path.join(work, shape.replace(":", "-") + "." + ext)
    r = subprocess.run([dartcheck, "-q", "draw-map", shape, "-o", out, *extra], capture_output=True, text=True)
    check(r.returncode == 0, f"draw-map {shape}: exit {r.returncode}: {r.stderr}")
    with open(out) as f:
        return f.read()


def pins(dot):
    return [(float(x), float(y)) for x, y in re.findall(r'pos="([-0-9.e]+),([-0-9.e]+)!"', dot)]


for shape, darts, extra, bound in (("cube", 48, [], 1500), ("grid:10x10", 800, [], 3000), ("stacked-cubes", 96, ["--model", "3-gmap"], 3000)):
    p = pins(draw(shape, "dot", *extra))
    check(len(p) == darts, f"{shape}: {len(p)} darts pinned of {darts}")
    svg = draw(shape, "svg", *extra)
    m = re.search(r'<svg width="([0-9.]+)pt" height="([0-9.]+)pt"', svg)
    check(m and float(m.group(1)) <= bound and float(m.group(2)) <= bound, f"{shape}: picture {m.groups() if m else None} pt, bound {bound}")
    if shape.startswith("grid"):
        closest = min(math.dist(p[i], p[j]) for i in range(len(p)) for j in range(i + 1, len(p)))
        check(closest >= 0.75, f"{shape}: two darts {closest:.3f} inch apart, nodes overlap")
check(pins(draw("polygon:4", "dot")) == [], "polygon:4 (8 darts) is pinned; small maps are dot's")
finish()
