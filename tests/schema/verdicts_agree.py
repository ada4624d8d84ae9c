#!/usr/bin/env python3
"""check, fuzz (fixed --runs), prove and report give the same verdict for
every rule of a catalog: the same failing conditions, the same recorded
verdict and the same comparison with it (issue 36: one result model).

Usage: verdicts_agree.py DARTCHECK SOURCE_DIR WORK_DIR

A Jerboa .jme records no verdicts: the baseline `check --write-baseline`
writes is given to every command. Each command's JSON is read (check,
fuzz, prove) or report's results.json.
"""
import json
import os
import subprocess
import sys

DARTCHECK, SOURCE, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(WORK, exist_ok=True)
CATALOGS = ["catalogs/seed-operations.yaml", "catalogs/embedding-operations.yaml", "../shared/jerboa-samples/JerboaRebuilt2.jme"]
failures = []


def run(args):
    p = subprocess.run([DARTCHECK] + args, cwd=SOURCE, capture_output=True)
    if p.returncode != 0:
        failures.append(f"{' '.join(args)}: exit {p.returncode}\n{p.stderr.decode('utf-8', 'replace')[-1500:]}")
    return p.stdout.decode("utf-8")


def verdicts(doc):
    return {r["name"]: (r["failures"], r["recorded"]["failures"], r["matches_record"], r["unsound"]) for r in doc["rules"]}


for k, catalog in enumerate(CATALOGS):
    extra = []
    if catalog.endswith(".jme"):
        baseline = os.path.join(WORK, f"baseline-{k}.yaml")
        run(["check", catalog, "--write-baseline", baseline, "--format", "json"])
        extra = ["--baseline", baseline]
    results = {}
    results["check"] = verdicts(json.loads(run(["check", catalog, "--format", "json"] + extra)))
    results["fuzz"] = verdicts(json.loads(run(["fuzz", catalog, "--runs", "200", "--seed", "1", "--format", "json"] + extra)))
    results["prove"] = verdicts(json.loads(run(["prove", catalog, "--max-darts", "4", "--scheme-darts", "3", "--format", "json"] + extra)))
    report_dir = os.path.join(WORK, f"report-{k}")
    run(["report", catalog, "-o", report_dir] + extra)
    with open(os.path.join(report_dir, "results.json"), encoding="utf-8") as f:
        results["report"] = verdicts(json.load(f))
    names = list(results["check"])
    if len(names) < 10:
        failures.append(f"{catalog}: only {len(names)} rules checked")
    for command, got in results.items():
        if list(got) != names:
            failures.append(f"{catalog}: {command} reports rules {sorted(set(got) ^ set(names))} differently from check")
        for name in names:
            if name in got and got[name] != results["check"][name]:
                failures.append(f"{catalog}: rule {name}: {command} says {got[name]}, check says {results['check'][name]}")
    print(f"{catalog}: {len(names)} rules, verdicts of check, fuzz, prove and report compared")

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
