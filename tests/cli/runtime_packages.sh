#!/usr/bin/env bash
# The program's package set (issue 64): every system header the product's
# libraries and the dartcheck binary include, and every shared library the
# binary loads, belongs to a Debian package that `scripts/install-deps.sh`
# (without --tests) installs, directly or as a dependency. The owners come
# from dpkg, the dependencies from apt-cache: neither from the script.
# Usage: runtime_packages.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build=$2
fail() { echo "FAIL: $*" >&2; exit 1; }

# The runtime=( ... ) array of the script, comments dropped.
runtime=$(sed -n '/^runtime=(/,/^)/p' "$source_dir/scripts/install-deps.sh" | sed -e 's/#.*//' -e 's/runtime=(//' -e 's/)//' | tr -s ' \n' '\n' | grep -v '^$')
[ -n "$runtime" ] || fail "no runtime=( ... ) set in scripts/install-deps.sh"
# shellcheck disable=SC2086
closure=$(apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks --no-replaces --no-enhances $runtime |
          grep -v '^ ' | sed 's/:.*//' | sort -u)

owner_of() {  # the package owning one path, or nothing
  dpkg -S "$1" 2>/dev/null | head -1 | sed -e 's/: .*//' -e 's/,.*//' -e 's/:.*//' || true
}
owners() {  # the packages owning the paths read from stdin, one per line
  local paths found path pkg
  paths=$(cat)
  # One dpkg call for all (a call per path takes a minute); the paths
  # dpkg lists under another spelling (merged /usr, symbolic links) one by one.
  # shellcheck disable=SC2086
  found=$(dpkg -S $paths 2>/dev/null || true)
  printf '%s\n' "$found" | sed -n 's/^\([^ ]*\): \(\/.*\)$/\1 \2/p' | sed -e 's/,[^ ]*//' -e 's/:[^ ]*//' | awk '{print $1}'
  for path in $paths; do
    grep -q -- ": $path\$" <<< "$found" && continue
    pkg=$(owner_of "$path")
    [ -n "$pkg" ] || case $path in
      /usr/lib/*) pkg=$(owner_of "${path#/usr}") ;;
      /lib/*) pkg=$(owner_of "/usr$path") ;;
    esac
    [ -n "$pkg" ] || pkg=$(owner_of "$(readlink -f "$path")")
    [ -n "$pkg" ] || fail "$path belongs to no Debian package"
    printf '%s\n' "$pkg"
  done
}

layers="core rewriting io checkers generators proofs events inference querymodify reports analysis campaign compiler cli"
deps=()
for layer in $layers; do
  for d in "$build/$layer"/CMakeFiles/*.dir; do
    [ -d "$d" ] && deps+=("$d")
  done
done
headers=$(find "${deps[@]}" -name '*.o.d' -exec cat {} + | tr ' \\' '\n\n' | grep '^/usr/' | sed 's/:$//' | sort -u)
[ -n "$headers" ] || fail "no dependency files under $build (build the dartcheck target first)"
libraries=$(ldd "$build/cli/dartcheck" | sed -n 's/.*=> \(\/[^ ]*\) .*/\1/p' | sort -u)
[ -n "$libraries" ] || fail "ldd found no libraries of $build/cli/dartcheck"

header_packages=$(printf '%s\n' "$headers" | owners | sort -u)
library_packages=$(printf '%s\n' "$libraries" | owners | sort -u)
for p in $header_packages $library_packages; do
  grep -qx -- "$p" <<< "$closure" || fail "$p (a header or library of dartcheck) is not installed by scripts/install-deps.sh without --tests, nor by its dependencies"
done
echo "runtime packages: $(printf '%s\n' "$headers" | wc -l) headers from $(printf '%s\n' "$header_packages" | wc -l) packages, $(printf '%s\n' "$libraries" | wc -l) libraries from $(printf '%s\n' "$library_packages" | wc -l) packages, all within the $(printf '%s\n' "$closure" | wc -l) packages the runtime set brings"
