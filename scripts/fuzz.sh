#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan+UBSan) and runs each on
# seed corpora assembled from the catalogs, the test data,
# ../shared/jerboa-samples and Debian's mesh packages. Prints one line per
# target (executions, coverage, corpus) and exits non-zero on any finding; a
# crashing input is left in BUILD/findings/<target>/.
#   scripts/fuzz.sh smoke [BUILD]     CI: a fixed seed and a fixed number of
#                                     executions per target (about 20 s
#                                     each), whatever the machine's speed
#   scripts/fuzz.sh SECONDS [BUILD]   a campaign: e.g. 600 s per target
# FUZZ_TARGETS="fuzz_shard fuzz_tet_mesh" limits a run to those targets.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-smoke}
build=${2:-build-fuzz}
root=$PWD

CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDARTCHECK_FUZZ=ON -DDARTCHECK_TESTS=OFF -DDARTCHECK_BENCH=OFF >/dev/null
cmake --build "$build" -j2 --target fuzz_targets >/dev/null

# Seed corpora: copies, so that what a run adds stays in the build folder.
seeds() {  # target, files...
  local dir="$build/corpus/$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$dir/" || true; done
}
jerboa=$root/../shared/jerboa-samples
seeds fuzz_catalog catalogs/*.yaml tests/data/*.yaml
seeds fuzz_yaml_map tests/data/corrupt-square.yaml tests/data/hostile-*.yaml
seeds fuzz_jba "$jerboa"/*.jba
seeds fuzz_jme "$jerboa"/*.jme tests/data/*.jme
seeds fuzz_term fuzz/seeds/term/*
seeds fuzz_jerboa_expression fuzz/seeds/jerboa/*
seeds fuzz_word fuzz/seeds/word/*
seeds fuzz_shard fuzz/seeds/shard/*
seeds fuzz_tet_mesh tests/data/*.mesh tests/data/*.msh
for n in tests/data/*.node; do
  [ -f "${n%.node}.ele" ] && { cat "$n"; printf '\n%%%%\n'; cat "${n%.node}.ele"; } > "$build/corpus/fuzz_tet_mesh/$(basename "$n").pair" || true
done
# The side-file harness reads a selector byte first: 0 baseline, 1 kappa.
mkdir -p "$build/corpus/fuzz_side_files"
for f in tests/data/*baseline*.yaml; do { printf '0'; cat "$f"; } > "$build/corpus/fuzz_side_files/$(basename "$f")"; done
for f in tests/data/*kappa*.yaml; do { printf '1'; cat "$f"; } > "$build/corpus/fuzz_side_files/$(basename "$f")"; done
for f in tests/data/*-after.yaml; do { printf '2'; cat "$f"; } > "$build/corpus/fuzz_side_files/$(basename "$f")"; done
# The mesh harness reads a model byte first.
mkdir -p "$build/corpus/fuzz_mesh"
for f in catalogs/meshes/*.off tests/data/*.off /usr/share/assimp/models/OFF/*.off; do
  [ -f "$f" ] && { printf '0'; cat "$f"; } > "$build/corpus/fuzz_mesh/$(basename "$f")" || true
done

# The smoke's executions per target: what 20 s gave on a busy 2-core VM.
declare -A smoke_runs=([fuzz_yaml_map]=40000 [fuzz_catalog]=2500 [fuzz_jme]=25000 [fuzz_jba]=10000 [fuzz_mesh]=50000 [fuzz_term]=200000 [fuzz_jerboa_expression]=400000 [fuzz_word]=300000 [fuzz_shard]=15000 [fuzz_tet_mesh]=50000 [fuzz_side_files]=20000)
declare -A dict=([fuzz_yaml_map]=yaml [fuzz_catalog]=yaml [fuzz_jme]=jme [fuzz_jba]=jba [fuzz_mesh]=off [fuzz_term]=term [fuzz_jerboa_expression]=jerboa [fuzz_word]=term [fuzz_shard]=jsonl [fuzz_tet_mesh]=tet [fuzz_side_files]=yaml)
status=0
all_targets="fuzz_yaml_map fuzz_catalog fuzz_jme fuzz_jerboa_expression fuzz_jba fuzz_mesh fuzz_term fuzz_word fuzz_shard fuzz_tet_mesh fuzz_side_files"
for t in ${FUZZ_TARGETS:-$all_targets}; do
  [ -n "${smoke_runs[$t]:-}" ] || { echo "fuzz.sh: no target $t (targets: $all_targets)" >&2; exit 2; }
  mkdir -p "$build/findings/$t"
  log="$root/$build/findings/$t.log"
  if [ "$mode" = smoke ]; then budget=(-seed=1 -runs="${smoke_runs[$t]}"); else budget=(-max_total_time="$mode"); fi
  if (cd "$build/findings/$t" && "$root/$build/fuzz/$t" "$root/$build/corpus/$t" -dict="$root/fuzz/dict/${dict[$t]}.dict" \
        "${budget[@]}" -max_len=65536 -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 >"$log" 2>&1); then
    result=ok
  else
    result=FINDING
    status=1
  fi
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo "?")
  corpus=$(ls "$build/corpus/$t" | wc -l)
  secs=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "$t: $result, $execs executions ($secs/s), coverage $cov edges, corpus $corpus inputs"
  [ "$result" = ok ] || tail -40 "$log"
done
exit $status
