#!/usr/bin/env bash
# The Slurm path end to end (docs/scale.md): a one-node cluster started for
# the test (scripts/campaign/slurm-local.sh), scripts/campaign/slurm.sh
# submits 4 shards of check and of fuzz as a job array and a dependent
# merge job, whose output must equal the single run's (JSON without the
# wall-clock fields); sbatch --test-only accepts the generated scripts.
# The cluster is stopped after. Exit 77 (skipped) without root or Slurm.
# Usage: slurm_array.sh DARTCHECK SOURCE_DIR WORK_DIR
set -euo pipefail
D=$(realpath "$1") SRC=$2 WORK=$3
if [ "$(id -u)" -ne 0 ] || ! command -v slurmctld > /dev/null || ! command -v munged > /dev/null; then
  echo "skipped: needs root and Debian's slurm-wlm and munge" >&2
  exit 77
fi
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$SRC"
cluster=$WORK/cluster
trap 'scripts/campaign/slurm-local.sh stop "$cluster"' EXIT
eval "$(scripts/campaign/slurm-local.sh start "$cluster")"
fail=0
C=catalogs/seed-operations.yaml
for run in "check" "fuzz --runs 300 --seed 7"; do
  read -r -a args <<< "$run"
  name=${args[0]}
  "$D" "${args[@]:0:1}" $C "${args[@]:1}" --format json > "$WORK/$name.single.json" 2> /dev/null || true
  timeout 120 scripts/campaign/slurm.sh -n 4 -d "$WORK/$name" -f json -b "$D" -w -- "${args[0]}" $C "${args[@]:1}" > "$WORK/$name.merged.json" \
    || { echo "FAIL: $name: slurm.sh exited $?" >&2; fail=1; }
  python3 - "$WORK/$name.single.json" "$WORK/$name.merged.json" <<'PY' || { echo "FAIL: $name: the merged Slurm run differs from the single run" >&2; fail=1; }
import json, sys
def norm(o):
    if isinstance(o, dict): return {k: norm(v) for k, v in o.items() if k not in ("seconds", "static_ms", "wall_clock", "shard_seconds")}
    if isinstance(o, list): return [norm(x) for x in o]
    return o
a, b = (norm(json.load(open(p))) for p in sys.argv[1:3])
sys.exit(a != b)
PY
done
scripts/campaign/slurm.sh -n 8 -d "$WORK/test-only" -b "$D" -T -- prove $C --max-darts 4 2> "$WORK/test-only.err" \
  || { echo "FAIL: sbatch --test-only refused the scripts:" >&2; cat "$WORK/test-only.err" >&2; fail=1; }
exit $fail
