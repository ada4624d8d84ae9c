#!/bin/sh
# Signals to a --jobs run (issue 62): the parent forwards them to its
# shards, starts none after, reaps them, removes its directory and prints
# the merge of what finished, exit 130. Three ways a signal comes:
#   term   SIGTERM to the parent alone (a scheduler's time-out)
#   group  SIGINT to the whole process group (Ctrl-C at a terminal)
#   twice  the shards are stopped (SIGSTOP), then SIGTERM twice 2.2 s
#          apart: the parent kills them and exits 130 without a merge
# Usage: jobs_signal.sh MODE DARTCHECK CATALOG (from the source directory).
# The catalog is read through a link of this run's own, so that any shard
# left running afterwards is found by its command line. kill(1) of procps
# signals a process group (dash's built-in does not take -PID).
mode=$1
dartcheck=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$(realpath "$(dirname "$3")")" "$work/catalogs"
catalog="$work/catalogs/$(basename "$3")"
mkdir "$work/tmp"
TMPDIR="$work/tmp" setsid "$dartcheck" fuzz "$catalog" --runs 100000000 --jobs 2 --seed 1 >"$work/out" 2>"$work/err" &
pid=$!
# Wait until two shards run.
n=0
until [ "$(pgrep -f -- "$catalog.*--shard" | wc -l)" -ge 2 ] || [ "$n" -ge 600 ]; do sleep 0.1; n=$((n + 1)); done
[ "$n" -lt 600 ] || { cat "$work/err"; echo "the shards did not start"; /bin/kill -KILL -- "-$pid"; exit 1; }
sleep 1
case $mode in
  term) kill -TERM "$pid" ;;
  group) /bin/kill -INT -- "-$pid" ;;
  twice)
    pkill -STOP -f -- "$catalog.*--shard"
    kill -TERM "$pid"
    sleep 2.2
    kill -TERM "$pid" ;;
esac
n=0
while kill -0 "$pid" 2>/dev/null && [ "$n" -lt 200 ]; do sleep 0.1; n=$((n + 1)); done
if kill -0 "$pid" 2>/dev/null; then
  /bin/kill -KILL -- "-$pid"
  echo "still running 20 s after the signal"
  exit 1
fi
wait "$pid"
rc=$?
cat "$work/out" "$work/err"
fail=0
[ "$rc" -eq 130 ] || { echo "exit status $rc, expected 130"; fail=1; }
left=$(pgrep -f -- "$catalog" | wc -l)
[ "$left" -eq 0 ] || { echo "$left shard processes still running"; pkill -KILL -f -- "$catalog"; fail=1; }
[ -z "$(ls -A "$work/tmp")" ] || { echo "left in TMPDIR:"; ls -A "$work/tmp"; fail=1; }
case $mode in
  twice)
    grep -q "^interrupted again: the shards were killed; nothing is merged" "$work/err" || { echo "no 'interrupted again' line"; fail=1; } ;;
  *)
    grep -Eq "^interrupted: [0-9]+ of 82 rules finished" "$work/err" || { echo "no 'interrupted: N of 82 rules finished' line"; fail=1; }
    grep -Eq "^[0-9]+ rules?: .* consistent" "$work/out" || { echo "no merged summary line"; fail=1; } ;;
esac
exit $fail
