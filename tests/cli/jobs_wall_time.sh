#!/bin/sh
# fuzz --jobs 2 prints the run's wall-clock time (issue 64): it printed the
# shards' seconds summed, "12.9 s (3570/s)" for a 7.0 s run, so --jobs
# looked slower than one job. The JSON summary's "seconds" must not exceed
# the wall time measured here plus 0.5 s (start-up and rounding); the old
# code printed 6.55 s for a 3.54 s run.
# Usage: jobs_wall_time.sh DARTCHECK (from the source directory).
out=$(mktemp)
trap 'rm -f "$out"' EXIT
start=$(date +%s.%N)
"$1" fuzz catalogs/seed-operations.yaml --runs 3000 --seed 1 --jobs 2 --format json >"$out" 2>/dev/null
end=$(date +%s.%N)
python3 - "$out" "$start" "$end" <<'PY'
import json, sys
printed = json.load(open(sys.argv[1]))["summary"]["seconds"]
wall = float(sys.argv[3]) - float(sys.argv[2])
print(f"printed {printed:.2f} s, wall {wall:.2f} s")
sys.exit(0 if printed <= wall + 0.5 else 1)
PY
