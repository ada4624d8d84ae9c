#!/usr/bin/env bash
# Installs dartcheck's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing (and prints nothing) when everything is present.
# scripts/install-deps.sh           what dartcheck needs to build and run
# scripts/install-deps.sh --tests   that, and what its tests, benchmarks,
#                                   fuzzing and campaigns need (CI)
set -euo pipefail

case "${1:-}" in
  "") with_tests=false ;;
  --tests) with_tests=true ;;
  *) echo "usage: scripts/install-deps.sh [--tests]" >&2; exit 2 ;;
esac

# The program: tests/cli/runtime_packages.sh checks that every header it
# includes and every library it loads comes from these or their dependencies.
runtime=(
  build-essential cmake pkg-config
  # Compiler output cached across builds and clones (CI time).
  ccache
  libz3-dev libfmt-dev libyaml-cpp-dev libcli11-dev libpugixml-dev
  # Pictures through libgvc; the graphviz package registers its plugins.
  libgraphviz-dev graphviz
  # JSON outputs are built with nlohmann::json (valid for any names).
  nlohmann-json3-dev
  # The man page that `cmake --install` installs, made from --help.
  help2man
  # Exact rationals for the orientation predicate of the recombination
  # (querymodify/orientation.cpp), when its floating-point filter is unsure.
  libgmp-dev
)
tests=(
  libgtest-dev libgmock-dev librapidcheck-dev
  # The JSON Schemas of the outputs (docs/schema/) are checked by
  # python3-jsonschema.
  python3-jsonschema
  # The HTML report's test: headless Chromium screenshots the page, libpng
  # reads the screenshot.
  chromium libpng-dev
  libbenchmark-dev
  # The libFuzzer harnesses (fuzz/, scripts/fuzz.sh): clang and its runtime.
  clang libclang-rt-14-dev
  # Oracles, peers and real data for tests and benchmarks only.
  libcgal-dev libcgal-demo geomview assimp-testmodels libopenmesh-dev
  # Tetrahedral meshes of CGAL's surfaces for the tet -> hex recombination.
  tetgen
  # Independent readers of the meshes recombine writes (VTK, gmsh, medit),
  # and gmsh's own tetrahedral meshes as its input (tests/cli/mesh_outputs.py).
  gmsh python3-meshio
  # Campaigns (docs/scale.md): GNU parallel runs shards in the tests; Slurm
  # (with munge) runs the job-array script on a one-node cluster.
  parallel slurm-wlm munge
  # The signal tests find and signal shard processes (pgrep, pkill, kill -PGID)
  # and start a run in a process group of its own (setsid).
  procps util-linux
  # The man page's test renders it in UTF-8 and ASCII.
  groff-base
)
packages=("${runtime[@]}")
$with_tests && packages+=("${tests[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

$with_tests || exit 0
# Images that exclude /usr/share/doc from installs drop CGAL's mesh archive,
# which the tests read: take it out of the package itself.
# The package ships it in libcgal-dev's documentation folder.
cgal_data=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -f "$cgal_data" ]; then
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download libcgal-demo >/dev/null 2>&1 && dpkg-deb --fsys-tarfile libcgal-demo_*.deb | tar -x ".$cgal_data")
  "${sudo_cmd[@]}" install -D -m 644 "$tmp$cgal_data" "$cgal_data"
  rm -rf "$tmp"
fi
