#!/usr/bin/env bash
# Installs dartcheck's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing (and prints nothing) when everything is present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libgtest-dev libgmock-dev librapidcheck-dev
  libz3-dev libfmt-dev libyaml-cpp-dev libcli11-dev libpugixml-dev
  libgraphviz-dev graphviz
  libbenchmark-dev
  # Oracles, peers and real data for tests and benchmarks only.
  libcgal-dev libcgal-demo geomview assimp-testmodels
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
