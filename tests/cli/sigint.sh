#!/bin/sh
# Ctrl-C during a long command (issue 38): SIGINT after DELAY seconds must
# end the command within 20 s (WITHIN in the environment: fewer) with exit
# status 130 and an output matching REGEX (grep -E): what it finished, and
# that it was interrupted.
#   sigint.sh DELAY REGEX DARTCHECK ARGS...   (run from the source directory)
# DELAY is seconds, or after:PATTERN to send the signal once the output has
# a line matching PATTERN (grep -E; at most 120 s): a fixed delay can fall
# before the work it means to interrupt on a slow (sanitizer) build.
# With REPEAT=2 in the environment the signal is sent twice back to back, as
# timeout(1) does (to the command, then to its process group): still one
# request, which must not kill the command before it writes what it finished.
delay=$1
regex=$2
shift 2
out=$(mktemp)
"$@" >"$out" 2>&1 &
pid=$!
case $delay in
  after:*)
    pattern=${delay#after:}
    n=0
    until grep -Eq "$pattern" "$out" || [ "$n" -ge 1200 ] || ! kill -0 "$pid" 2>/dev/null; do sleep 0.1; n=$((n + 1)); done
    grep -Eq "$pattern" "$out" || { cat "$out"; echo "no line matching '$pattern' to wait for"; kill -KILL "$pid" 2>/dev/null; exit 1; } ;;
  *) sleep "$delay" ;;
esac
kill -INT "$pid"
[ "${REPEAT:-1}" -eq 2 ] && kill -INT "$pid"
within=${WITHIN:-20}
n=0
while kill -0 "$pid" 2>/dev/null && [ "$n" -lt $((within * 10)) ]; do sleep 0.1; n=$((n + 1)); done
if kill -0 "$pid" 2>/dev/null; then
  kill -KILL "$pid"
  cat "$out"
  echo "still running $within s after SIGINT"
  exit 1
fi
wait "$pid"
rc=$?
cat "$out"
found=0
grep -Eq "$regex" "$out" && found=1
rm -f "$out"
[ "$found" -eq 1 ] || { echo "no line matching '$regex'"; exit 1; }
[ "$rc" -eq 130 ] || { echo "exit status $rc, expected 130"; exit 1; }
