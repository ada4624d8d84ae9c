#!/usr/bin/env bash
# Installs dartcheck's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing (and prints nothing) when everything is present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  # Compiler output cached across builds and clones (CI time).
  ccache
  libgtest-dev libgmock-dev librapidcheck-dev
  libz3-dev libfmt-dev libyaml-cpp-dev libcli11-dev libpugixml-dev
  libgraphviz-dev graphviz
  # JSON outputs are built with nlohmann::json (valid for any names); their
  # JSON Schemas (docs/schema/) are checked by python3-jsonschema in tests.
  nlohmann-json3-dev python3-jsonschema
  # The HTML report's test: headless Chromium screenshots the page, libpng
  # reads the screenshot.
  chromium libpng-dev
  libbenchmark-dev
  # The man page that `cmake --install` installs, made from --help.
  help2man
  # Exact rationals for the orientation predicate of the recombination
  # (querymodify/orientation.cpp), when its floating-point filter is unsure.
  libgmp-dev
  # The libFuzzer harnesses (fuzz/, scripts/fuzz.sh): clang and its runtime.
  clang libclang-rt-14-dev
  # Oracles, peers and real data for tests and benchmarks only.
  libcgal-dev libcgal-demo geomview assimp-testmodels libopenmesh-dev
  # Tetrahedral meshes of CGAL's surfaces for the tet -> hex recombination.
  tetgen
  # Campaigns (docs/scale.md): GNU parallel runs shards in the tests; Slurm
  # (with munge) runs the job-array script on a one-node cluster.
  parallel slurm-wlm munge
  # The signal tests find and signal shard processes (pgrep, pkill, kill -PGID)
  # and start a run in a process group of its own (setsid).
  procps util-linux
)

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
