#!/usr/bin/env bash
# `cmake --install` (issue 39): the binary, a man page that documents every
# command the binary lists, and a bash completion that completes commands,
# options (also a command's and the global ones after a global option's
# value) and the choices of --format, all read back from the binary itself.
# Usage: install_test.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
build=$1
prefix=$2
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" > /dev/null
export PATH="$prefix/bin:$PATH"
fail() { echo "FAIL: $*" >&2; exit 1; }

[ -x "$prefix/bin/dartcheck" ] || fail "no bin/dartcheck"
page="$prefix/share/man/man1/dartcheck.1"
[ -f "$page" ] || fail "no man page"
commands=$(dartcheck --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}')
[ "$(printf '%s\n' "$commands" | wc -l)" -ge 15 ] || fail "dartcheck --help lists too few commands: $commands"
for c in $commands; do
  grep -q "^\.SS $c\$" "$page" || fail "the man page has no section for $c"
done
grep -q -- "--write-baseline" "$page" || fail "the man page lacks check's --write-baseline"

# shellcheck source=/dev/null
source "$prefix/share/bash-completion/completions/dartcheck"
complete_words() {  # the words of the line, the last being completed
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _dartcheck
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' '
}
expect() {
  local want=$1
  shift
  local got
  got=$(complete_words "$@")
  [ "$got" = "$want" ] || fail "completing '$*': got '$got', expected '$want'"
}
expect "check compile convert " dartcheck c
expect "fuzz " dartcheck --limit-darts 5 fu
expect "--format " dartcheck check --form
expect "json jsonl junit " dartcheck check --format j
expect "--limit-darts " dartcheck check --limit-da
expect "--write-baseline " dartcheck check --write-b
echo "install: man page documents $(printf "%s\n" "$commands" | wc -l) commands; completion ok"
