#!/bin/sh
# Every printed hint can be pasted as is (issue 64 item 7): the commands
# that `check --explain` prints under a scheme's model-level
# counterexample, and the one the fuzz table prints for a counterexample
# written without -o, are run verbatim (in a scratch directory, with
# `dartcheck` on the PATH, as a user's shell would), and each writes the
# counterexample the hint was printed for: same origin ("found in ...") and
# the files the hint names. The replay line the fuzz run then prints is
# pasted too and applies the rule to the host (exit 1: H breaks a
# constraint).
# Usage: hints_paste.sh DARTCHECK SOURCE_DIR
set -e
dartcheck=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
ln -s "$dartcheck" "$work/bin/dartcheck"
PATH="$work/bin:$PATH"
export PATH
cd "$work"
catalog="$src/catalogs/seed-operations.yaml"
fail() { echo "FAIL: $*"; exit 1; }

# The hint's command: the text after "run: " on the line below `pattern`.
paste_and_run() {  # NAME HINT ORIGIN
  cmd=$2
  [ -n "$cmd" ] || fail "$1: no hint printed"
  rm -rf DIR
  status=0
  sh -c "$cmd" > out.txt 2> err.txt || status=$?
  [ "$status" -le 1 ] || fail "$1: the hint exits $status: $cmd ($(cat err.txt))"
  file=$(ls DIR/*.counterexample.yaml 2>/dev/null | head -1)
  [ -n "$file" ] || fail "$1: the hint wrote no counterexample: $cmd"
  grep -qF "$3" "$file" || fail "$1: the hint's counterexample was not found in '$3': $(grep -i found "$file")"
  replay=$(sed -n 's/^ *replay: //p' out.txt | head -1)
  [ -n "$replay" ] || fail "$1: the pasted run printed no replay line"
  status=0
  sh -c "$replay" > /dev/null 2>&1 || status=$?
  [ "$status" -eq 1 ] || fail "$1: its replay exits $status, expected 1 (H breaks a constraint): $replay"
  echo "$1: pasted, wrote $(basename "$file") (found in $3), replay exits 1"
}

for rule in fig21-scheme/missing-1 face-extrusion-omap/broken-word; do
  text=$(COLUMNS=100 dartcheck check "$catalog" --rule "$rule" --explain 2>/dev/null || true)
  origin=$(printf '%s\n' "$text" | sed -n 's/^ *host: //p' | head -1)
  hint=$(printf '%s\n' "$text" | sed -n 's/^.*to write it with the match, H and a replay command, run: //p' | head -1)
  paste_and_run "check --explain $rule" "$hint" "$origin"
done

rule=insert-vertex-free-edge/sewn-new-darts
text=$(COLUMNS=100 dartcheck fuzz "$catalog" --rule "$rule" --runs 200 --seed 3 2>/dev/null || true)
origin=$(printf '%s\n' "$text" | sed -n 's/^ *found in //p' | head -1)
hint=$(printf '%s\n' "$text" | sed -n 's/^.*to write the host, the match and H with a replay command, run: //p' | head -1)
paste_and_run "fuzz $rule" "$hint" "$origin"
