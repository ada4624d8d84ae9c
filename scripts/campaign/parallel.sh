#!/usr/bin/env bash
# A dartcheck campaign run by GNU parallel (docs/scale.md): the N shards of
# one command (check, fuzz, prove or report) on this machine's cores, or on
# the hosts of --sshlogin, then `dartcheck merge` into one result.
#
#   scripts/campaign/parallel.sh [-n SHARDS] [-j JOBS] [-S SSHLOGINS] [-d DIR] [-f FORMAT] [-o OUT] [-b DARTCHECK] \
#       -- COMMAND CATALOG [OPTIONS...]
#
#   -n  shards (default: the number of cores)      -j  shards at once per host (default: one per core)
#   -S  GNU parallel's --sshlogin (e.g. 8/alice@node1,8/node2): every host
#       must see dartcheck, the catalog and DIR at the same paths (a shared
#       file system, as on a cluster)
#   -d  where the shard files go (default: a new directory under /tmp)
#   -f  merged output: text, json, sarif, junit or html (default text)
#   -o  the html page's directory (with -f html)
#   -b  the dartcheck binary (default: dartcheck on PATH)
#
# The shards' exit statuses (1 a mismatch, 3 a soundness bug) are verdicts
# that the merge reports again; a shard that failed otherwise leaves an
# unfinished file, which the merge refuses, naming it. Exit: the merge's.
set -euo pipefail

shards=$(nproc) jobs="" sshlogin="" dir="" format=text out="" dartcheck=dartcheck
while getopts "n:j:S:d:f:o:b:" opt; do
  case $opt in
    n) shards=$OPTARG ;; j) jobs=$OPTARG ;; S) sshlogin=$OPTARG ;; d) dir=$OPTARG ;;
    f) format=$OPTARG ;; o) out=$OPTARG ;; b) dartcheck=$OPTARG ;;
    *) sed -n '6,16p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ "${1:-}" = "--" ] && shift
if [ $# -lt 2 ]; then sed -n '6,16p' "$0" >&2; exit 2; fi
command -v parallel > /dev/null || { echo "parallel.sh: GNU parallel is not installed (apt-get install parallel)" >&2; exit 2; }
dir=${dir:-$(mktemp -d /tmp/dartcheck-campaign-XXXXXX)}
mkdir -p "$dir"

# One shell command line per shard: the arguments quoted once for the shell
# that parallel starts (locally or through ssh).
quoted=$(printf '%q ' "$dartcheck" "$@")
options=(--will-cite --halt never)
[ -n "$jobs" ] && options+=(-j "$jobs")
[ -n "$sshlogin" ] && options+=(-S "$sshlogin")
echo "parallel.sh: $shards shards of '$*' into $dir" >&2
parallel "${options[@]}" "$quoted --shard {}/$shards --format jsonl > $(printf '%q' "$dir")/shard-{}.jsonl" ::: $(seq 0 $((shards - 1))) || true

merge=("$dartcheck" merge --format "$format")
[ -n "$out" ] && merge+=(-o "$out")
exec "${merge[@]}" "$dir"/shard-*.jsonl
