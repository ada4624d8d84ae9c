#!/usr/bin/env bash
# Clean Release builds of the product (the dartcheck target, -j2) of two
# revisions, alternated round by round so that both see the same noise of
# a shared machine: the "build time does not grow" measure of issues 36
# and 63. ccache is off: every translation unit is compiled.
# Usage: scripts/build-time.sh BEFORE_REV [AFTER_REV (default HEAD)] [ROUNDS (default 2)]
set -euo pipefail
before=$1
after=${2:-HEAD}
rounds=${3:-2}
root=$(git rev-parse --show-toplevel)
scratch=$(mktemp -d)
trap 'git -C "$root" worktree remove --force "$scratch/before" > /dev/null 2>&1 || true;
      git -C "$root" worktree remove --force "$scratch/after" > /dev/null 2>&1 || true; rm -rf "$scratch"' EXIT
git -C "$root" worktree add -f --detach "$scratch/before" "$before" > /dev/null 2>&1
git -C "$root" worktree add -f --detach "$scratch/after" "$after" > /dev/null 2>&1
for round in $(seq 1 "$rounds"); do
  for side in before after; do
    rm -rf "$scratch/build"
    cmake -S "$scratch/$side" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release -DDARTCHECK_TESTS=OFF -DDARTCHECK_BENCH=OFF -DDARTCHECK_CCACHE=OFF > /dev/null
    start=$(date +%s.%N)
    cmake --build "$scratch/build" -j2 --target dartcheck > /dev/null
    end=$(date +%s.%N)
    printf '%s (%s) round %d: %.1f s, %d translation units\n' "$side" "$(git -C "$scratch/$side" rev-parse --short HEAD)" "$round" \
      "$(awk -v s="$start" -v e="$end" 'BEGIN { print e - s }')" "$(find "$scratch/build" -name '*.o' | wc -l)"
  done
done
