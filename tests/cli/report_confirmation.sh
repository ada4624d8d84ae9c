#!/bin/sh
# report shows check's model-level confirmation (issue 64): for each rule
# below (two DPO rules and a scheme), the confirmation sentence that
# `check` prints under the rule is on the report's page, in the rule's
# section, and the verdict table has a confirmation column.
# Usage: report_confirmation.sh DARTCHECK WORK_DIR (from the source directory).
set -e
work=$2
rm -rf "$work"
mkdir -p "$work"
for rule in insert-vertex-free-edge/oriented-1 insert-vertex-sewn-edge/missing-1 fig21-scheme/missing-1; do
  line=$(COLUMNS=200 "$1" check catalogs/seed-operations.yaml --rule "$rule" 2>/dev/null | sed -n 's/^ *\(confirmed: .*\)$/\1/p')
  [ -n "$line" ] || { echo "check prints no confirmation for $rule"; exit 1; }
  "$1" -q report catalogs/seed-operations.yaml --rule "$rule" -o "$work" 2>/dev/null || [ $? -eq 1 ]
  grep -qF "Model-level confirmation (as check's): $line</p>" "$work/index.html" ||
    { echo "the report of $rule lacks check's line: $line"; exit 1; }
  grep -qF "<th>confirmation</th>" "$work/index.html" || { echo "no confirmation column for $rule"; exit 1; }
  echo "$rule: $line"
done
