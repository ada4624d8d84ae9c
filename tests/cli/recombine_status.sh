#!/bin/sh
# recombine on a terminal (issue 64): a status line names each stage as it
# starts (it was silent for 27 s during the candidate search on 460k
# tetrahedra), the search says how many vertices are done, and the line is
# cleared before the report. Off a terminal nothing is added. script(1)
# (util-linux) gives the pseudo-terminal.
# Usage: recombine_status.sh DARTCHECK (from the source directory).
out=$(mktemp)
trap 'rm -f "$out"' EXIT
script -qec "$1 recombine tests/data/cube-5-tets.mesh" "$out" >/dev/null 2>&1 || { echo "recombine failed"; cat "$out"; exit 1; }
python3 - "$out" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8", newline="").read()
stages = re.findall(r"\r\x1b\[Krecombine: ([^\r\n\x1b]*)", text)
want = ["reading the mesh", "checking the input map", "indexing the tetrahedra", "searching hex candidates: vertex 0 of 8 (0%)",
        "selecting hexes", "merging the cells' tetrahedra", "checking the recombined map"]
if stages != want:
    sys.exit(f"stages {stages}, expected {want}")
if "\r\x1b[Kmesh        tests/data/cube-5-tets.mesh:" not in text:
    sys.exit("the status line is not cleared before the report")
print(f"{len(stages)} stages shown, the line cleared before the report")
PY
[ $? -eq 0 ] || exit 1
off=$("$1" recombine tests/data/cube-5-tets.mesh 2>&1)
case $off in *"recombine: "*) echo "a status line off a terminal"; exit 1 ;; esac
