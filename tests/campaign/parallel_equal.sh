#!/usr/bin/env bash
# Theorem (docs/scale.md): for deterministic settings (--runs, a seed, a
# resource limit rather than a time), the N shards of a run, merged, give
# the unsharded run's output. Checked here on the seed catalog for check,
# fuzz and prove, with 4 shards run by GNU parallel (scripts/campaign/
# parallel.sh) and with --jobs 2: the JSON documents are equal once the
# timing fields ("seconds", "static_ms", "wall_clock", "shard_seconds") are dropped, and SARIF equal
# byte for byte; events (3 shards) equal byte for byte as text and JSON;
# recombine on two meshes, one job each, gathered. Then merge's refusals: a missing, duplicated, unfinished
# or foreign shard, and a catalog changed since the shards ran.
# Usage: parallel_equal.sh DARTCHECK SOURCE_DIR WORK_DIR
set -euo pipefail
D=$1 SRC=$2 WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$SRC"
C=catalogs/seed-operations.yaml
fail=0

same_json() {  # label a b
  if ! python3 - "$2" "$3" <<'PY'
import json, sys
def norm(o):
    if isinstance(o, dict): return {k: norm(v) for k, v in o.items() if k not in ("seconds", "static_ms", "wall_clock", "shard_seconds")}
    if isinstance(o, list): return [norm(x) for x in o]
    return o
a, b = (norm(json.load(open(p))) for p in sys.argv[1:3])
if a != b:
    for k in a:
        if a.get(k) != b.get(k): print("differs at", k)
    sys.exit(1)
PY
  then echo "FAIL: $1: merged JSON differs from the single run" >&2; fail=1; fi
}

expect_exit() {  # status label pattern command...
  local status=$1 label=$2 pattern=$3; shift 3
  local rc=0
  "$@" > "$WORK/out.txt" 2> "$WORK/err.txt" || rc=$?
  if [ "$rc" -ne "$status" ] || ! grep -Eq -- "$pattern" "$WORK/err.txt"; then
    echo "FAIL: $label: exit $rc, expected $status and '$pattern' in:" >&2; cat "$WORK/err.txt" >&2; fail=1
  fi
}
expect_error() { expect_exit 2 "$@"; }

for run in "check" "fuzz --runs 300 --seed 7" "prove --max-darts 3"; do
  read -r -a args <<< "$run"
  name=${args[0]}
  "$D" "${args[0]}" $C "${args[@]:1}" --format json > "$WORK/$name.single.json" 2> /dev/null || true
  scripts/campaign/parallel.sh -n 4 -b "$D" -d "$WORK/$name-shards" -f json -- "${args[0]}" $C "${args[@]:1}" \
    > "$WORK/$name.merged.json" 2> "$WORK/$name.parallel.err" || { echo "FAIL: $name: parallel.sh exited $?" >&2; tail "$WORK/$name.parallel.err" >&2; fail=1; }
  same_json "$name, 4 shards by GNU parallel" "$WORK/$name.single.json" "$WORK/$name.merged.json"
  "$D" "${args[0]}" $C "${args[@]:1}" --format json --jobs 2 > "$WORK/$name.jobs.json" 2> /dev/null || true
  same_json "$name --jobs 2" "$WORK/$name.single.json" "$WORK/$name.jobs.json"
done
# events: no wall-clock fields, so text and JSON are equal byte for byte.
for format in text json; do
  "$D" events $C --format $format > "$WORK/events.single.$format"
  scripts/campaign/parallel.sh -n 3 -b "$D" -d "$WORK/events-shards" -f $format -- events $C > "$WORK/events.merged.$format" 2> /dev/null
  cmp "$WORK/events.single.$format" "$WORK/events.merged.$format" || { echo "FAIL: events: merged $format differs" >&2; fail=1; }
done
"$D" check $C --format sarif > "$WORK/single.sarif"
"$D" merge "$WORK"/check-shards/shard-*.jsonl --format sarif > "$WORK/merged.sarif" 2> /dev/null
cmp "$WORK/single.sarif" "$WORK/merged.sarif" || { echo "FAIL: check: merged SARIF differs" >&2; fail=1; }

