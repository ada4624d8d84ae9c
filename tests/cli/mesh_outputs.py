#!/usr/bin/python3
"""recombine's meshes read back by readers that are not dartcheck's (issue 64 item 3).

  mesh_outputs.py DARTCHECK WORKDIR

A tetrahedral mesh made by gmsh itself (a unit box, `gmsh -3`, formats 4.1
and 2.2) is recombined by dartcheck, which must read gmsh's files as gmsh
wrote them: its tetrahedra count is the one meshio reads in the same file.
The result is written as .mesh, .vtu, .vtk, .msh 4.1 and .msh 2.2, and
read back:
- by meshio (Debian's python3-meshio) for .mesh, .vtu, .vtk and .msh 4.1:
  the points equal the input's, coordinate for coordinate (the writers print
  shortest round-trip decimals; meshio reads medit's as float32, compared
  within its precision); the cells of each kind are as many as
  recombine's JSON reports, and the same vertex sets in every format; each
  cell has the handedness its format defines (gmsh: every kind positive at
  corner 0; VTK: the same but the wedge, whose first triangle faces away
  from the second, and which meshio turns into gmsh's order on reading),
  computed here from the coordinates; the cell data
  scaled_jacobian holds the quantiles the JSON reports (min, median, max of
  the recombined cells, by nearest rank as the JSON documents);
- by gmsh's CLI for both .msh files (meshio 5's 2.2 reader fails on cell
  data, its own files included): gmsh re-saves each as 2.2 and its element
  counts per type are recombine's.
A broken file (a tetrahedron naming a node that is not in $Nodes) is
refused with its line and column.
"""
import json
import os
import subprocess
import sys

import meshio
import numpy as np

from script_checks import check, finish

dartcheck, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)


def run(*args, **kw):
    return subprocess.run(list(args), capture_output=True, text=True, **kw)


# The input: gmsh's own tetrahedral mesh of the unit box.
geo = os.path.join(work, "box.geo")
with open(geo, "w") as f:
    f.write('SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\nMesh.CharacteristicLengthMax = 0.25;\n')
inputs = {}
for version, fmt in (("4.1", "msh41"), ("2.2", "msh22")):
    path = os.path.join(work, f"box-{version}.msh")
    r = run("gmsh", "-3", geo, "-o", path, "-format", fmt)
    check(r.returncode == 0, f"gmsh -3 failed: {r.stderr}")
    inputs[version] = path

tets_in = sum(len(c.data) for c in meshio.read(inputs["4.1"]).cells if c.type == "tetra")
check(tets_in > 100, f"gmsh made only {tets_in} tetrahedra")
for version, path in inputs.items():
    r = run(dartcheck, "recombine", path, "--format", "json", "-q")
    check(r.returncode == 0, f"recombine {path}: exit {r.returncode}: {r.stderr}")
    if r.returncode == 0:
        check(json.loads(r.stdout)["tetrahedra"] == tets_in, f"{path}: dartcheck reads {json.loads(r.stdout)['tetrahedra']} tetrahedra, meshio {tets_in}")

# The outputs, with prisms and pyramids so that every kind of cell is there.
base = os.path.join(work, "box-hex")
outputs = {ext: base + ext for ext in (".mesh", ".vtu", ".vtk", ".msh")}
outputs["2.2"] = base + "-22.msh"
report = None
for key, path in outputs.items():
    extra = ["--msh-version", "2.2"] if key == "2.2" else []
    r = run(dartcheck, "recombine", inputs["4.1"], "--cells", "hex,prism,pyramid", "-o", path, "--format", "json", "-q", *extra)
    check(r.returncode == 0, f"recombine -o {path}: exit {r.returncode}: {r.stderr}")
    report = json.loads(r.stdout)
counts = {"hexahedron": report["hexes"], "wedge": report["prisms"]["selected"], "pyramid": report["pyramids"]["selected"],
          "tetra": report["remaining_tetrahedra"]}
check(all(counts[k] > 0 for k in counts), f"a kind of cell is missing from the test: {counts}")
source_points = meshio.read(inputs["4.1"]).points


