#!/usr/bin/env python3
"""Every machine-readable output of dartcheck parses and follows its schema.

Usage: validate_outputs.py DARTCHECK SOURCE_DIR WORK_DIR

Runs the commands below from SOURCE_DIR and checks each output:
JSON and JSONL documents against docs/schema/*.schema.json (python3-jsonschema,
draft 2020-12), SARIF against docs/schema/sarif-subset.schema.json and the OASIS
SARIF 2.1.0 schema (tests/data/sarif-2.1.0-rtm.5.json, draft-04), JUnit and
.jme as XML (xml.etree), YAML (baselines, converted catalogs) by reading them
back with dartcheck's own yaml-cpp reader. The hostile catalog's names hold
quotes, backslashes, newlines, control characters, an ESC sequence, U+FFFE
and invalid UTF-8; the expected decoded names below are derived by hand from
the YAML escapes in tests/data/hostile-names.yaml, not from dartcheck.
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import jsonschema

DARTCHECK, SOURCE, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(WORK, exist_ok=True)
SCHEMAS = os.path.join(SOURCE, "docs", "schema")
HOSTILE = "tests/data/hostile-names.yaml"
# YAML "r\"1\\\n\t\x07\e[31m\uFFFE" decoded by hand.
HOSTILE_RULE = 'r"1\\\n\t\x07\x1b[31m\ufffe'
# The plain scalar bad-\xff\xfe-utf8\xc3: invalid bytes become U+FFFD (one per maximal invalid run).
HOSTILE_RULE_2 = "bad-\ufffd-utf8\ufffd"
HOSTILE_MODEL = 'q\\m\x01\x1b\n\ufffe'

store = {}
for name in os.listdir(SCHEMAS):
    if name.endswith(".schema.json"):
        with open(os.path.join(SCHEMAS, name), encoding="utf-8") as f:
            schema = json.load(f)
        jsonschema.Draft202012Validator.check_schema(schema)
        store[schema["$id"]] = schema

failures = []


def validator(schema_id):
    schema = store[schema_id]
    resolver = jsonschema.RefResolver.from_schema(schema, store=store)
    return jsonschema.Draft202012Validator(schema, resolver=resolver)


def run(args, expect):
    p = subprocess.run([DARTCHECK] + args, cwd=SOURCE, capture_output=True)
    if p.returncode != expect:
        failures.append(f"{' '.join(args)}: exit {p.returncode}, expected {expect}\n{p.stderr.decode('utf-8', 'replace')[-2000:]}")
    return p.stdout


def check_json(args, expect, schema_id, jsonl=False):
    out = run(args, expect)
    docs = []
    try:
        text = out.decode("utf-8")  # strict: every output must be UTF-8
        lines = [l for l in text.splitlines() if l.strip()] if jsonl else [text]
        for line in lines:
            doc = json.loads(line)
            errors = sorted(validator(schema_id).iter_errors(doc), key=lambda e: list(e.path))
            for e in errors[:5]:
                failures.append(f"{' '.join(args)}: {schema_id}: {'/'.join(map(str, e.path))}: {e.message[:300]}")
            docs.append(doc)
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        failures.append(f"{' '.join(args)}: not valid {'JSONL' if jsonl else 'JSON'}: {e}")
    return docs


# The OASIS SARIF 2.1.0 schema (draft-04), shipped in tests/data: from the
# npm package @microsoft/jest-sarif 1.0.0-beta.0 (MIT),
# lib/schemas/sarif-2.1.0-rtm.5.json, the schema of the OASIS standard.
with open(os.path.join(SOURCE, "tests", "data", "sarif-2.1.0-rtm.5.json"), encoding="utf-8") as f:
    OASIS_SARIF = jsonschema.Draft4Validator(json.load(f))


def check_sarif(args, expect):
    """SARIF against dartcheck's subset schema and the OASIS one."""
    docs = check_json(args, expect, "https://dartcheck.invalid/schema/sarif-subset.schema.json")
    for doc in docs:
        for e in sorted(OASIS_SARIF.iter_errors(doc), key=lambda e: list(e.path))[:5]:
            failures.append(f"{' '.join(args)}: OASIS SARIF 2.1.0: {'/'.join(map(str, e.path))}: {e.message[:300]}")
    return docs


