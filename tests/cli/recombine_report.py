#!/usr/bin/python3
"""recombine --report DIR: the HTML page and its histogram (issue 64 item 3).

  recombine_report.py DARTCHECK REPO WORKDIR

gmsh's box (tests/data/gmsh-box-41.msh) and a sheared cube whose one hex
has a scaled Jacobian under 0.2 are recombined with -o X.vtu and --report.
The page and quality.svg must parse as XML; the SVG's bars (one per bin,
"BIN: N cells" in each bar's title) must hold the counts this script bins
itself from the scaled_jacobian cell data that meshio reads in the .vtu
(the recombined cells: every cell but the tetrahedra; bins < 0, [0, 0.1),
..., [0.8, 0.9), >= 0.9); a bar is amber exactly when its bin lies under
0.2 and red for < 0; the page's inline SVG is quality.svg; the page warns of
poor cells exactly when the data has a cell under 0.2. An unwritable
report directory is exit 4 before any work.
"""
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

from script_checks import check, finish

dartcheck, repo, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
SVG = "{http://www.w3.org/2000/svg}"


def bin_of(q):
    return 0 if q < 0 else 1 + min(9, math.floor(q * 10 + 1e-12))


labels = ["< 0"] + [f"[{k / 10:g}, {(k + 1) / 10:g})" for k in range(9)] + [">= 0.9"]
for name, mesh, extra in (("box", "tests/data/gmsh-box-41.msh", ["--cells", "hex,prism,pyramid"]),
                          ("sheared", "tests/data/sheared-cube-5-tets.mesh", [])):
    out_dir = os.path.join(work, name)
    vtu = os.path.join(work, name + ".vtu")
    r = subprocess.run([dartcheck, "recombine", mesh, *extra, "-o", vtu, "--report", out_dir, "-q"], capture_output=True, text=True, cwd=repo)
    check(r.returncode == 0, f"{name}: exit {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        continue
    m = meshio.read(vtu)
    q = np.concatenate([np.ravel(d) for c, d in zip(m.cells, m.cell_data["scaled_jacobian"]) if c.type != "tetra"])
    want = [0] * 11
    for v in q:
        want[bin_of(float(v))] += 1
    svg = ET.parse(os.path.join(out_dir, "quality.svg")).getroot()
    bars = [e for e in svg.iter(SVG + "rect") if e.get("class") == "bin"]
    got = [e.find(SVG + "title").text for e in bars]
    check(got == [f"{labels[k]}: {want[k]} cells" for k in range(11)], f"{name}: bars {got}, the .vtu's cells bin as {want}")
    fills = [e.get("fill") for e in bars]
    check(len(set(fills[1:3])) == 1 and fills[1] not in (fills[0], fills[3]) and len(set(fills[3:])) == 1 and fills[0] != fills[3],
          f"{name}: bar colours {fills}: red below 0, amber under 0.2, blue above")
    with open(os.path.join(out_dir, "index.html")) as f:
        page = f.read()
    root = ET.fromstring(page.split("\n", 1)[1])  # after the doctype
    inline = [e for e in root.iter(SVG + "svg")]
    for e in inline:
        e.tail = None  # the page's newline after the picture
    check(len(inline) == 1 and ET.tostring(inline[0]) == ET.tostring(svg), f"{name}: the page's histogram is not quality.svg")
    poor = any(v < 0.2 for v in q)
    check(("poor for a simulation" in page) == poor, f"{name}: the page's warning disagrees with the data (a cell under 0.2: {poor})")
    check(name != "sheared" or poor, "sheared: its hex must be poor, else the warning is not tested")

r = subprocess.run([dartcheck, "recombine", "tests/data/cube-5-tets.mesh", "--report", "/proc/dartcheck-report"], capture_output=True, text=True, cwd=repo)
check(r.returncode == 4 and "/proc/dartcheck-report" in r.stderr and "mesh " not in r.stdout, f"unwritable --report: exit {r.returncode}, {r.stderr}")
finish()
