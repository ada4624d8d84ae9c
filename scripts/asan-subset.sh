#!/usr/bin/env bash
# CI's sanitizer step (issue 38): an ASan + UBSan build of the command and
# of the reader, writer, report, campaign and compiled-operation tests, then
# every CLI test except the long engine runs (the whole suite under the
# sanitizers takes about 31 minutes on 2 cores, past CI's budget; it is run
# by hand and recorded in RELIABILITY.md). The readers are also fuzzed under
# the sanitizers by scripts/fuzz.sh smoke.
#   scripts/asan-subset.sh [BUILD]   (default build-asan)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-asan}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DDARTCHECK_SANITIZE=ON -DDARTCHECK_BENCH=OFF >/dev/null
cmake --build "$build" -j2 --target dartcheck test_io test_jerboa test_reports test_campaign test_compiled test_compiled_mutant test_compiled_shortcut_mutant >/dev/null
suites='MapYaml|Mesh|MeshWriter|GmshMsh|Catalog|HostileInput|TetMeshIo|Jme|Jba|RuleDot|RuleSvg|MapSvg|Render|CounterexampleDot|Shard|ResultRecord|CompiledOperations'
# Over 30 s each under the sanitizers: fuzzing, proving and recombining
# whole catalogs and meshes, and every example of docs/cli.md (which fuzzes
# the embedding catalog and the Jerboa modelers with values: minutes under
# ASan), which the Release suite runs.
long='cli\.(docs_cli_examples|check_solver_baseline_.*|recombine_elephant|fuzz_jme|fuzz_events_.*|outputs_follow_schemas|verdicts_agree_across_commands|fuzz_embedding_catalog|prove_catalog|fuzz_subdivision_catalog)|campaign\.(parallel_equal|slurm_array)'
ctest --test-dir "$build" -j2 --output-on-failure -R "^(cli\.|compiled\.|campaign\.|($suites)\.)" -E "^($long)$"
