#!/bin/bash
# The outputs of dartcheck's commands on the shipped inputs, written to a
# directory so that two builds can be compared byte for byte (issue 63: a
# refactoring changes no output).
#
#   scripts/outputs-snapshot.sh DARTCHECK OUT_DIR [ELEPHANT.ele]
#   diff -r BEFORE_DIR AFTER_DIR        # nothing: the same outputs
#
# Run from the repository root with ../shared beside it. Each command's
# stdout, stderr and exit status go to OUT_DIR/<name>.out, its written files
# to OUT_DIR/<name>/. What varies from run to run is masked (and nothing
# else): wall and CPU times (check's ms column too), rates, peak memory,
# the output directory's path. The
# elephant (27,474 tetrahedra from CGAL's elephant.off by TetGen, as
# ctest's cli.tetgen_elephant makes it) is recombined when given.
set -euo pipefail
dartcheck=$(realpath "$1")
out=$(realpath -m "$2")
elephant=${3:-}
rm -rf "$out"
mkdir -p "$out"
shared=../shared/jerboa-samples
catalogs=(catalogs/seed-operations.yaml catalogs/embedding-operations.yaml catalogs/event-operations.yaml
          catalogs/subdivision-operations.yaml tests/data/jerboa-rebuild/JerboaRebuilt.jme "$shared/JerboaRebuilt2.jme")

# Times and memory, in every form the commands print them.
mask() {
  sed -E \
    -e 's/[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? ?(s|ms|µs|us)\b/<time>/g' \
    -e 's/[0-9]+(\.[0-9]+)? ?(MiB|KiB|GiB)/<memory>/g' \
    -e 's/[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?\/s\b/<rate>/g' \
    -e 's/[0-9]+(\.[0-9]+)? (tetrahedra|applications|hosts|runs|rules) per second/<rate>/g' \
    -e 's/"([a-z_]*(seconds|_s|_ms|time|per_second|_mib|rate))": ?[-0-9.e+]+/"\1": <masked>/g' \
    -e 's/"seconds":\{[^}]*\}/"seconds":<masked>/g' \
    -e 's/ +[0-9]+\.[0-9]{2}  ([a-z])/ <ms>  \1/' \
    -e 's/seed [0-9]+ \(--seed/seed <seed> (--seed/g' \
    -e "s|$out|<out>|g"
}

# run NAME ARGS...: one command, its output masked.
run() {
  local name=$1
  shift
  local status=0
  mkdir -p "$out/$name"
  "$dartcheck" "${@//@OUT@/$out/$name}" >"$out/$name.stdout" 2>"$out/$name.stderr" || status=$?
  {
    echo "\$ dartcheck $*" | mask
    mask <"$out/$name.stdout"
    echo "--- stderr"
    mask <"$out/$name.stderr"
    echo "--- exit $status"
  } >"$out/$name.out"
  rm "$out/$name.stdout" "$out/$name.stderr"
  # Written text files are masked the same way; others are kept as they are.
  find "$out/$name" -type f | while read -r f; do
    if grep -Iq . "$f"; then mask <"$f" >"$f.masked" && mv "$f.masked" "$f"; fi
  done
  rmdir "$out/$name" 2>/dev/null || true
}

for cat in "${catalogs[@]}"; do
  n=$(basename "$cat" | sed 's/\.[a-z]*$//')
  run "check-$n" check "$cat" --explain
  run "check-json-$n" check "$cat" --format json
  run "fuzz-$n" fuzz "$cat" --seed 1 --runs 300 --jobs 1
  run "fuzz-json-$n" fuzz "$cat" --seed 1 --runs 300 --jobs 1 --format json
  run "events-$n" events "$cat"
  run "report-$n" report "$cat" -o @OUT@/report
  run "compile-$n" compile "$cat" -o @OUT@/operations.hpp
done
run prove-seed prove catalogs/seed-operations.yaml --max-darts 6 --scheme-darts 4
run prove-embedding prove catalogs/embedding-operations.yaml --max-darts 6
run prove-events prove catalogs/event-operations.yaml --max-darts 6
run infer-quad-apply apply catalogs/seed-operations.yaml --rule quad-subdivision-jerboa --map cube --hook 0 -o @OUT@/quad-cube.yaml
run infer-quad infer --before cube --after "$out/infer-quad-apply/quad-cube.yaml" --orbit '<0,1,2>' -o @OUT@/inferred.yaml
run infer-edge-split infer --before polygon:3 --after polygon:6 --orbit '<0,1,2>' --format json
run recombine-cube recombine tests/data/cube-5-tets.mesh --cells hex,prism,pyramid -o @OUT@/cube.vtu
run recombine-gmsh recombine tests/data/gmsh-box-41.msh --cells hex,prism,pyramid --format json -o @OUT@/box.msh
if [ -n "$elephant" ]; then
  run recombine-elephant recombine "$elephant" -o @OUT@/elephant-hex.mesh
  run recombine-elephant-cells recombine "$elephant" --cells hex,prism,pyramid --format json
fi
echo "$(ls "$out"/*.out | wc -l) command outputs in $out"
