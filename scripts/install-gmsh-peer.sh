#!/usr/bin/env bash
# Installs gmsh's recombinator as a peer for bench/bench_gmsh_recombination
# (issue 40): Debian's libgmsh 4.8.4 and its private headers, and the one
# header the packages do not ship, contrib/domhex/yamakawa.h, from the
# gmsh source package (a deb-src line for Debian's archive is added).
# Not needed to build or test dartcheck; CMake builds the benchmark when it
# finds the header in DIR (default /usr/local/src/gmsh).
#
#   scripts/install-gmsh-peer.sh [DIR]
set -euo pipefail

dir=${1:-/usr/local/src/gmsh}
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)

sources=/etc/apt/sources.list.d/dartcheck-debian-src.sources
if ! grep -rqs "deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  "${sudo_cmd[@]}" tee "$sources" > /dev/null <<'X'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
X
fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
  dpkg-dev xz-utils libgmsh-dev libgmsh-private-headers-dev

# The source of the very version installed (the header must match the library).
version=$(dpkg-query -W -f='${Version}' libgmsh-dev)
work=$(mktemp -d)
chmod 755 "$work"  # apt's download user writes there
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get source --download-only "gmsh=$version" > /dev/null)
"${sudo_cmd[@]}" mkdir -p "$dir"
"${sudo_cmd[@]}" tar -xJf "$work"/gmsh_*.orig.tar.xz -C "$dir" --strip-components=3 --wildcards '*/contrib/domhex/yamakawa.h'
echo "gmsh peer: $dir/yamakawa.h (gmsh $version)"
