#!/usr/bin/env bash
# `cmake --install` (issue 39): the binary, a man page that documents every
# command the binary lists, and a bash completion that completes commands,
# options (also a command's and the global ones after a global option's
# value) and the choices of --format, all read back from the binary itself.
# Rule and map names complete from the catalog on the line, models, cells
# and every option's choices from the binary (issue 64).
# Usage: install_test.sh BUILD_DIR SCRATCH_DIR SOURCE_DIR
set -euo pipefail
build=$1
prefix=$2
source_dir=$3
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
# A conventional page (issue 64): its sections, and the Greek letters of the
# help texts in UTF-8 with ASCII fallbacks (help2man alone wrote '??').
for section in "EXIT STATUS" ENVIRONMENT EXAMPLES "SEE ALSO"; do
  grep -q "^\.SH \"\?$section\"\?\$" "$page" || fail "the man page has no $section section"
done
if grep -q '??' "$page"; then fail "the man page has '??' for a character"; fi
ascii=$(groff -man -Tascii -P-cbou -rLL=200n "$page" 2>/dev/null)
utf8=$(groff -man -Tutf8 -P-cbou -rLL=200n "$page" 2>/dev/null)
grep -q -- "the kappa file" <<< "$ascii" || fail "the ASCII page lacks the kappa fallback"
grep -q -- "boundary (eps), interior (~eps) or no-link (<->)" <<< "$ascii" || fail "the ASCII page lacks the epsilon fallbacks"
grep -q -- "the κ file" <<< "$utf8" || fail "the UTF-8 page lacks κ"
grep -q -- "boundary (ε), interior (ε̄) or no-link (↔)" <<< "$utf8" || fail "the UTF-8 page lacks ε, ε̄ or ↔"
grep -q -- "^ *130 *interrupted" <<< "$utf8" || fail "EXIT STATUS does not list 130"
# --help lists the commands before the options, the input limits last.
order=$(dartcheck --help | grep -n -e '^Subcommands:' -e '^Options:' -e '^Input limits:' | cut -d: -f2 | tr '\n' ',')
[ "$order" = "Subcommands,Options,Input limits," ] || fail "--help lists its parts as $order"

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
events=$source_dir/catalogs/event-operations.yaml
mkdir -p "$prefix/empty" && cd "$prefix/empty"  # --map also completes files: none here
expect "delete-edge " dartcheck events "$events" --rule del
expect "collapse-edge " dartcheck events --orbit "<0>" "$events" --rule co
expect "grid-2x2 grid-3x3 grid: " dartcheck apply "$events" --rule sew2 --map grid
expect "cube " dartcheck apply "$events" --rule sew2 --map cu
expect "3-closed-gmap 3-gmap 3-omap 3-open-omap " dartcheck validate-map cube --model 3
expect "hex,prism hex,prism,pyramid " dartcheck recombine x.mesh --cells hex,pr
expect "global greedy " dartcheck recombine x.mesh --strategy g
expect "vertices words " dartcheck recombine x.mesh --search ""
expect " " dartcheck check /nonexistent.yaml --rule a  # nothing (printf prints one empty line)
echo "install: man page documents $(printf "%s\n" "$commands" | wc -l) commands; completion ok"
