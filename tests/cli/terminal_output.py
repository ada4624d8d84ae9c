#!/usr/bin/env python3
"""--quiet, --color and the terminal width (issue 39), end to end.

Statements tested:
- --quiet prints nothing on stdout in text format and no progress on
  stderr; failures (MISMATCH lines) still reach stderr; the exit status is
  unchanged.
- --color always colours stdout and stderr's "error:", never and auto off a
  terminal do not; on a terminal auto colours unless NO_COLOR is set; always
  wins over NO_COLOR (no-color.org: the user's explicit choice).
- check's, fuzz's, events', prove's and run's text fits the width: COLUMNS, else the terminal's (a pty of 72
  columns), else 100; a line may pass it only when it is one unbreakable word
  or a diagnostic (file:line:column: error: ..., one line for its parsers)
  or a replay command (one line to copy) or the closing summary line.

usage: terminal_output.py DARTCHECK REPO
"""
import fcntl
import re
import os
import pty
import struct
import subprocess
import sys
import termios

dartcheck, repo = sys.argv[1:3]
problems = []
ESC = "\x1b["


def run(args, env=None):
    e = dict(os.environ)
    e.pop("NO_COLOR", None)
    e.pop("COLUMNS", None)
    e.update(env or {})
    return subprocess.run([dartcheck] + args, cwd=repo, env=e, capture_output=True, text=True)


def run_pty(args, columns, env=None):
    """stdout and stderr on one pseudo-terminal of `columns` columns."""
    e = dict(os.environ)
    e.pop("NO_COLOR", None)
    e.pop("COLUMNS", None)
    e["TERM"] = "xterm"
    e.update(env or {})
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 40, columns, 0, 0))
    p = subprocess.Popen([dartcheck] + args, cwd=repo, env=e, stdout=slave, stderr=slave, stdin=subprocess.DEVNULL)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    p.wait()
    os.close(master)
    return p.returncode, b"".join(chunks).decode("utf-8", "replace").replace("\r\n", "\n")


def expect(cond, what):
    if not cond:
        problems.append(what)


def fits(text, width, what):
    for line in text.splitlines():
        plain = line
        while ESC in plain:  # drop colour codes: they take no columns
            k = plain.index(ESC)
            plain = plain[:k] + plain[plain.index("m", k) + 1:]
        # A diagnostic (error or note) stays on one line for the tools that
        # parse it, a replay command or a command to run for the mouse that
        # copies it.
        # The closing summary ("82 rules, ...") is one line for the logs that grep it.
        summary = re.match(r"\d+ rules?([,:] | \()", plain)
        if len(plain) > width and len(plain.split()) > 1 and ": error: " not in plain and ": note: " not in plain and "replay: " not in plain and "run: dartcheck " not in plain and not summary:
            problems.append(f"{what}: line of {len(plain)} columns over {width}: {plain!r}")


SEED = "catalogs/seed-operations.yaml"
WRONG = "tests/data/wrong-verdict.yaml"

r = run(["check", SEED, "--quiet"])
expect(r.returncode == 0 and r.stdout == "" and r.stderr == "", f"check --quiet on the seed catalog: {r.returncode} {r.stdout[:200]!r} {r.stderr[:200]!r}")
r = run(["check", WRONG, "-q"])
expect(r.returncode == 1 and r.stdout == "" and ": error: " in r.stderr and "MISMATCH" in r.stderr,
       f"check -q on a wrong verdict: {r.returncode} {r.stdout[:200]!r} {r.stderr[:200]!r}")
r = run(["fuzz", SEED, "--rule", "insert-vertex-free-edge", "--runs", "50", "--seed", "1", "--quiet"])
expect(r.returncode == 0 and r.stdout == "" and r.stderr == "", f"fuzz --quiet (no seed line, no progress): {r.returncode} {r.stdout[:200]!r} {r.stderr[:300]!r}")
r = run(["check", SEED, "--quiet", "--format", "json"])
expect(r.returncode == 0 and r.stdout.startswith("{"), "check --quiet --format json still prints its document")

r = run(["--color", "always", "check", WRONG])
expect(ESC in r.stdout and f"{ESC}1;31merror:" in r.stderr, f"--color always: {r.stdout[:200]!r} {r.stderr[:200]!r}")
r = run(["check", WRONG, "--color", "always"], {"NO_COLOR": "1"})
expect(ESC in r.stdout, "--color always after the command, under NO_COLOR: no colour")
for mode in ["never", "auto"]:
    r = run(["check", WRONG, "--color", mode])
    expect(ESC not in r.stdout + r.stderr, f"--color {mode} off a terminal: colour codes")
r = run(["check", SEED, "--color", "sometimes"])
expect(r.returncode == 2 and r.stderr.startswith("dartcheck: error:"), f"--color sometimes: {r.returncode} {r.stderr[:200]!r}")

status, out = run_pty(["check", WRONG], 72)
expect(status == 1 and ESC in out, f"on a terminal, auto colours: {status} {out[:200]!r}")
fits(out, 72, "check on a 72-column terminal")
status, out = run_pty(["check", WRONG], 72, {"NO_COLOR": "1"})
expect(ESC not in out, "on a terminal with NO_COLOR: colour codes")
status, out = run_pty(["check", SEED], 200, {"NO_COLOR": ""})
expect(ESC in out, "an empty NO_COLOR does not count (no-color.org)")

for cols, env in [(100, {}), (60, {"COLUMNS": "60"}), (140, {"COLUMNS": "140"})]:
    for args in [["check", SEED], ["check", SEED, "--explain"], ["check", "catalogs/embedding-operations.yaml", "--explain"],
                 ["check", "../shared/jerboa-samples/JerboaRebuilt2.jme"], ["fuzz", SEED, "--runs", "100", "--seed", "1"],
                 ["fuzz", "catalogs/embedding-operations.yaml", "--runs", "100", "--seed", "1"], ["events", SEED], ["run", SEED],
                 ["prove", SEED, "--rule", "insert-vertex-free-edge/oriented-1", "--explain"]]:
        r = run(args, env)
        expect(r.stdout.count("\n") > 5, f"{args}: no table")
        fits(r.stdout, cols, f"{' '.join(args)} with {env or 'no terminal'}")

for p in problems:
    print(p)
print(f"{len(problems)} problems")
sys.exit(1 if problems else 0)
