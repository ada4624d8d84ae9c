#!/usr/bin/env bash
# A dartcheck campaign as a Slurm job array (docs/scale.md): task K of the
# array runs shard K/N of one command (check, fuzz, prove or report); a
# merge job, dependent on the whole array, merges the shards into one
# result. Writes the two batch scripts into DIR (read them, or submit them
# yourself) and submits them.
#
#   scripts/campaign/slurm.sh [-n SHARDS] [-d DIR] [-f FORMAT] [-o OUT] [-b DARTCHECK] [-p PARTITION] [-t TIME] [-w | -T] \
#       -- COMMAND CATALOG [OPTIONS...]
#
#   -n  shards, one array task each (default 16)    -d  shard files, logs, scripts (default ./dartcheck-campaign)
#   -f  merged output: text, json, sarif, junit or html (default text), in DIR/merged.FORMAT
#   -o  the html page's directory (with -f html)     -b  dartcheck binary (default: the one on PATH, made absolute)
#   -p  partition    -t  time limit per task (sbatch --time, e.g. 1:00:00)
#   -w  wait for the merge job and print its output  -T  only ask Slurm whether it would run them (sbatch --test-only)
#
# DIR, the catalog and dartcheck must be visible at the same paths on every
# node (a shared file system). The merge runs after every task ends, even
# failed ones (afterany): it names a shard that did not finish.
set -euo pipefail

shards=16 dir=dartcheck-campaign format=text out="" dartcheck="" partition="" limit="" wait=0 test_only=0
while getopts "n:d:f:o:b:p:t:wT" opt; do
  case $opt in
    n) shards=$OPTARG ;; d) dir=$OPTARG ;; f) format=$OPTARG ;; o) out=$OPTARG ;; b) dartcheck=$OPTARG ;;
    p) partition=$OPTARG ;; t) limit=$OPTARG ;; w) wait=1 ;; T) test_only=1 ;;
    *) sed -n '8,18p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ "${1:-}" = "--" ] && shift
if [ $# -lt 2 ]; then sed -n '8,18p' "$0" >&2; exit 2; fi
dartcheck=$(realpath "${dartcheck:-$(command -v dartcheck)}")
mkdir -p "$dir" && dir=$(realpath "$dir")
q() { printf '%q ' "$@"; }

common="#SBATCH --chdir=$(q "$PWD")"
[ -n "$partition" ] && common+=$'\n'"#SBATCH --partition=$partition"
[ -n "$limit" ] && common+=$'\n'"#SBATCH --time=$limit"
cat > "$dir/shards.sbatch" <<SCRIPT
#!/bin/bash
#SBATCH --job-name=dartcheck-shard
#SBATCH --array=0-$((shards - 1))
#SBATCH --ntasks=1
#SBATCH --output=$dir/shard-%a.err
$common
# Shard \$SLURM_ARRAY_TASK_ID of $shards: its lines, which the merge job reads.
exec $(q "$dartcheck" "$@")--shard "\$SLURM_ARRAY_TASK_ID/$shards" --format jsonl > "$dir/shard-\$SLURM_ARRAY_TASK_ID.jsonl"
SCRIPT
merge_args=(merge --format "$format")
[ -n "$out" ] && merge_args+=(-o "$(realpath -m "$out")")
cat > "$dir/merge.sbatch" <<SCRIPT
#!/bin/bash
#SBATCH --job-name=dartcheck-merge
#SBATCH --ntasks=1
#SBATCH --output=$dir/merged.$format
#SBATCH --error=$dir/merge.err
$common
exec $(q "$dartcheck" "${merge_args[@]}")$dir/shard-*.jsonl
SCRIPT

if [ $test_only -eq 1 ]; then
  sbatch --test-only "$dir/shards.sbatch"
  sbatch --test-only "$dir/merge.sbatch"
  exit 0
fi
array=$(sbatch --parsable "$dir/shards.sbatch")
array=${array%%;*}
echo "slurm.sh: array job $array ($shards shards), scripts and shard files in $dir" >&2
if [ $wait -eq 1 ]; then
  rc=0
  sbatch --parsable --wait --dependency=afterany:"$array" "$dir/merge.sbatch" > /dev/null || rc=$?
  cat "$dir/merged.$format"
  cat "$dir/merge.err" >&2
  exit $rc
fi
merge=$(sbatch --parsable --dependency=afterany:"$array" "$dir/merge.sbatch")
echo "slurm.sh: merge job ${merge%%;*} writes $dir/merged.$format when the array ends" >&2