def check_xml(args, expect):
    out = run(args, expect)
    try:
        return ET.fromstring(out)
    except ET.ParseError as e:
        failures.append(f"{' '.join(args)}: not well-formed XML: {e}")
        return None


def expect_equal(what, got, want):
    if got != want:
        failures.append(f"{what}: got {got!r}, expected {want!r}")


# --- the hostile catalog, every format of every command that reads it ---
[doc] = check_json(["check", HOSTILE, "--format", "json"], 0, "https://dartcheck.invalid/schema/check.schema.json") or [None]
if doc:
    expect_equal("check json: rule names", [r["name"] for r in doc["rules"]], [HOSTILE_RULE, HOSTILE_RULE_2])
    expect_equal("check json: model name", doc["rules"][0]["model"], HOSTILE_MODEL)
    expect_equal("check json: says invalid UTF-8 was replaced", doc.get("replaced_invalid_utf8", 0) >= 1, True)
    expect_equal("check json: verdicts", [r["failures"] for r in doc["rules"]], [[], ["I(1)"]])
check_sarif(["check", HOSTILE, "--format", "sarif"], 0)
root = check_xml(["check", HOSTILE, "--format", "junit"], 0)
if root is not None:
    # XML 1.0 cannot carry U+0007, ESC, U+0001 or U+FFFE: each becomes U+FFFD.
    expect_equal("junit: test case names", [c.get("name") for c in root.iter("testcase")],
                 ['r"1\\\n\t\ufffd\ufffd[31m\ufffd', HOSTILE_RULE_2])