S=$WORK/fuzz-shards
expect_error "a missing shard" "shard 2/4 is missing" "$D" merge "$S/shard-0.jsonl" "$S/shard-1.jsonl" "$S/shard-3.jsonl"
expect_error "a shard given twice" "shard 1/4 is also" "$D" merge "$S"/shard-*.jsonl "$S/shard-1.jsonl"
head -n 3 "$S/shard-2.jsonl" > "$WORK/cut.jsonl"
expect_error "an unfinished shard" "no summary line: shard 2/4 did not finish" "$D" merge "$S/shard-0.jsonl" "$S/shard-1.jsonl" "$WORK/cut.jsonl" "$S/shard-3.jsonl"
"$D" fuzz $C --runs 300 --seed 8 --shard 2/4 --format jsonl > "$WORK/seed8.jsonl" 2> /dev/null || true
expect_error "a shard of another seed" "not a shard of the same run" "$D" merge "$S/shard-0.jsonl" "$S/shard-1.jsonl" "$WORK/seed8.jsonl" "$S/shard-3.jsonl"
expect_error "a shard of another command" "not a shard of the same run" "$D" merge "$S/shard-0.jsonl" "$WORK/check-shards/shard-1.jsonl"
sed 's/"applications":[0-9]*,"hosts"/"applications":-1,"hosts"/g' "$S/shard-1.jsonl" > "$WORK/damaged.jsonl"
expect_error "a damaged record" "damaged.jsonl:[0-9]*:1: error: record.fuzz.applications" "$D" merge "$S/shard-0.jsonl" "$WORK/damaged.jsonl" "$S/shard-2.jsonl" "$S/shard-3.jsonl"
cp tests/data/wrong-verdict.yaml "$WORK/catalog.yaml" && "$D" check "$WORK/catalog.yaml" --shard 0/1 --format jsonl > "$WORK/moved.jsonl" 2> /dev/null || true
echo "# changed" >> "$WORK/catalog.yaml"
expect_error "a changed catalog" "not the catalog the shards ran on" "$D" merge "$WORK/moved.jsonl"

# merge --incomplete (issue 62): the cut and the missing shard merge, the
# result names how many rules finished and the exit status is 130.
expect_incomplete() { expect_exit 130 "$@"; }
expect_incomplete "--incomplete, a cut shard" "^interrupted: [0-9]+ of 82 rules finished" \
  "$D" merge --incomplete "$S/shard-0.jsonl" "$S/shard-1.jsonl" "$WORK/cut.jsonl" "$S/shard-3.jsonl"
expect_incomplete "--incomplete, a missing shard" "^interrupted: [0-9]+ of 82 rules finished" \
  "$D" merge --incomplete "$S/shard-0.jsonl" "$S/shard-1.jsonl" "$S/shard-3.jsonl"
# Another format version: refused, not read as if it were this one.
sed 's/"format_version":[0-9]*/"format_version":99/' "$S/shard-1.jsonl" > "$WORK/version99.jsonl"
expect_error "an unknown format version" "version99.jsonl:1:1: error: format_version 99: this dartcheck reads version" \
  "$D" merge "$S/shard-0.jsonl" "$WORK/version99.jsonl" "$S/shard-2.jsonl" "$S/shard-3.jsonl"

# recombine and query on many inputs, one GNU parallel job each: the merged
# document holds each input's own document, in the order of their paths.
meshes=(tests/data/two-tets.mesh tests/data/cube-5-tets.mesh)
parallel --will-cite "$D recombine {} --format jsonl > $WORK/recombine-{#}.jsonl" ::: "${meshes[@]}"
"$D" merge "$WORK"/recombine-*.jsonl --format json > "$WORK/recombine.merged.json" 2> /dev/null
for k in 0 1; do "$D" recombine "${meshes[$k]}" --format json > "$WORK/recombine-single-$k.json"; done
if ! python3 - "$WORK/recombine.merged.json" "$WORK/recombine-single-1.json" "$WORK/recombine-single-0.json" <<'PY'
import json, sys
def norm(o):
    if isinstance(o, dict): return {k: norm(v) for k, v in o.items() if k not in ("seconds", "tets_per_second", "peak_mib")}
    if isinstance(o, list): return [norm(x) for x in o]
    return o
merged = json.load(open(sys.argv[1]))
singles = [norm(json.load(open(p))) for p in sys.argv[2:]]
sys.exit(not (merged["inputs"] == 2 and [norm(r) for r in merged["runs"]] == singles))
PY
then echo "FAIL: recombine: the merged runs differ from the single runs (in path order)" >&2; fail=1; fi
expect_error "an input given twice" "is also the input of" "$D" merge "$WORK/recombine-1.jsonl" "$WORK/recombine-1.jsonl"
"$D" recombine tests/data/folded-tets.mesh --format jsonl > "$WORK/recombine-folded.jsonl" 2> /dev/null || true
expect_error "a run that failed" "recombine-folded.jsonl: error: empty: no header line" "$D" merge "$WORK"/recombine-*.jsonl
rm "$WORK/recombine-folded.jsonl"
# A run a signal stopped says so by its status (130): it used to merge as 0.
sed 's/"summary":{"status":[0-9]*}/"summary":{"status":130}/' "$WORK/recombine-2.jsonl" > "$WORK/recombine-stopped.jsonl"
expect_error "an interrupted input run" "recombine-stopped.jsonl:3:1: error: this shard was interrupted" "$D" merge "$WORK/recombine-1.jsonl" "$WORK/recombine-stopped.jsonl"
expect_incomplete "--incomplete, an interrupted input run" "^incomplete: 1 of 2 runs finished" "$D" merge --incomplete "$WORK/recombine-1.jsonl" "$WORK/recombine-stopped.jsonl"
exit $fail
