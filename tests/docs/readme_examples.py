#!/usr/bin/env python3
"""Runs the examples of README's quick start so that they cannot go stale.

Each line of the ```sh block under "## Quick start" that starts with
build/cli/dartcheck is run from the repository's root (with the binary
under test), after dropping its trailing "# comment". It must exit 0, and
each "# ..." line that follows it must appear in its output, with runs of
spaces matching any spacing and decimals ("0.04" ms) matching any decimal.

usage: readme_examples.py DARTCHECK REPO WORKDIR
"""
import os
import re
import subprocess
import sys


def quick_start(readme):
    text = open(readme, encoding="utf-8").read()
    section = text.split("## Quick start", 1)[1]
    return section.split("```sh\n", 1)[1].split("```", 1)[0].splitlines()


def expectation(line):
    """The regex a '# output' line must match in the output."""
    parts = re.split(r"(\s+|\d+\.\d+)", line)
    out = ""
    for p in parts:
        if not p:
            continue
        if p.isspace():
            out += r"\s+"
        elif re.fullmatch(r"\d+\.\d+", p):
            out += r"\d+\.\d+"
        else:
            out += re.escape(p)
    return out


def main():
    dartcheck, repo, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    examples = []  # [command, [expected lines]]
    for line in quick_start(os.path.join(repo, "README.md")):
        if line.startswith("build/cli/dartcheck"):
            examples.append([re.sub(r"\s+#.*$", "", line), []])
        elif line.startswith("# ") and examples:
            examples[-1][1].append(line[2:])
    if len(examples) < 5:
        print(f"only {len(examples)} examples found in README's quick start")
        return 1
    failures = 0
    for command, expected in examples:
        # Outputs the examples write under /tmp go to WORKDIR instead.
        # (before the binary goes in: its own path may be under /tmp).
        run = command.replace("/tmp/", work.rstrip("/") + "/").replace("build/cli/dartcheck", dartcheck, 1)
        done = subprocess.run(run, shell=True, cwd=repo, capture_output=True, text=True, timeout=300)
        output = done.stdout + done.stderr
        problems = [] if done.returncode == 0 else [f"exit {done.returncode}"]
        problems += [f"no line matching '{e}'" for e in expected if not re.search(expectation(e), output)]
        print(f"{'FAIL' if problems else 'ok'}: {command}" + "".join(f"\n  {p}" for p in problems))
        if problems:
            print("  output:\n    " + "\n    ".join(output.splitlines()[-15:]))
            failures += 1
    print(f"{len(examples)} README examples, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