check_json(["fuzz", HOSTILE, "--runs", "50", "--seed", "1", "--format", "json"], 0, "https://dartcheck.invalid/schema/fuzz.schema.json")
lines = check_json(["fuzz", HOSTILE, "--runs", "50", "--seed", "1", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
expect_equal("fuzz jsonl: line types", [l.get("type") for l in lines], ["header", "rule", "rule", "summary"])
# Shards of the hostile catalog (2 of them, whatever their sizes) merge back
# into the unsharded run's document, names and all.
for command, extra, schema in [("check", [], "check"), ("fuzz", ["--runs", "50", "--seed", "1"], "fuzz"), ("prove", ["--max-darts", "3"], "prove")]:
    shard_files = []
    for k in range(2):
        lines = check_json([command, HOSTILE, *extra, "--shard", f"{k}/2", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
        shard_files.append(os.path.join(WORK, f"hostile-{command}-{k}.jsonl"))
        with open(shard_files[-1], "w", encoding="utf-8") as f:
            f.write("".join(json.dumps(l) + "\n" for l in lines))
    [merged] = check_json(["merge", *shard_files, "--format", "json"], 0, f"https://dartcheck.invalid/schema/{schema}.schema.json") or [None]
    if merged:
        expect_equal(f"{command} merged: rule names", [r["name"] for r in merged["rules"]], [HOSTILE_RULE, HOSTILE_RULE_2])
check_json(["prove", HOSTILE, "--max-darts", "3", "--format", "json"], 0, "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["events", HOSTILE, "--format", "json"], 0, "https://dartcheck.invalid/schema/events.schema.json")
report_dir = os.path.join(WORK, "hostile-report")
run(["report", HOSTILE, "-o", report_dir], 0)
with open(os.path.join(report_dir, "results.json"), "rb") as f:
    try:
        doc = json.loads(f.read().decode("utf-8"))
        for e in list(validator("https://dartcheck.invalid/schema/check.schema.json").iter_errors(doc))[:5]:
            failures.append(f"report results.json: {e.message[:300]}")
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        failures.append(f"report results.json: not valid JSON: {e}")
# compile's messages name rules and files through printable(): no raw
# control byte (here an ESC sequence in the output's name) reaches the
# terminal. The header itself is compiled by tests/compiler.
p = subprocess.run([DARTCHECK, "compile", HOSTILE, "-o", os.path.join(WORK, "hostile\x1b[31m.hpp")], cwd=SOURCE, capture_output=True)
if p.returncode != 0:
    failures.append(f"compile {HOSTILE}: exit {p.returncode}\n{p.stderr.decode('utf-8', 'replace')[-2000:]}")
if any((b < 0x20 and b != 0x0a) or b == 0x7f for b in p.stdout + p.stderr):
    failures.append(f"compile {HOSTILE}: raw control bytes in its messages: {(p.stdout + p.stderr)[:300]!r}")
# YAML written by dartcheck is read back by dartcheck (yaml-cpp) to the same verdicts.
baseline = os.path.join(WORK, "hostile-baseline.yaml")
run(["check", HOSTILE, "--write-baseline", baseline], 0)
run(["check", HOSTILE, "--baseline", baseline], 0)
converted = os.path.join(WORK, "hostile-converted.yaml")
run(["convert", HOSTILE, "-o", converted], 0)
[back] = check_json(["check", converted, "--format", "json"], 0, "https://dartcheck.invalid/schema/check.schema.json") or [None]
if back:
    # YAML 1.2 excludes U+FFFE from its printable set (c-printable) and
    # yaml-cpp's emitter writes U+FFFD for it; invalid bytes stay as read.
    expect_equal("converted catalog: rule names", [r["name"] for r in back["rules"]], [HOSTILE_RULE.replace("\ufffe", "\ufffd"), HOSTILE_RULE_2])

# --- real catalogs: every JSON document follows its schema ---
check_json(["check", "catalogs/seed-operations.yaml", "--format", "json"], 0, "https://dartcheck.invalid/schema/check.schema.json")
check_json(["check", "catalogs/embedding-operations.yaml", "--format", "json"], 0, "https://dartcheck.invalid/schema/check.schema.json")
# Jerboa expressions, read (terms) and opaque (reasons).
check_json(["check", "tests/data/jerboa-opaque-expression.jme", "--format", "json"], 0, "https://dartcheck.invalid/schema/check.schema.json")
check_json(["check", "../shared/jerboa-samples/JerboaRebuilt2.jme", "--format", "json", "--confirm-darts", "0"], 1,
           "https://dartcheck.invalid/schema/check.schema.json")
# Code scanning (issue 64): the failures the catalog records are suppressed
# (75 on the seed catalog: its 59 failing rules' conditions), a changed one
# is not; paths are relative to the repository's root, %SRCROOT%.
[doc] = check_sarif(["check", "catalogs/seed-operations.yaml", "--format", "sarif"], 0) or [None]
if doc:
    results = doc["runs"][0]["results"]
    expect_equal("sarif: every recorded failure suppressed", [len(r.get("suppressions", [])) for r in results], [1] * len(results))
    expect_equal("sarif: results", len(results), 75)
    expect_equal("sarif: the catalog's path", {r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for r in results},
                 {"catalogs/seed-operations.yaml"})
    expect_equal("sarif: %SRCROOT% is the repository", doc["runs"][0]["originalUriBaseIds"]["%SRCROOT%"]["uri"],
                 "file://" + os.path.realpath(SOURCE) + "/")
    expect_equal("sarif: help embedded", all(d["help"]["markdown"].startswith("### ") for d in doc["runs"][0]["tool"]["driver"]["rules"]), True)
[doc] = check_sarif(["check", "tests/data/wrong-verdict.yaml", "--format", "sarif"], 1) or [None]
if doc:
    unexpected = [r for r in doc["runs"][0]["results"] if "suppressions" not in r]
    expect_equal("sarif: a failure the catalog does not record is an open error", [r["level"] for r in unexpected] != [] and
                 all(r["level"] == "error" for r in unexpected), True)
check_json(["fuzz", "catalogs/event-operations.yaml", "--runs", "100", "--seed", "1", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json",
           jsonl=True)
check_json(["check", "catalogs/seed-operations.yaml", "--shard", "1/3", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["events", "catalogs/event-operations.yaml", "--shard", "1/2", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["recombine", "tests/data/cube-5-tets.mesh", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["query", "tests/data/cube-5-tets.mesh", "--hex", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["prove", "catalogs/seed-operations.yaml", "--shard", "2/3", "--max-darts", "3", "--format", "jsonl"], 0,
           "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["report", "catalogs/seed-operations.yaml", "-o", os.path.join(WORK, "shard-report"), "--prove", "3", "--shard", "0/3", "--format", "jsonl"], 0,
           "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
check_json(["prove", "catalogs/seed-operations.yaml", "--rule", "fig17-exchange", "--format", "json"], 0, "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["prove", "tests/data/wrong-verdict.yaml", "--format", "json"], 1, "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["prove", "catalogs/embedding-operations.yaml", "--rule", "triangulation-all-faces-pos/corner-copy", "--max-darts", "5", "--format", "json"], 0,
           "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["prove", "tests/data/embedding-readings.yaml", "--max-darts", "5", "--format", "json"], 0, "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["check", "catalogs/embedding-operations.yaml", "--solver", "--rule", "fig19b-triangulation-col/equal-terms", "--format", "json"], 0,
           "https://dartcheck.invalid/schema/check.schema.json")
check_json(["prove", "catalogs/event-operations.yaml", "--rule", "unsew2", "--format", "json"], 0, "https://dartcheck.invalid/schema/prove.schema.json")
check_json(["events", "catalogs/event-operations.yaml", "--format", "json"], 0, "https://dartcheck.invalid/schema/events.schema.json")
check_json(["events", "catalogs/event-operations.yaml", "--rule", "delete-edge", "--map", "cube", "--hook", "0", "--dynamic", "--format", "json"],
           0, "https://dartcheck.invalid/schema/events.schema.json")
check_json(["events", "catalogs/event-operations.yaml", "--rule", "sew2", "--map", "cube", "--hook", "0", "--hook", "1", "--format", "json"], 1,
           "https://dartcheck.invalid/schema/events.schema.json")
check_json(["events", "catalogs/seed-operations.yaml", "--rule", "insert-vertex-sewn-edge-one-side", "--map", "cube", "--hook", "0", "--format", "json"], 1,
           "https://dartcheck.invalid/schema/events.schema.json")
check_json(["query", "tests/data/cube-5-tets.mesh", "--hex", "--format", "json"], 0, "https://dartcheck.invalid/schema/query.schema.json")
VALIDATE = "https://dartcheck.invalid/schema/validate-map.schema.json"
check_json(["validate-map", "cube", "--format", "json"], 0, VALIDATE)
check_json(["validate-map", "tests/data/corrupt-square.yaml", "--format", "json"], 1, VALIDATE)
check_json(["validate-map", "../shared/jerboa-samples/cube.jba", "--format", "json"], 0, VALIDATE)
check_json(["recombine", "tests/data/cube-5-tets.mesh", "--strategy", "greedy", "--format", "json"], 0, "https://dartcheck.invalid/schema/recombine.schema.json")
check_json(["recombine", "tests/data/prism-3-tets.mesh", "--cells", "hex,prism,pyramid", "--format", "json"], 0, "https://dartcheck.invalid/schema/recombine.schema.json")
check_json(["infer", "--before", "polygon:3", "--after", "polygon:6", "--orbit", "<0,1,2>", "--kappa", "tests/data/kappa-edge-split.yaml",
            "--format", "json"], 0, "https://dartcheck.invalid/schema/infer.schema.json")
# An example that changes nothing: no rule, exit 1, still a valid document.
check_json(["infer", "--before", "polygon:4", "--after", "polygon:4", "--orbit", "<0,1>", "--format", "json"], 1, "https://dartcheck.invalid/schema/infer.schema.json")

# merge prints a shard's text: a shard is input, so an escape sequence
# planted in it reaches the terminal escaped (issue 62, item 3).
lines = check_json(["recombine", "tests/data/cube-5-tets.mesh", "--format", "jsonl"], 0, "https://dartcheck.invalid/schema/jsonl.schema.json", jsonl=True)
for l in lines:
    if l.get("type") == "input":
        l["input"]["text"] = "\x1b]0;owned\x07\x1b[31m" + l["input"]["text"]
hostile_shard = os.path.join(WORK, "escape-shard.jsonl")
with open(hostile_shard, "w", encoding="utf-8") as f:
    f.write("".join(json.dumps(l) + "\n" for l in lines))
merged = run(["merge", hostile_shard], 0)
expect_equal("merge: raw ESC bytes on stdout", b"\x1b" in merged, False)
expect_equal("merge: the escaped sequence shown", b"\\x1b[31m" in merged, True)

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
