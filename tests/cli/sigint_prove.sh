#!/bin/sh
# Ctrl-C during `prove` (issue 38): Z3 used to take SIGINT itself, answer
# "unknown (rlimit reached)" and let the run go on (minutes at larger
# --max-darts, then exit 0). Now the running query is interrupted through
# Z3's context, the finished rules are printed and the exit status is 130.
# One rule at --max-darts 60: its C(0,2) query runs for minutes, so the
# signal arrives inside Z3 (with Z3's own ctrl_c handler this test fails).
#   sigint_prove.sh DARTCHECK   (run from the source directory)
out=$(mktemp)
"$1" prove catalogs/seed-operations.yaml --rule insert-vertex-free-edge/sewn-new-darts --max-darts 60 >"$out" 2>&1 &
pid=$!
sleep 3
kill -INT "$pid"
n=0
while kill -0 "$pid" 2>/dev/null && [ "$n" -lt 200 ]; do sleep 0.1; n=$((n + 1)); done
if kill -0 "$pid" 2>/dev/null; then
  kill -KILL "$pid"
  echo "prove still running 20 s after SIGINT"
  exit 1
fi
wait "$pid"
rc=$?
cat "$out"
grep -q "^interrupted during the solver queries of insert-vertex-free-edge/sewn-new-darts" "$out" || { echo "no 'interrupted during the solver queries' line: the query was not interrupted"; exit 1; }
[ "$rc" -eq 130 ] || { echo "exit status $rc, expected 130"; exit 1; }
