#!/usr/bin/env python3
"""Runs the examples of README's quick start so that they cannot go stale.

Each line of the ```sh block under "## Quick start" that starts with
build/cli/dartcheck is run from the repository's root (with the binary
under test), after dropping its trailing "# comment". It must exit 0, and
each "# ..." line that follows it must appear in its output, in order, as
tests/docs/cli_examples.py matches the examples of docs/cli.md.

usage: readme_examples.py DARTCHECK REPO WORKDIR
"""
import os
import re
import sys

from cli_examples import run_examples


def quick_start(readme):
    text = open(readme, encoding="utf-8").read()
    section = text.split("## Quick start", 1)[1]
    return section.split("```sh\n", 1)[1].split("```", 1)[0].splitlines()


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
    # Outputs the examples write under /tmp go to WORKDIR instead (before
    # the binary goes in: its own path may be under /tmp).
    found = [(f"README quick start {k + 1}", c.replace("/tmp/", work.rstrip("/") + "/").replace("build/cli/dartcheck", dartcheck, 1), shown)
             for k, (c, shown) in enumerate(examples)]
    return 1 if run_examples(found, repo, dict(os.environ)) else 0

if __name__ == "__main__":
    sys.exit(main())
