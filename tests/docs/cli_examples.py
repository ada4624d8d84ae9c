#!/usr/bin/env python3
"""Runs every example of docs/cli.md so that the reference cannot go stale.

An example is a fenced block holding lines that start with "$ ": each such
line is a shell command, the lines after it (up to the next "$ ") are what
it prints. The commands run in order, in one scratch copy of the tree
(catalogs/, tests/, scripts/ linked, ../shared beside it, docs/img/ and
every output its own), with `dartcheck` on PATH meaning the binary under
test; stdout and stderr are read as one stream. A command must exit 0, or the status its "# exits N" comment names.
Its shown lines must appear in its output in the order shown, where
  - a line "..." stands for lines left out,
  - "..." inside a line stands for any text,
  - runs of spaces match any spacing, and a decimal ("0.04" ms, "5.216" s)
    matches any decimal: timings vary, counts do not.

usage: cli_examples.py DARTCHECK REPO WORKDIR ELEPHANT_OFF
(ELEPHANT_OFF: CGAL's elephant.off, which the recombine example tetrahedralizes)
"""
import os
import re
import shutil
import subprocess
import sys


def examples(markdown):
    """[(line number, command, [shown lines])] of every "$ " block."""
    out = []
    fenced = False
    current = None  # the example whose output the next lines show
    for number, line in enumerate(open(markdown, encoding="utf-8").read().splitlines(), 1):
        if line.startswith("```"):
            fenced, current = not fenced, None
        elif fenced and line.startswith("$ "):
            current = (number, line[2:], [])
            out.append(current)
        elif current is not None and line.strip():
            current[2].append(line)
    return out


def pattern(line):
    """The regex a shown line must match within one output line."""
    out = ""
    for part in re.split(r"(\.\.\.|\s+|\d+\.\d+)", line.strip()):
        if not part:
            continue
        if part == "...":
            out += ".*"
        elif part.isspace():
            out += r"\s+"
        elif re.fullmatch(r"\d+\.\d+", part):
            out += r"\d+\.\d+"
        else:
            out += re.escape(part)
    return re.compile(out)


def missing(shown, output):
    """The first shown line not found, in order, in output; None if all are."""
    lines = output.splitlines()
    at = 0
    for s in shown:
        if s.strip() == "...":
            continue
        p = pattern(s)
        while at < len(lines) and not p.search(lines[at]):
            at += 1
        if at == len(lines):
            return s
        at += 1
    return None


def run_examples(found, cwd, env):
    """Runs each (label, command, shown lines) in cwd and prints ok or FAIL
    with what went wrong; returns the number that failed (also README's
    quick start, tests/docs/readme_examples.py)."""
    failures = 0
    for label, command, shown in found:
        m = re.search(r"#\s*exits (\d+)\s*$", command)
        status = int(m.group(1)) if m else 0
        # stdout and stderr in one stream, in the order a terminal shows them
        done = subprocess.run(command, shell=True, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              errors="replace", timeout=600)
        problems = [] if done.returncode == status else [f"exit {done.returncode}, expected {status}"]
        lost = missing(shown, done.stdout)
        if lost is not None:
            problems.append(f"no line matching, in order: {lost.strip()}")
        print(f"{'FAIL' if problems else 'ok'}: {label}: {command}" + "".join(f"\n  {p}" for p in problems))
        if problems:
            print("  output:\n    " + "\n    ".join(done.stdout.splitlines()[-20:]))
            failures += 1
    print(f"{len(found)} examples, {failures} failed")
    return failures


def scratch_tree(repo, work, elephant):
    """A directory that looks like the repository to the examples."""
    shutil.rmtree(work, ignore_errors=True)
    main = os.path.join(work, "main")
    os.makedirs(os.path.join(main, "docs", "img"))
    for d in ("catalogs", "tests", "scripts"):
        os.symlink(os.path.join(repo, d), os.path.join(main, d))
    os.symlink(os.path.realpath(os.path.join(repo, "..", "shared")), os.path.join(work, "shared"))
    shutil.copy(elephant, os.path.join(main, "elephant.off"))
    return main


def main():
    dartcheck, repo, work, elephant = sys.argv[1:5]
    cwd = scratch_tree(os.path.realpath(repo), os.path.realpath(work), elephant)
    bin_dir = os.path.join(os.path.realpath(work), "bin")
    os.makedirs(bin_dir, exist_ok=True)
    os.symlink(os.path.realpath(dartcheck), os.path.join(bin_dir, "dartcheck"))
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"])
    found = examples(os.path.join(repo, "docs", "cli.md"))
    if len(found) < 30:
        print(f"only {len(found)} examples found in docs/cli.md")
        return 1
    return 1 if run_examples([(f"docs/cli.md:{n}", c, shown) for n, c, shown in found], cwd, env) else 0

if __name__ == "__main__":
    sys.exit(main())
