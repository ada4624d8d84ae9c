#!/usr/bin/python3
"""apply's polygon meshes and query's selections read back by readers that are not dartcheck's (issue 64 item 3).

  apply_query_mesh_outputs.py DARTCHECK REPO WORKDIR

apply: Jerboa's triangulation with positions (catalogs/embedding-operations.yaml,
triangulation-jerboa-pos) at dart 0 of a mesh of two faces, the triangle
(0,0) (1,0) (0,1) first and a pentagon apart. By hand (003 Sec. 5.1: the
new vertex at the mean of the face's vertices): 9 points, the 8 given and
(1/3, 1/3, 0); 3 triangles, each the centre and one side of the triangle;
the pentagon untouched. meshio reads .vtu and .vtk and must find exactly
that; .msh is refused (gmsh has no pentagon element: exit 2, the face named,
no file). On the unit square (one quadrangle) the .msh is written: meshio
reads 5 points with the centre (0.5, 0.5, 0) and 4 triangles, gmsh's CLI
re-saves it as 2.2 with 4 elements of type 2.

query: on tests/data/cube-5-tets.mesh (a cube cut into a central
tetrahedron and 4 corner ones, each sharing a face with the centre), the
two-tets query matches each pair centre + corner: 4 matches, so the centre
is in all 4 (cell data matches = 4) and each corner in one, a different one
per corner (match 0..3). The 322 hex patterns with --strategy global select
one match, the whole cube: match 0 on all 5. Each file's points are the
input's as meshio reads the input; gmsh re-saves the .msh with 5 elements
of type 4. -o on a map that is not a tetrahedral mesh, and -o .mesh, are
exit 2 with no file.
"""
import os
import subprocess
import sys

import meshio
import numpy as np

from script_checks import check, finish

dartcheck, repo, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)


def run(*args):
    return subprocess.run([dartcheck, *args], capture_output=True, text=True, cwd=repo)


def gmsh_element_types(path):
    """gmsh's own reading of `path`: the element types of its 2.2 re-save."""
    back = path + ".gmsh.msh"
    r = subprocess.run(["gmsh", path, "-0", "-o", back, "-format", "msh22"], capture_output=True, text=True)
    check(r.returncode == 0 and os.path.exists(back), f"gmsh cannot read {path}: {r.stdout[-300:]}")
    if not os.path.exists(back):
        return []
    with open(back) as f:
        lines = f.read().split("\n")
    return [line.split()[1] for line in lines[lines.index("$Elements") + 2:lines.index("$EndElements")]]


catalog = "catalogs/embedding-operations.yaml"
rule = ["--rule", "triangulation-jerboa-pos", "--hook", "0"]

# apply: a triangle and a pentagon.
two_faces = os.path.join(work, "triangle-pentagon.off")
with open(two_faces, "w") as f:
    f.write("OFF\n8 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0\n4 0 0\n4.5 1 0\n3.5 2 0\n2.5 1 0\n3 0 1 2\n5 3 4 5 6 7\n")
given = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (3, 0, 0), (4, 0, 0), (4.5, 1, 0), (3.5, 2, 0), (2.5, 1, 0)]
centre = (1 / 3, 1 / 3, 0)
for ext in ("vtu", "vtk"):
    out = os.path.join(work, f"triangulated.{ext}")
    r = run("apply", catalog, *rule, "--map", two_faces, "-o", out)
    check(r.returncode == 0, f"apply -o .{ext}: exit {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        continue
    m = meshio.read(out)
    pts = [tuple(p) for p in m.points]
    check(len(pts) == 9 and all(np.allclose(pts[k], given[k]) for k in range(8)) and np.allclose(pts[8], centre),
          f".{ext}: points {pts}, expected the 8 given and the centre {centre}")
    cells = {c.type: [sorted(tuple(np.round(m.points[v], 12)) for v in cell) for cell in c.data] for c in m.cells}
    sides = [[(0, 0, 0), (1, 0, 0)], [(1, 0, 0), (0, 1, 0)], [(0, 0, 0), (0, 1, 0)]]
    want_triangles = sorted(sorted([tuple(np.round(centre, 12)), *s]) for s in sides)
    check(sorted(cells.get("triangle", [])) == want_triangles, f".{ext}: triangles {cells.get('triangle')}, expected {want_triangles}")
    polygons = [cell for t, cs in cells.items() if t.startswith("polygon") for cell in cs]
    check(polygons == [sorted(given[3:])], f".{ext}: polygons {polygons}, expected the pentagon")
refused = os.path.join(work, "triangulated.msh")
r = run("apply", catalog, *rule, "--map", two_faces, "-o", refused)
check(r.returncode == 2 and "gmsh has no element for a face of 5 corners" in r.stderr and not os.path.exists(refused),
      f"apply -o .msh with a pentagon: exit {r.returncode}, {r.stderr.strip()}, file {os.path.exists(refused)}")

square = os.path.join(work, "square.msh")
r = run("apply", catalog, *rule, "--map", "catalogs/meshes/unit-square.off", "-o", square)
check(r.returncode == 0, f"apply -o .msh: exit {r.returncode}: {r.stderr}")
if r.returncode == 0:
    m = meshio.read(square)
    check(len(m.points) == 5 and any(np.array_equal(p, [0.5, 0.5, 0]) for p in m.points), f"square.msh: points {m.points.tolist()}")
    check([(c.type, len(c.data)) for c in m.cells] == [("triangle", 4)], f"square.msh: cells {[(c.type, len(c.data)) for c in m.cells]}")
    types = gmsh_element_types(square)
    check(types == ["2"] * 4, f"gmsh reads element types {types} in square.msh, expected 4 triangles")

# query: the selections as cell data.
mesh = "tests/data/cube-5-tets.mesh"
source_points = meshio.read(os.path.join(repo, mesh)).points
for ext in ("vtu", "vtk", "msh"):
    out = os.path.join(work, f"pairs.{ext}")
    r = run("query", mesh, "--query", "tests/data/two-tets.mesh", "-o", out)
    check(r.returncode == 0 and f"written: {out}" in r.stdout, f"query -o .{ext}: exit {r.returncode}: {r.stderr}")
    if r.returncode != 0:
        continue
    m = meshio.read(out)
    # meshio reads medit's coordinates as float32.
    check(np.allclose(m.points, source_points, rtol=1e-6), f"pairs.{ext}: points differ from the input's")
    check([(c.type, len(c.data)) for c in m.cells] == [("tetra", 5)], f"pairs.{ext}: cells {[(c.type, len(c.data)) for c in m.cells]}")
    count = [int(v) for v in np.ravel(m.cell_data["matches"][0])]
    match = [int(v) for v in np.ravel(m.cell_data["match"][0])]
    query = [int(v) for v in np.ravel(m.cell_data["query"][0])]
    centre_tet = count.index(4) if 4 in count else -1
    check(sorted(count) == [1, 1, 1, 1, 4], f"pairs.{ext}: matches per tetrahedron {count}, expected 4 on the centre and 1 on each corner")
    corners = [match[t] for t in range(5) if t != centre_tet]
    check(sorted(corners) == [0, 1, 2, 3], f"pairs.{ext}: the corners' match {corners}, expected one each of 0..3")
    check(query == [0] * 5, f"pairs.{ext}: query {query}, expected the one query 0 everywhere")
    if ext == "msh":
        types = gmsh_element_types(out)
        check(types == ["4"] * 5, f"gmsh reads element types {types} in pairs.msh, expected 5 tetrahedra")
hex_out = os.path.join(work, "hex.vtu")
r = run("query", mesh, "--hex", "--strategy", "global", "-o", hex_out)
check(r.returncode == 0, f"query --hex -o: exit {r.returncode}: {r.stderr}")
if r.returncode == 0:
    m = meshio.read(hex_out)
    check([int(v) for v in np.ravel(m.cell_data["match"][0])] == [0] * 5, f"hex.vtu: match {m.cell_data['match']}, expected one match on all 5")
for args, message in ((["cube", "--query", "cube"], "is not one"), ([mesh, "--hex"], "medit .mesh carries no cell data")):
    out = os.path.join(work, "refused" + (".mesh" if "medit" in message else ".vtu"))
    r = run("query", *args, "-o", out)
    check(r.returncode == 2 and message in r.stderr and not os.path.exists(out), f"query {args} -o {out}: exit {r.returncode}, {r.stderr.strip()}")

finish()