def handedness(points, cell, kind):
    p = points[cell]
    at = {"tetra": (1, 2, 3), "hexahedron": (1, 3, 4), "wedge": (1, 2, 3), "pyramid": (1, 3, 4)}[kind]
    return np.sign(np.dot(np.cross(p[at[0]] - p[0], p[at[1]] - p[0]), p[at[2]] - p[0]))


cell_sets = {}
for key in (".mesh", ".vtu", ".vtk", ".msh"):
    m = meshio.read(outputs[key])
    # meshio reads medit's coordinates as float32.
    same = np.allclose(m.points, source_points, rtol=1e-6, atol=1e-7) if key == ".mesh" else np.array_equal(m.points, source_points)
    check(same, f"{key}: the points differ from the input's")
    got = {}
    for c in m.cells:
        got[c.type] = got.get(c.type, 0) + len(c.data)
    got = {k: v for k, v in got.items() if k in counts}
    check(got == counts, f"{key}: cells {got}, recombine reports {counts}")
    cell_sets[key] = sorted((c.type, tuple(sorted(cell))) for c in m.cells if c.type in counts for cell in c.data)
    if key == ".mesh":
        continue  # medit's handedness is the recombination's own
    # meshio turns VTK's wedge (first triangle facing away from the second)
    # into gmsh's order on reading: positive everywhere means each file had
    # its format's handedness.
    for c in m.cells:
        if c.type not in counts:
            continue
        want = 1
        signs = [handedness(m.points, cell, c.type) for cell in c.data]
        check(all(s == want for s in signs), f"{key}: {sum(s != want for s in signs)} {c.type} cells not of the format's handedness")
    q = np.concatenate([np.ravel(d) for c, d in zip(m.cells, m.cell_data["scaled_jacobian"]) if c.type != "tetra"])
    q.sort()
    quantiles = report["quality"]["quantiles"]
    for name, at in (("min", 0.0), ("median", 0.5), ("max", 1.0)):
        value = q[int(round(at * (len(q) - 1)))]
        check(value == quantiles[name], f"{key}: scaled_jacobian {name} {value}, the JSON says {quantiles[name]}")
for key in (".vtu", ".vtk", ".msh"):
    check(cell_sets[key] == cell_sets[".mesh"], f"{key}: not the cells of the .mesh")

# gmsh reads both .msh files: re-saved as 2.2, its element counts are ours.
gmsh_types = {"5": "hexahedron", "6": "wedge", "7": "pyramid", "4": "tetra"}
for key in (".msh", "2.2"):
    back = outputs[key] + ".gmsh.msh"
    r = run("gmsh", outputs[key], "-0", "-o", back, "-format", "msh22")
    check(r.returncode == 0 and os.path.exists(back), f"gmsh cannot read {outputs[key]}: {r.stdout[-500:]} {r.stderr[-500:]}")
    if not os.path.exists(back):
        continue
    with open(back) as f:
        lines = f.read().split("\n")
    start = lines.index("$Elements")
    got = {}
    for line in lines[start + 2:lines.index("$EndElements")]:
        kind = gmsh_types.get(line.split()[1])
        if kind:
            got[kind] = got.get(kind, 0) + 1
    check(got == counts, f"gmsh reads {got} in {outputs[key]}, recombine reports {counts}")

# A broken gmsh file: an element naming a node that is not in $Nodes.
with open(inputs["2.2"]) as f:
    text = f.read().split("\n")
last = text.index("$EndElements") - 1
fields = text[last].split()
fields[-1] = "999999"
text[last] = " ".join(fields)
broken = os.path.join(work, "broken.msh")
with open(broken, "w") as f:
    f.write("\n".join(text))
r = run(dartcheck, "recombine", broken)
column = len(" ".join(fields[:-1])) + 2
check(r.returncode == 2 and f"broken.msh:{last + 1}:{column}: error: node tag 999999 is not in $Nodes" in r.stderr,
      f"broken .msh: exit {r.returncode}, {r.stderr.strip()}")

finish(f"{tets_in} tetrahedra from gmsh, recombined into {counts}, read back by meshio and gmsh")
