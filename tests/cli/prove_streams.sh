#!/bin/sh
# prove on a terminal (issue 64): its status line is cleared before anything
# else is printed (it was left in place: "...up to 6 dartsinsert-vertex-...")
# and each rule's result is printed as it finishes, before the next rule's
# status line, not all at the end. A pseudo-terminal from util-linux's
# script(1) stands for the user's.
# Usage: prove_streams.sh DARTCHECK (from the source directory).
out=$(mktemp)
trap 'rm -f "$out"' EXIT
COLUMNS=100 script -qec "$1 prove catalogs/event-operations.yaml" "$out" >/dev/null 2>&1 || { echo "prove failed"; cat "$out"; exit 1; }
python3 - "$out" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8", errors="replace", newline="").read()
status = list(re.finditer(r"\[(\d+)/(\d+)\] [^\r\n]*?: asking Z3 for a host up to \d+ darts", text))
if len(status) < 2:
    sys.exit(f"fewer than two status lines on the terminal: {text!r}")
for m in status:  # every status line is cleared before other text follows
    if not text.startswith("\r\x1b[K", m.end()):
        sys.exit(f"status line not cleared: {text[m.start():m.end() + 40]!r}")
blocks = [m.start() for m in re.finditer(r"(?:^|\x1b\[K)[\w/-]+ \([0-9]-[go]map\):", text, re.M)]
if len(blocks) != int(status[0].group(2)):
    sys.exit(f"{len(blocks)} rule results for {status[0].group(2)} rules")
for k in range(1, len(status)):  # rule k's result comes before rule k+1's status
    if not blocks[k - 1] < status[k].start():
        sys.exit(f"rule {k}'s result was printed after rule {k + 1} started: not streamed")
print(f"{len(status)} status lines, each cleared; {len(blocks)} results, each before the next rule started")
PY
