#!/usr/bin/env bash
# README's first command on a machine with only the program's packages
# (issue 64): without the tests' packages (GTest, RapidCheck, CGAL,
# OpenMesh, Google Benchmark: hidden from CMake here) the project still
# configures, says which tests it left out, builds the dartcheck target
# alone (its man page with it), installs with `cmake --install`, and the
# installed binary runs the main job. The build compiles the whole program
# again (8.5 min on 2 cores without a warm ccache): ctest configures only,
# unless DARTCHECK_RUNTIME_BUILD=1; tests/cli/runtime_packages.sh checks
# that the program's sources include nothing from the tests' packages.
# Usage: runtime_only_build.sh SOURCE_DIR SCRATCH_DIR BUILD_TYPE SANITIZE
set -euo pipefail
source_dir=$1
scratch=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch"
hidden=()
for p in GTest rapidcheck CGAL OpenMesh benchmark; do hidden+=("-DCMAKE_DISABLE_FIND_PACKAGE_$p=ON"); done
configure=$(cmake -S "$source_dir" -B "$scratch/build" -DCMAKE_BUILD_TYPE="$3" -DDARTCHECK_SANITIZE="$4" "${hidden[@]}" 2>&1) ||
  fail "configure failed: $configure"
grep -q "tests not configured: GTest, rapidcheck, CGAL, OpenMesh not found" <<< "$(tr -s ' \n' ' ' <<< "$configure")" ||
  fail "configure does not say which test packages it misses: $configure"
[ ! -d "$scratch/build/tests" ] || fail "tests were configured without their packages"
if [ "${DARTCHECK_RUNTIME_BUILD:-0}" != 1 ]; then
  rm -rf "$scratch"
  echo "runtime-only build: configured without the tests' packages (DARTCHECK_RUNTIME_BUILD=1 also builds, installs and runs it)"
  exit 0
fi
cmake --build "$scratch/build" -j2 --target dartcheck > "$scratch/build.log" 2>&1 || fail "building dartcheck failed: $(tail -20 "$scratch/build.log")"
cmake --install "$scratch/build" --prefix "$scratch/prefix" > /dev/null || fail "cmake --install failed"
[ -x "$scratch/prefix/bin/dartcheck" ] || fail "no bin/dartcheck installed"
[ -f "$scratch/prefix/share/man/man1/dartcheck.1" ] || fail "no man page installed"
out=$("$scratch/prefix/bin/dartcheck" check "$source_dir/catalogs/seed-operations.yaml" 2>&1) || fail "the main job failed: $out"
grep -q -- "0 verdicts differ from the catalog" <<< "$out" || fail "the main job's summary is missing: $out"
echo "runtime-only build: configured without the tests' packages, built, installed, main job passed"
